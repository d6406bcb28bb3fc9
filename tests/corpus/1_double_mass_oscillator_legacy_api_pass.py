# corpus: task=double_mass_oscillator seed=0 expect=pass
# style: legacy API, a helper that adds a spring between two bodies
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m1, m2 = 4.42, 1.79
k1, k2 = 1290.0, 1600.0
d1, d2 = 3.58, 4.58
L1, L2 = 1.79, 1.88
u2 = 0.0221


def add_mass(x, u, m):
    n = mbs.AddNode(NodePoint(referenceCoordinates=[x, 0, 0], initialCoordinates=[u, 0, 0]))
    return mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=n))


def add_spring(bodyA, bodyB, k, d, length):
    mA = mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodyA, localPosition=[0, 0, 0]))
    mB = mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodyB, localPosition=[0, 0, 0]))
    return mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[mA, mB], stiffness=k, damping=d,
                                                     referenceLength=length))


ground = mbs.AddObject(ObjectGround())
b1 = add_mass(L1, 0, m1)
b2 = add_mass(L1 + L2, u2, m2)
add_spring(ground, b1, k1, d1, L1)
add_spring(b1, b2, k2, d2, L2)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
