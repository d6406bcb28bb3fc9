# corpus: task=wind_turbine_tower_part seed=0 expect=pass
# style: boxes from centre and size via a helper, bore as a circle on a y-z work plane extruded along x, derived tower_top
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import *

# tower geometry
base_width, base_thickness = 0.29, 0.0219
tower_width, tower_wall = 0.0932, 0.02
nacelle_length, nacelle_width, nacelle_height = 0.266, 0.159, 0.113
hub_height = 0.835
shaft_radius = 0.0221
tower_top = hub_height - nacelle_height / 2          # bottom of the nacelle
cavity_width = tower_width - 2 * tower_wall


def box_xyz(cx, cy, sx, sy, z0, z1):
    """Axis-aligned box centred at (cx, cy) in the x-y plane, from z0 to z1."""
    return Box(Pnt(cx - sx / 2, cy - sy / 2, z0), Pnt(cx + sx / 2, cy + sy / 2, z1))


base = box_xyz(0, 0, base_width, base_width, 0, base_thickness)
tube = box_xyz(0, 0, tower_width, tower_width, base_thickness, tower_top)
nacelle = box_xyz(0, 0, nacelle_length, nacelle_width, tower_top, tower_top + nacelle_height)
cavity = box_xyz(0, 0, cavity_width, cavity_width, base_thickness, tower_top)

# bore: circle in the plane x = -nacelle_length/2, extruded through the nacelle
wp = WorkPlane(Axes((-nacelle_length / 2, 0, hub_height), n=X, h=Y))
bore = wp.Circle(shaft_radius).Face().Extrude(nacelle_length)

tower = (base + tube + nacelle) - cavity - bore
tower.faces.Min(Z).name = 'ground'
tower.faces.Nearest(Pnt(0, 0, hub_height - shaft_radius)).name = 'bore'

mesh = ngs.Mesh(OCCGeometry(tower).GenerateMesh(maxh=0.02))
print('nodes:', mesh.nv)

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850, youngsModulus=2.1e11, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['ground', 'bore'])
[nodeLists, weightLists] = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodeLists, nEigenModes=6,
                                  boundaryNodesWeights=weightLists,
                                  computationMode=HCBstaticModeSelection.RBE2)
print('first eigenfrequencies:', fem.GetEigenFrequenciesHz()[:8])
