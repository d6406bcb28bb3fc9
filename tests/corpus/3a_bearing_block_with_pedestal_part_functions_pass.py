# corpus: task=bearing_block_with_pedestal_part seed=0 expect=pass
# style: one function per feature (fuse, two chamfer steps, bore), chamfer edges picked with Nearest, block height derived in code
from netgen.occ import Box, Cylinder, Pnt, X, Z, OCCGeometry
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

# dimensions [m]
shaft_radius = 0.0175
bearing_width = 0.0539
axis_height = 0.101
foot_width = 0.112
foot_length = 0.239
foot_thickness = 0.0242
housing_length = 0.103
top_wall = 0.0194
top_chamfer = 0.0326
foot_chamfer = 0.0136
block_height = axis_height + shaft_radius + top_wall   # 0.1379

# cast iron
E, nu, rho = 1.1e11, 0.26, 7200.0


def pedestal_and_housing():
    fw, fl = foot_width / 2, foot_length / 2
    bw, hl = bearing_width / 2, housing_length / 2
    pedestal = Box(Pnt(-fw, -fl, 0.0), Pnt(fw, fl, foot_thickness))
    housing = Box(Pnt(-bw, -hl, foot_thickness), Pnt(bw, hl, block_height))
    return pedestal + housing


def chamfer_housing_top(solid):
    # top edges along x (parallel to the bore axis) at y = +-housing_length/2
    edges = [solid.edges.Nearest(Pnt(0.0, y, block_height)) for y in (-housing_length / 2, housing_length / 2)]
    return solid.MakeChamfer(edges, top_chamfer)


def chamfer_pedestal_top(solid):
    fw, fl = foot_width / 2, foot_length / 2
    points = [Pnt(-fw, 0.0, foot_thickness), Pnt(fw, 0.0, foot_thickness),
              Pnt(0.0, -fl, foot_thickness), Pnt(0.0, fl, foot_thickness)]
    return solid.MakeChamfer([solid.edges.Nearest(p) for p in points], foot_chamfer)


def drill_bore(solid):
    bore = Cylinder(Pnt(-foot_width, 0.0, axis_height), X, r=shaft_radius, h=2 * foot_width)
    return solid - bore


block = drill_bore(chamfer_pedestal_top(chamfer_housing_top(pedestal_and_housing())))
block.faces.Nearest(Pnt(0.0, shaft_radius, axis_height)).name = 'bore'
block.faces.Min(Z).name = 'bottom'

mesh = ngs.Mesh(OCCGeometry(block).GenerateMesh(maxh=0.013))
print(f"mesh with {mesh.ne} elements and {mesh.nv} nodes")

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=rho, youngsModulus=E, poissonsRatio=nu,
                          meshOrder=1, boundaryNamesList=['bore', 'bottom'])
nodes, weights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodes, nEigenModes=6,
                                  boundaryNodesWeights=weights,
                                  computationMode=HCBstaticModeSelection.RBE2)
