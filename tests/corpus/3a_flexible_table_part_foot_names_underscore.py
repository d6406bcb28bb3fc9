# corpus: task=flexible_table_part seed=1 expect=fail stage=interface_name_match
# mistake: interface names spelled 'foot_1' ... 'foot_4' instead of 'foot1' ... 'foot4'
import numpy as np
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

table_length = 0.654
table_width = 0.493
plate_thickness = 0.0205
leg_height = 0.471
leg_size = 0.0634
leg_inset = 0.0305
pad_size = 0.112
pad_height = 0.0209

leg_x = table_length / 2 - leg_inset - leg_size / 2
leg_y = table_width / 2 - leg_inset - leg_size / 2
feet_z = -(plate_thickness / 2 + leg_height)
pad_top_z = plate_thickness / 2 + pad_height


def centred_box(cx, cy, size_x, size_y, z_bottom, z_top):
    return Box(Pnt(cx - size_x / 2, cy - size_y / 2, z_bottom), Pnt(cx + size_x / 2, cy + size_y / 2, z_top))


table = centred_box(0, 0, table_length, table_width, -plate_thickness / 2, plate_thickness / 2)
table = table + centred_box(0, 0, pad_size, pad_size, plate_thickness / 2, pad_top_z)
leg_positions = np.array([[-leg_x, -leg_y], [leg_x, -leg_y], [leg_x, leg_y], [-leg_x, leg_y]])
for x, y in leg_positions:
    table = table + centred_box(x, y, leg_size, leg_size, feet_z, -plate_thickness / 2)

interface_names = []
for k, (x, y) in enumerate(leg_positions):
    name = f'foot_{k + 1}'
    table.faces.Nearest(Pnt(x, y, feet_z)).name = name
    interface_names.append(name)
table.faces.Max(Z).name = 'load'
interface_names.append('load')

mesh = ngs.Mesh(OCCGeometry(table).GenerateMesh(maxh=0.021))
print('mesh:', mesh.ne, 'tetrahedra')
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=2700., youngsModulus=7e10, poissonsRatio=0.33, meshOrder=1,
                          boundaryNamesList=interface_names)
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
