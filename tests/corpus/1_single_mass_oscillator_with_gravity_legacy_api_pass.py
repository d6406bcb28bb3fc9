# corpus: task=single_mass_oscillator_with_gravity seed=0 expect=pass
# style: legacy API, gravity as LoadMassProportional, guarded renderer
import exudyn as exu
from exudyn.itemInterface import *

useGraphics = False

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m, k, d = 4.74, 1120.0, 4.88
L = 0.621
lift = 0.129
g = 9.799

oGround = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
nMass = mbs.AddNode(NodePoint(referenceCoordinates=[0, -L, 0], initialCoordinates=[0, lift, 0]))
oMass = mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=nMass))
mMassCOM = mbs.AddMarker(MarkerBodyMass(bodyNumber=oMass))
mbs.AddLoad(LoadMassProportional(markerNumber=mMassCOM, loadVector=[0, -g, 0]))
m0 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=oGround, localPosition=[0, 0, 0]))
m1 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=oMass, localPosition=[0, 0, 0]))
mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[m0, m1], referenceLength=L, stiffness=k, damping=d))
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
if useGraphics:
    exu.StartRenderer()
mbs.SolveDynamic(simulationSettings)
if useGraphics:
    exu.StopRenderer()
