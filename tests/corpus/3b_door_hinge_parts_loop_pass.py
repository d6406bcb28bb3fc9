# corpus: task=door_hinge seed=0 expect=pass
# style: both leaves loaded in a for-loop over their names, mid_z computed from knuckle_length, named markers, prints
import exudyn as exu
from exudyn.itemInterface import *
from exudyn.FEM import FEMinterface
import numpy as np

SC = exu.SystemContainer()
mbs = SC.AddSystem()

knuckle_length = 0.0291
door_force = 0.652      # N, +y
g = 9.81
mount_x = -0.0258       # x of the screw holes of the pin-side leaf
mid_z = 1.5 * knuckle_length

flex = {}
for partName in ['pin_leaf', 'gap_leaf']:
    femPart = FEMinterface()
    femPart.LoadFromFile(partName + '.npz')
    flex[partName] = mbs.CreateFFRFReducedOrderObject(partName, femPart, referencePosition=[0, 0, 0],
                                                      referenceRotationMatrix=np.eye(3),
                                                      gravity=[0, 0, -g])
    print(partName, 'markers:', [k for k in flex[partName] if ':' in k])

groundObject = mbs.CreateGround(referencePosition=[0, 0, 0])
groundMarker = mbs.AddMarker(MarkerBodyRigid(name='frameMount', bodyNumber=groundObject,
                                             localPosition=[mount_x, 0, mid_z]))

# (1) pin-side leaf screwed to the door frame
mbs.AddObject(GenericJoint(name='mountClamp', markerNumbers=[groundMarker, flex['pin_leaf']['pin_leaf:mount']],
                           constrainedAxes=[1, 1, 1, 1, 1, 1]))
# (2) hinge: revolute about the global z-axis
mbs.AddObject(GenericJoint(name='hinge', markerNumbers=[flex['pin_leaf']['pin_leaf:pin'], flex['gap_leaf']['gap_leaf:bore']],
                           constrainedAxes=[1, 1, 1, 1, 1, 0]))

mbs.AddLoad(Force(name='doorPush', markerNumber=flex['gap_leaf']['gap_leaf:door'], loadVector=[0, door_force, 0]))

mbs.Assemble()

settings = exu.SimulationSettings()
settings.timeIntegration.endTime = 0.1
settings.timeIntegration.numberOfSteps = 200
settings.timeIntegration.newton.useModifiedNewton = True
settings.solution.file.write = False
mbs.SolveDynamic(settings)
print("door hinge simulated until t =", settings.timeIntegration.endTime)
