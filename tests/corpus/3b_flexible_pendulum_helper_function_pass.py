# corpus: task=flexible_pendulum seed=1 expect=pass
# style: helper function that loads and adds a part, np.radians, rotation matrix built by hand, tip sensor, print of results
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()
print("using Exudyn", exu.__version__)

# --- parameters from the task ---
L = 0.6                 # beam length in m
theta0 = np.radians(63.9)  # initial angle between beam axis and the downward vertical
g = 9.81
tEnd = 0.5
nSteps = 250


def add_flexible_part(name, position, rotation, gravity):
    """load <name>.npz and add it as FFRF reduced order body; returns the marker dict"""
    fem = FEMinterface()
    fem.LoadFromFile(name + '.npz')
    return mbs.CreateFFRFReducedOrderObject(name, fem, referencePosition=position,
                                            referenceRotationMatrix=rotation, gravity=gravity)


# rotation about the global y-axis by pi/2 - theta0 (same as RotationMatrixY)
phi = np.pi / 2 - theta0
Ry = np.array([[np.cos(phi), 0.0, np.sin(phi)],
               [0.0, 1.0, 0.0],
               [-np.sin(phi), 0.0, np.cos(phi)]])

beam = add_flexible_part('beam', [0.0, 0.0, 0.0], Ry, [0.0, 0.0, -g])
print('beam axis direction:', Ry @ np.array([1.0, 0.0, 0.0]))  # = [sin(theta0), 0, -cos(theta0)]

# hinge: revolute joint about the global y-axis at the origin
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mHinge = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mHinge, beam['beam:left']],
                           constrainedAxes=[1, 1, 1, 1, 0, 1]))

sensTip = mbs.AddSensor(SensorMarker(markerNumber=beam['beam:right'], storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.Position))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = tEnd
simulationSettings.timeIntegration.numberOfSteps = nSteps
simulationSettings.solution.file.write = False
simulationSettings.timeIntegration.verboseMode = 1

mbs.SolveDynamic(simulationSettings)

tipData = mbs.GetSensorValues(sensTip)
print("tip position at t =", tipData[-1, 0], ":", tipData[-1, 1:])
