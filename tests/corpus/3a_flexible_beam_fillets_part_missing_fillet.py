# corpus: task=flexible_beam_fillets_part seed=1 expect=fail stage=mass_match
# mistake: the fillet step is missing (MakeFillet result not assigned), the beam keeps sharp long edges
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

beam_length = 0.44
beam_width = 0.0416
beam_height = 0.0265
fillet_radius = 0.0114

beam = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))

# round the four edges parallel to x
edges = [beam.edges.Nearest(Pnt(beam_length / 2, sy * beam_width / 2, sz * beam_height / 2))
         for sy in (-1, 1) for sz in (-1, 1)]
beam.MakeFillet(edges, fillet_radius)

beam.faces.Min(X).name = 'left'
beam.faces.Max(X).name = 'right'

mesh = ngs.Mesh(OCCGeometry(beam).GenerateMesh(maxh=0.013))
print("Mesh:", mesh.ne, "elements")
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850, youngsModulus=2.1e11, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['left', 'right'])
nodeLists, weightLists = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodeLists, nEigenModes=6,
                                  boundaryNodesWeights=weightLists,
                                  computationMode=HCBstaticModeSelection.RBE2)
