# corpus: task=flexible_beam_drilled_part seed=1 expect=pass
# style: hole positions computed with numpy from the formula, holes as Cylinder(gp_Ax2, r, h), helper functions
import numpy as np
from netgen.occ import Box, Cylinder, Pnt, gp_Ax2, Dir, OCCGeometry, X
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

# --- parameters of the drilled beam ---
length = 0.622
width = 0.0355
height = 0.0203
nHoles = 5
holeDiameter = 0.0189

material = {'E': 2.1e11, 'nu': 0.3, 'rho': 7850.}


def drilled_beam():
    hw, hh = 0.5 * width, 0.5 * height
    body = Box(Pnt(0., -hw, -hh), Pnt(length, hw, hh))
    # hole i at x = (i - 1/2) * L / n, i = 1..n
    xHoles = (np.arange(1, nHoles + 1) - 0.5) * length / nHoles
    for xh in xHoles:
        axis = gp_Ax2(Pnt(float(xh), 0., -hh), Dir(0, 0, 1))
        body = body - Cylinder(axis, holeDiameter / 2, height)
    return body


def name_interfaces(body):
    body.faces.Min(X).name = 'left'
    body.faces.Max(X).name = 'right'


beam = drilled_beam()
name_interfaces(beam)

ngmesh = OCCGeometry(beam).GenerateMesh(maxh=0.01)
mesh = ngs.Mesh(ngmesh)
print("number of tets:", mesh.ne)

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=material['rho'], youngsModulus=material['E'],
                          poissonsRatio=material['nu'], meshOrder=1,
                          boundaryNamesList=['left', 'right'])

nodeSets, weightSets = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodeSets, nEigenModes=6,
                                  boundaryNodesWeights=weightSets,
                                  computationMode=HCBstaticModeSelection.RBE2)
print("HCB eigenfrequencies:", fem.GetEigenFrequenciesHz())
