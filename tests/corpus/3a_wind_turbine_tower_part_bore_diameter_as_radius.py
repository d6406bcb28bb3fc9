# corpus: task=wind_turbine_tower_part seed=1 expect=fail stage=mass_match
# mistake: radius and diameter confused: the bore is cut with r = shaft_radius/2 (shaft_radius taken as a diameter)
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

shaft_radius = 0.0245
nacelle_length = 0.207
hub_height = 1.06
base_width = 0.266
base_thickness = 0.0238
tower_width = 0.106
tower_wall = 0.0206
nacelle_width = 0.158
nacelle_height = 0.123
tower_top = hub_height - nacelle_height / 2
cavity_width = tower_width - 2 * tower_wall

b2, t2, c2 = base_width / 2, tower_width / 2, cavity_width / 2
plate = Box(Pnt(-b2, -b2, 0), Pnt(b2, b2, base_thickness))
tube = Box(Pnt(-t2, -t2, base_thickness), Pnt(t2, t2, tower_top))
cavity = Box(Pnt(-c2, -c2, base_thickness), Pnt(c2, c2, tower_top))
nacelle = Box(Pnt(-nacelle_length / 2, -nacelle_width / 2, tower_top),
              Pnt(nacelle_length / 2, nacelle_width / 2, tower_top + nacelle_height))

bore_radius = shaft_radius / 2     # shaft diameter / 2
bore = Cylinder(Pnt(-nacelle_length / 2, 0, hub_height), X, r=bore_radius, h=nacelle_length)

tower = plate + tube + nacelle
tower = tower - cavity - bore
tower.faces.Min(Z).name = 'ground'
tower.faces.Nearest(Pnt(0, 0, hub_height + bore_radius)).name = 'bore'

mesh = ngs.Mesh(OCCGeometry(tower).GenerateMesh(maxh=0.021))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850.0, youngsModulus=2.1e11, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['ground', 'bore'])
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
