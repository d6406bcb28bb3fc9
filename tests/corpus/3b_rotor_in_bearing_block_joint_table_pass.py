# corpus: task=rotor_in_bearing_block seed=1 expect=pass
# style: parts loaded in a loop from a dict, joints from a table of (marker, marker, axes), derived rotor_x computed
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()

# parameters
shaft_radius = 0.0139
bearing_width = 0.0529
axis_height = 0.108
bearing_span = 0.386
omega0 = 51.1        # rad/s
torque = 2.0         # N*m
g = 9.81
gravity = [0, 0, -g]

rotor_x = -bearing_width / 2   # left seat centre sits at the bore centre

# part name -> (reference position, initial angular velocity)
partSetup = {
    'block': ([0, 0, 0], [0, 0, 0]),
    'rotor': ([rotor_x, 0, axis_height], [omega0, 0, 0]),
}
parts = {}
for name, (pos, omega) in partSetup.items():
    fem = FEMinterface()
    fem.LoadFromFile(f'{name}.npz')
    parts[name] = mbs.CreateFFRFReducedOrderObject(name, fem, referencePosition=pos,
                                                   referenceRotationMatrix=np.eye(3),
                                                   initialAngularVelocity=omega, gravity=gravity)
    print(f"added part '{name}' at {pos}")

block, rotor = parts['block'], parts['rotor']

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mGround0 = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0, 0, 0]))
mGroundRight = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[bearing_span, 0, axis_height]))

joints = [
    (mGround0, block['block:bottom'], [1, 1, 1, 1, 1, 1]),       # block clamped to the floor
    (block['block:bore'], rotor['rotor:left'], [1, 1, 1, 0, 1, 1]),  # locating bearing, revolute about x
    (mGroundRight, rotor['rotor:right'], [0, 1, 1, 0, 0, 0]),    # floating bearing
]
for m0, m1, axes in joints:
    mbs.AddObject(GenericJoint(markerNumbers=[m0, m1], constrainedAxes=axes))

mbs.AddLoad(Torque(markerNumber=rotor['rotor:left'], loadVector=[torque, 0, 0]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.2
simulationSettings.timeIntegration.numberOfSteps = 200
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
print('simulation done')
