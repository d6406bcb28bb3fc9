# corpus: task=free_fall_mass_point seed=0 expect=pass
# style: legacy item interface with explicit markers, parameters in a dict
import exudyn as exu
from exudyn.itemInterface import NodePoint, MassPoint, MarkerBodyMass, LoadMassProportional

p = dict(m=1.46, x0=-0.403, y0=0.628, z0=6.38, g=9.81, tEnd=1.0, steps=1000)

SC = exu.SystemContainer()
mbs = SC.AddSystem()

node = mbs.AddNode(NodePoint(referenceCoordinates=[p["x0"], p["y0"], p["z0"]]))
body = mbs.AddObject(MassPoint(nodeNumber=node, physicsMass=p["m"]))
marker = mbs.AddMarker(MarkerBodyMass(bodyNumber=body))
mbs.AddLoad(LoadMassProportional(markerNumber=marker, loadVector=[0, 0, -p["g"]]))
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = p["tEnd"]
simulationSettings.timeIntegration.numberOfSteps = p["steps"]
mbs.SolveDynamic(simulationSettings)
