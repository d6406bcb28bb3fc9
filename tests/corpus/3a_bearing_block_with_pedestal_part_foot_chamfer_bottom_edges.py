# corpus: task=bearing_block_with_pedestal_part seed=1 expect=fail stage=mesh_match
# mistake: the pedestal chamfer is put on the four lower edges of the plate (z = 0) instead of the upper ones (z = foot_thickness)
from netgen.occ import *
import ngsolve as ngs
import numpy as np
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

shaft_radius = 0.0139
bearing_width = 0.042
axis_height = 0.103
foot_width = 0.109
foot_length = 0.258
foot_thickness = 0.0215
housing_length = 0.108
top_wall = 0.0174
top_chamfer = 0.0296
foot_chamfer = 0.0112
block_height = axis_height + shaft_radius + top_wall

pedestal = Box(Pnt(-foot_width / 2, -foot_length / 2, 0), Pnt(foot_width / 2, foot_length / 2, foot_thickness))
housing = Box(Pnt(-bearing_width / 2, -housing_length / 2, foot_thickness),
              Pnt(bearing_width / 2, housing_length / 2, block_height))
block = pedestal + housing

# upper edges of the housing parallel to the bore axis (x)
top_edges = [block.edges.Nearest(Pnt(0, sy * housing_length / 2, block_height)) for sy in (-1, 1)]
block = block.MakeChamfer(top_edges, top_chamfer)

# outer edges of the pedestal plate
foot_edges = [block.edges.Nearest(Pnt(sx * foot_width / 2, 0, 0)) for sx in (-1, 1)]
foot_edges += [block.edges.Nearest(Pnt(0, sy * foot_length / 2, 0)) for sy in (-1, 1)]
block = block.MakeChamfer(foot_edges, foot_chamfer)

# bore along x
block = block - Cylinder(Pnt(-foot_width / 2, 0, axis_height), X, r=shaft_radius, h=foot_width)
block.faces.Nearest(Pnt(0, 0, axis_height - shaft_radius)).name = 'bore'
block.faces.Min(Z).name = 'bottom'

mesh = ngs.Mesh(OCCGeometry(block).GenerateMesh(maxh=0.011))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7200, youngsModulus=1.1e11, poissonsRatio=0.26,
                          meshOrder=1, boundaryNamesList=['bore', 'bottom'])
boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                  boundaryNodesWeights=boundaryWeights,
                                  computationMode=HCBstaticModeSelection.RBE2)
