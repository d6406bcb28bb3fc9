# corpus: task=door_hinge seed=1 expect=fail stage=graph_content_match category="gravity and load"
# mistake: the door force points along the leaf (+x) instead of pushing it open (+y)
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()

# parameters
knuckle_length = 0.0275
door_force = 0.438
g = 9.81
mid_z = 1.5 * knuckle_length
mount_x = -0.0286
mountPoint = np.array([mount_x, 0, mid_z])

femPin = FEMinterface()
femPin.LoadFromFile('pin_leaf.npz')
pinLeaf = mbs.CreateFFRFReducedOrderObject('pin_leaf', femPin, referencePosition=[0, 0, 0],
                                           gravity=[0, 0, -g])

femGap = FEMinterface()
femGap.LoadFromFile('gap_leaf.npz')
gapLeaf = mbs.CreateFFRFReducedOrderObject('gap_leaf', femGap, referencePosition=[0, 0, 0],
                                           gravity=[0, 0, -g])

oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mMount = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=mountPoint))

mbs.AddObject(GenericJoint(markerNumbers=[mMount, pinLeaf['pin_leaf:mount']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[pinLeaf['pin_leaf:pin'], gapLeaf['gap_leaf:bore']],
                           constrainedAxes=[1, 1, 1, 1, 1, 0]))
mbs.AddLoad(Force(markerNumber=gapLeaf['gap_leaf:door'], loadVector=[door_force, 0, 0]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.1
simulationSettings.timeIntegration.numberOfSteps = 200
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
