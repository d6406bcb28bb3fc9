# corpus: task=hinge_leaf_pin_side_part seed=0 expect=fail stage=eigenfrequencies_match
# mistake: the 'pin' interface only names the pin surface in the lower gap, the upper gap is left out
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

pin_radius = 0.00494
knuckle_outer_radius = 0.01
knuckle_length = 0.0207
leaf_thickness = 0.00498
knuckle_clearance = 0.00136
leaf_width = 0.0413
hole_radius = 0.00448
hinge_length = 3 * knuckle_length
notch_depth = knuckle_outer_radius + knuckle_clearance
hole_x = 0.0263
hole_z = [0.01035, 0.05175]

ty = leaf_thickness / 2
leaf = Box(Pnt(-leaf_width, -ty, 0), Pnt(0, ty, hinge_length))
lower_notch = Box(Pnt(-notch_depth, -ty, 0), Pnt(0, ty, knuckle_length))
upper_notch = Box(Pnt(-notch_depth, -ty, 2 * knuckle_length), Pnt(0, ty, hinge_length))
leaf = leaf - lower_notch - upper_notch

knuckle = Cylinder(Pnt(0, 0, knuckle_length), Z, r=knuckle_outer_radius, h=knuckle_length)
pin = Cylinder(Pnt(0, 0, 0), Z, r=pin_radius, h=hinge_length)
leaf = leaf + knuckle + pin

for z in hole_z:
    leaf = leaf - Cylinder(Pnt(-hole_x, -ty, z), Y, r=hole_radius, h=leaf_thickness)

# interfaces
leaf.faces.Nearest(Pnt(pin_radius, 0, knuckle_length / 2)).name = 'pin'
for z in hole_z:
    leaf.faces.Nearest(Pnt(-hole_x, 0, z + hole_radius)).name = 'mount'

mesh = ngs.Mesh(OCCGeometry(leaf).GenerateMesh(maxh=0.0025))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850.0, youngsModulus=2.1e11, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['pin', 'mount'])
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
