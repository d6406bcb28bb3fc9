# corpus: task=flexible_beam_drilled_part seed=0 expect=fail stage=mesh_match
# mistake: hole pitch rounded to 0.11 m instead of beam_length/n_holes = 0.11233 m, so the holes drift up to 13 mm off
import numpy as np
from netgen.occ import *
import ngsolve as ngs
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

beam_length = 0.674
beam_width = 0.0394
beam_height = 0.0284
n_holes = 6
hole_diameter = 0.0201

pitch = 0.11                       # distance between the holes
hole_positions = [pitch / 2 + i * pitch for i in range(n_holes)]

beam = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))
for xh in hole_positions:
    beam = beam - Cylinder(Pnt(xh, 0, -beam_height / 2), Z, r=hole_diameter / 2, h=beam_height)

beam.faces.Min(X).name = 'left'
beam.faces.Max(X).name = 'right'

mesh = ngs.Mesh(OCCGeometry(beam).GenerateMesh(maxh=0.014))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850, youngsModulus=2.1e11, poissonsRatio=0.3, meshOrder=1,
                          boundaryNamesList=['left', 'right'])
nodes, weights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodes, nEigenModes=6, boundaryNodesWeights=weights,
                                  computationMode=HCBstaticModeSelection.RBE2)
