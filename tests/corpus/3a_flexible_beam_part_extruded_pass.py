# corpus: task=flexible_beam_part seed=0 expect=pass
# style: box as an extruded work-plane rectangle, helper function, __main__ block, prints mesh size and mass
"""Flexible beam with rectangular cross section, reduced with Hurty-Craig-Bampton modes."""
import numpy as np
import ngsolve as ngs
from netgen.occ import WorkPlane, Axes, OCCGeometry, X, Y, Z
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

# beam dimensions in m
L = 0.489      # length along x
W = 0.0404     # width along y
H = 0.0208     # height along z

# steel
E_steel = 2.1e11
nu_steel = 0.3
rho_steel = 7850.


def make_geometry(length, width, height):
    """Rectangle in the y-z plane at x = 0, extruded along +x."""
    wp = WorkPlane(Axes((0, 0, 0), n=X, h=Y))
    wp.MoveTo(-width / 2, -height / 2).Rectangle(width, height)
    beam = wp.Face().Extrude(length)
    beam.faces.Min(X).name = 'left'
    beam.faces.Max(X).name = 'right'
    return beam


def main():
    beam = make_geometry(L, W, H)
    geo = OCCGeometry(beam)
    mesh = ngs.Mesh(geo.GenerateMesh(maxh=0.01))
    print('elements:', mesh.ne, 'vertices:', mesh.nv)

    fem = FEMinterface()
    fem.ImportMeshFromNGsolve(mesh, density=rho_steel, youngsModulus=E_steel,
                              poissonsRatio=nu_steel, meshOrder=1,
                              boundaryNamesList=['left', 'right'])
    volume = L * W * H
    print('mass of the beam: %.4f kg' % (rho_steel * volume))

    nodeLists, weightLists = fem.GetBoundaryNodeSetsAsLists()
    fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodeLists,
                                      nEigenModes=6,
                                      boundaryNodesWeights=weightLists,
                                      computationMode=HCBstaticModeSelection.RBE2)
    print('eigenfrequencies (Hz):', np.round(fem.GetEigenFrequenciesHz(), 2))
    return fem


if __name__ == "__main__":
    fem = main()
