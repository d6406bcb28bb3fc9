# corpus: task=mounting_bracket_part seed=1 expect=fail stage=mass_match
# mistake: the bend chamfer is put on the inner bend edge (x = z = t) instead of the outer bend edge (x = z = 0)
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

bracket_thickness = 0.0118
bracket_width = 0.0762
base_length = 0.0676
upright_height = 0.0507
chamfer_size = 0.00859
hole_radius = 0.00498
base_hole_x = 0.0397
upright_hole_z = 0.0312
hole_y = 0.0191

t = bracket_thickness
hw = bracket_width / 2

base_plate = Box(Pnt(0, -hw, 0), Pnt(base_length, hw, t))
upright_plate = Box(Pnt(0, -hw, 0), Pnt(t, hw, upright_height))
bracket = base_plate + upright_plate

# chamfer the bend edge, the free end of the base and the top of the upright
bend_edge = bracket.edges.Nearest(Pnt(t, 0, t))
base_end_edge = bracket.edges.Nearest(Pnt(base_length, 0, 0))
top_edge = bracket.edges.Nearest(Pnt(0, 0, upright_height))
bracket = bracket.MakeChamfer([bend_edge, base_end_edge, top_edge], chamfer_size)

# bolt holes
for y in (-hole_y, hole_y):
    bracket = bracket - Cylinder(Pnt(base_hole_x, y, 0), Z, r=hole_radius, h=t)
    bracket = bracket - Cylinder(Pnt(0, y, upright_hole_z), X, r=hole_radius, h=t)
for y in (-hole_y, hole_y):
    bracket.faces.Nearest(Pnt(base_hole_x + hole_radius, y, t / 2)).name = 'base_holes'
    bracket.faces.Nearest(Pnt(t / 2, y, upright_hole_z + hole_radius)).name = 'upright_holes'

mesh = ngs.Mesh(OCCGeometry(bracket).GenerateMesh(maxh=0.0059))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=2700.0, youngsModulus=7.0e10, poissonsRatio=0.33,
                          meshOrder=1, boundaryNamesList=['base_holes', 'upright_holes'])
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
