# corpus: task=crank_part_simple seed=1 expect=pass
# style: plate as an extruded work-plane rectangle, holes as extruded circles, interfaces named by looping over faces and their centres
import numpy as np
from netgen.occ import WorkPlane, Axes, OCCGeometry, Z
import ngsolve as ngs
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

crank_length = 0.0787
pin_radius = 0.00773
thickness = 0.0133
crank_width = 0.0362

# plate: rectangle in the x-y plane at z = -t/2, extruded by t in +z
wp = WorkPlane(Axes((0, 0, -thickness / 2), n=Z, h=(1, 0, 0)))
wp.MoveTo(-crank_width / 2, -crank_width / 2)
wp.Rectangle(crank_length + crank_width, crank_width)
crank = wp.Face().Extrude(thickness)

hole_centres = {'hole_a': np.array([0.0, 0.0]), 'hole_b': np.array([crank_length, 0.0])}
for c in hole_centres.values():
    hole = WorkPlane(Axes((c[0], c[1], -thickness / 2), n=Z, h=(1, 0, 0))).Circle(pin_radius).Face()
    crank = crank - hole.Extrude(thickness)

# name the two hole surfaces: only a hole's cylindrical face has its centre on the hole axis at z = 0
for face in crank.faces:
    centre = np.array([face.center.x, face.center.y, face.center.z])
    for name, c in hole_centres.items():
        if np.linalg.norm(centre - np.array([c[0], c[1], 0.0])) < 1e-6:
            face.name = name

mesh = ngs.Mesh(OCCGeometry(crank).GenerateMesh(maxh=0.0066))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850., youngsModulus=2.1e11, poissonsRatio=0.3,
                          meshOrder=1, boundaryNamesList=['hole_a', 'hole_b'])
nodesList, weightsList = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodesList, nEigenModes=6,
                                  boundaryNodesWeights=weightsList,
                                  computationMode=HCBstaticModeSelection.RBE2)
print("eigenfrequencies in Hz:", np.round(fem.GetEigenFrequenciesHz(), 1))
