# corpus: task=two_mass_points_with_springs seed=0 expect=pass
# style: legacy API, initial velocities on the nodes, no ground
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

a = 0.317
n1 = mbs.AddNode(NodePoint(referenceCoordinates=[-a, 0, 0], initialVelocities=[0, 1.31, 0]))
n2 = mbs.AddNode(NodePoint(referenceCoordinates=[a, 0, 0], initialVelocities=[0, -2.83, 0]))
b1 = mbs.AddObject(MassPoint(physicsMass=1.55, nodeNumber=n1))
b2 = mbs.AddObject(MassPoint(physicsMass=0.971, nodeNumber=n2))
m1 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=b1))
m2 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=b2))
mbs.AddObject(SpringDamper(markerNumbers=[m1, m2], stiffness=1680.0, damping=0.0501, referenceLength=2 * a))

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
