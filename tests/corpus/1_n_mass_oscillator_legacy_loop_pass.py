# corpus: task=n_mass_oscillator seed=1 expect=pass
# style: legacy API in one loop that builds each mass with the spring to its predecessor
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

n = 8
m = 2.38
k = 2690.0
d = 3.84
L = 0.55
F = 28.8

ground = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
bodies = []
for i in range(1, n + 1):
    node = mbs.AddNode(NodePoint(referenceCoordinates=[i * L, 0, 0]))
    bodies.append(mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=node)))

previous = ground
for body in bodies:
    m0 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=previous, localPosition=[0, 0, 0]))
    m1 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=body, localPosition=[0, 0, 0]))
    mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[m0, m1], stiffness=k, damping=d, referenceLength=L))
    previous = body

mLast = mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodies[-1], localPosition=[0, 0, 0]))
mbs.AddLoad(Force(markerNumber=mLast, loadVector=[F, 0, 0]))

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
