# corpus: task=single_mass_oscillator seed=0 expect=pass
# style: legacy API with body-position markers and an explicit reference length
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 0.885      # kg
k = 550.0      # N/m
d = 4.01       # N*s/m
L = 1.37       # m
u0 = 0.0369    # m

ground = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
node = mbs.AddNode(NodePoint(referenceCoordinates=[L, 0, 0], initialCoordinates=[u0, 0, 0]))
mass = mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=node))

mGround = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[0, 0, 0]))
mMass = mbs.AddMarker(MarkerBodyPosition(bodyNumber=mass, localPosition=[0, 0, 0]))
mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[mGround, mMass], referenceLength=L,
                                          stiffness=k, damping=d))
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
