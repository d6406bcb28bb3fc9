# corpus: task=mounting_bracket_part seed=0 expect=pass
# style: L profile drawn on a work plane and extruded along y, chamfer edges picked in a loop, holes named by loop
from netgen.occ import *
import ngsolve as ngs
import numpy as np
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

t = 0.0101          # plate thickness
b = 0.0655          # bracket width (y)
a = 0.0575          # base length (x)
hUp = 0.0546        # upright height (z)
c = 0.00894         # chamfer size
rHole = 0.00459
xHoleBase = 0.0338
zHoleUp = 0.0324
yHole = 0.0164

# L-shaped profile in the x-z plane; the work plane normal is -y so that the local axes are (x, z)
wp = WorkPlane(Axes((0, b / 2, 0), n=-Y, h=X))
wp.MoveTo(0, 0).LineTo(a, 0).LineTo(a, t).LineTo(t, t).LineTo(t, hUp).LineTo(0, hUp).Close()
bracket = wp.Face().Extrude(b)   # from y = +b/2 to y = -b/2

# the three outer edges parallel to y
chamferPoints = [(0, 0), (a, 0), (0, hUp)]
outerEdges = [bracket.edges.Nearest(Pnt(x, 0, z)) for x, z in chamferPoints]
bracket = bracket.MakeChamfer(outerEdges, c)

# bolt holes
for y in [-yHole, yHole]:
    bracket -= Cylinder(Pnt(xHoleBase, y, -t), Z, r=rHole, h=3 * t)
    bracket -= Cylinder(Pnt(-t, y, zHoleUp), X, r=rHole, h=3 * t)

# interfaces
for y in [-yHole, yHole]:
    bracket.faces.Nearest(Pnt(xHoleBase - rHole, y, 0.5 * t)).name = 'base_holes'
    bracket.faces.Nearest(Pnt(0.5 * t, y, zHoleUp - rHole)).name = 'upright_holes'

mesh = ngs.Mesh(OCCGeometry(bracket).GenerateMesh(maxh=0.005))
print('mesh:', mesh.nv, 'nodes,', mesh.ne, 'tets')

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=2700, youngsModulus=7e10, poissonsRatio=0.33,
                          meshOrder=1, boundaryNamesList=['base_holes', 'upright_holes'])
bNodes, bWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=bNodes, boundaryNodesWeights=bWeights,
                                  nEigenModes=6, computationMode=HCBstaticModeSelection.RBE2)
