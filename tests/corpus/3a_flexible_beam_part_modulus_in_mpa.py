# corpus: task=flexible_beam_part seed=1 expect=fail stage=material_match
# mistake: Young's modulus given in MPa (210000) instead of Pa
from netgen.occ import *
import ngsolve as ngs
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

# Beam dimensions
L, W, H = 0.664, 0.0302, 0.0232

# Material: steel
E = 210000.0      # Young's modulus [MPa]
nu = 0.3
rho = 7850.0      # kg/m^3

beam = Box(Pnt(0, -W / 2, -H / 2), Pnt(L, W / 2, H / 2))
beam.faces.Min(X).name = 'left'
beam.faces.Max(X).name = 'right'

geo = OCCGeometry(beam)
mesh = ngs.Mesh(geo.GenerateMesh(maxh=0.012))

fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=rho, youngsModulus=E, poissonsRatio=nu,
                          meshOrder=1, boundaryNamesList=['left', 'right'])
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
print("eigenfrequencies:", fem.GetEigenFrequenciesHz())
