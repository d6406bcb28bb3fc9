# corpus: task=flying_mass_point seed=1 expect=pass
# style: legacy AddNode/AddObject/AddMarker/AddLoad API, gravity as a mass-proportional load
import exudyn as exu
from exudyn.itemInterface import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 1.99
g = 9.781
p0 = [0, 0, 3.06]
v0 = [5.57, -2.06, 10.0]

n0 = mbs.AddNode(NodePoint(referenceCoordinates=p0, initialVelocities=v0))
b0 = mbs.AddObject(MassPoint(physicsMass=m, nodeNumber=n0))
mMass = mbs.AddMarker(MarkerBodyMass(bodyNumber=b0))
mbs.AddLoad(LoadMassProportional(markerNumber=mMass, loadVector=[0, 0, -g]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 1000
simulationSettings.solutionSettings.writeSolutionToFile = False
mbs.SolveDynamic(simulationSettings)

print("final position:", mbs.GetNodeOutput(n0, exu.OutputVariableType.Position))
