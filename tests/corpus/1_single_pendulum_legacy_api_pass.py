# corpus: task=single_pendulum seed=0 expect=pass
# style: legacy API with ObjectConnectorDistance between body-position markers
import numpy as np
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 0.56
L = 1.15
phi0 = np.deg2rad(38.0)
g = 9.781

oGround = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
nBob = mbs.AddNode(NodePoint(referenceCoordinates=[L * np.sin(phi0), -L * np.cos(phi0), 0]))
oBob = mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=nBob))
mBobMass = mbs.AddMarker(MarkerBodyMass(bodyNumber=oBob))
mbs.AddLoad(LoadMassProportional(markerNumber=mBobMass, loadVector=[0, -g, 0]))
mGround = mbs.AddMarker(MarkerBodyPosition(bodyNumber=oGround, localPosition=[0, 0, 0]))
mBob = mbs.AddMarker(MarkerBodyPosition(bodyNumber=oBob, localPosition=[0, 0, 0]))
mbs.AddObject(DistanceConstraint(markerNumbers=[mGround, mBob], distance=L))

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
