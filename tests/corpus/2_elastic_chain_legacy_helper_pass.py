# corpus: task=elastic_chain seed=1 expect=pass
# style: legacy API with a helper that adds two position markers and a spring-damper, chain built in a loop
import exudyn as exu
from exudyn.itemInterface import *
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

n = 4            # number of mass points
L = 2.02         # distance between the supports A and B
m = 0.144
k = 3750.0
d = 3.83
g = 9.787
h = L / (n + 1)
l0 = 0.83 * h    # pretensioned: relaxed length shorter than the spacing

ground = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
bodies = []
for i in range(1, n + 1):
    node = mbs.AddNode(NodePoint(referenceCoordinates=[i * h, 0, 0],
                                 initialCoordinates=[0, 0, 0], initialVelocities=[0, 0, 0]))
    body = mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=node))
    mbs.AddLoad(LoadMassProportional(markerNumber=mbs.AddMarker(MarkerBodyMass(bodyNumber=body)),
                                     loadVector=[0, -g, 0]))
    bodies.append(body)


def AddSpring(body0, body1, localPosition0=[0, 0, 0]):
    marker0 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=body0, localPosition=localPosition0))
    marker1 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=body1, localPosition=[0, 0, 0]))
    return mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[marker0, marker1],
                                                     referenceLength=l0, stiffness=k, damping=d))


springs = [AddSpring(ground, bodies[0])]
for i in range(n - 1):
    springs.append(AddSpring(bodies[i], bodies[i + 1]))
springs.append(AddSpring(ground, bodies[-1], localPosition0=[L, 0, 0]))
print("number of springs:", len(springs))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
simulationSettings.timeIntegration.verboseMode = 1
mbs.SolveDynamic(simulationSettings)
