# corpus: task=flexible_beam_hollow_part seed=1 expect=pass
# style: hollow section as a work-plane face minus the inner rectangle (RectangleC), extruded; __main__ and mass print
import numpy as np
from netgen.occ import WorkPlane, Axes, OCCGeometry, X, Y
from ngsolve import Mesh
from exudyn.FEM import FEMinterface, HCBstaticModeSelection


def hollow_tube(length, width, height, wall):
    """Rectangular tube: outer rectangle minus inner rectangle in the y-z plane, extruded along x."""
    outer = WorkPlane(Axes((0, 0, 0), n=X, h=Y)).RectangleC(width, height).Face()
    inner = WorkPlane(Axes((0, 0, 0), n=X, h=Y)).RectangleC(width - 2 * wall, height - 2 * wall).Face()
    ring = outer - inner
    return ring.Extrude(length)


if __name__ == "__main__":
    beam_length, beam_width, beam_height = 0.491, 0.0473, 0.0214
    wall_thickness = 0.00252
    E, nu, rho = 2.1e11, 0.3, 7850.

    tube = hollow_tube(beam_length, beam_width, beam_height, wall_thickness)
    tube.faces.Min(X).name = 'left'
    tube.faces.Max(X).name = 'right'

    area = beam_width * beam_height - (beam_width - 2 * wall_thickness) * (beam_height - 2 * wall_thickness)
    print("expected mass:", rho * area * beam_length)

    mesh = Mesh(OCCGeometry(tube).GenerateMesh(maxh=0.0076))
    fem = FEMinterface()
    fem.ImportMeshFromNGsolve(mesh, density=rho, youngsModulus=E, poissonsRatio=nu, meshOrder=1,
                              boundaryNamesList=['left', 'right'])
    boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
    fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                      boundaryNodesWeights=boundaryWeights,
                                      computationMode=HCBstaticModeSelection.RBE2)
    print(np.array(fem.GetEigenFrequenciesHz())[:10])
