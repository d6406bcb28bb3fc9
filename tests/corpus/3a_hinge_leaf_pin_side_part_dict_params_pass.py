# corpus: task=hinge_leaf_pin_side_part seed=1 expect=pass
# style: parameters in a dict, notches cut in a loop, knuckle and pin as Cylinder(gp_Ax2, r, h), interface faces collected in lists before naming
from netgen.occ import *
import ngsolve as ngs
import numpy as np
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

p = dict(pin_radius=0.00458, knuckle_outer_radius=0.0106, knuckle_length=0.0292,
         leaf_thickness=0.00513, knuckle_clearance=0.00119, leaf_width=0.0473,
         hole_radius=0.00377, hole_x=0.0295, hole_z=(0.0146, 0.073))

Lk = p['knuckle_length']
hinge_length = 3 * Lk
notch_depth = p['knuckle_outer_radius'] + p['knuckle_clearance']
ty = p['leaf_thickness'] / 2

# (1) leaf plate on the -x side
leaf = Box(Pnt(-p['leaf_width'], -ty, 0), Pnt(0, ty, hinge_length))
# (2) notches over the lower and the upper third
for z0 in (0.0, 2 * Lk):
    leaf = leaf - Box(Pnt(-notch_depth, -ty, z0), Pnt(0, ty, z0 + Lk))
# (3) knuckle over the middle third and (4) the pin over the full length
knuckle = Cylinder(gp_Ax2(Pnt(0, 0, Lk), Dir(0, 0, 1)), p['knuckle_outer_radius'], Lk)
pin = Cylinder(gp_Ax2(Pnt(0, 0, 0), Dir(0, 0, 1)), p['pin_radius'], hinge_length)
leaf = leaf + knuckle + pin
# (5) screw holes along y
for zh in p['hole_z']:
    leaf = leaf - Cylinder(Pnt(-p['hole_x'], -2 * ty, zh), Y, r=p['hole_radius'], h=4 * ty)

pinFaces = [leaf.faces.Nearest(Pnt(-p['pin_radius'], 0, zc)) for zc in (0.5 * Lk, 2.5 * Lk)]
mountFaces = [leaf.faces.Nearest(Pnt(-p['hole_x'] + p['hole_radius'], 0, zh)) for zh in p['hole_z']]
for f in pinFaces:
    f.name = 'pin'
for f in mountFaces:
    f.name = 'mount'

mesh = ngs.Mesh(OCCGeometry(leaf).GenerateMesh(maxh=0.0026))
print('tets:', mesh.ne)

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850, youngsModulus=210e9, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['pin', 'mount'])
nodeSets, weightSets = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodeSets, nEigenModes=6,
                                  boundaryNodesWeights=weightSets,
                                  computationMode=HCBstaticModeSelection.RBE2)
