# corpus: task=sphere_sphere_impact seed=1 expect=pass
# style: legacy NodePoint/MassPoint/ObjectContactSphereSphere with a data node, velocity sensors, momentum check printed
import numpy as np
import exudyn as exu
from exudyn.itemInterface import *
from exudyn.utilities import SensorBody

SC = exu.SystemContainer()
mbs = SC.AddSystem()

spheres = [  # mass, radius, position, velocity
    (0.978, 0.0722, [0, 0, 0], [2.22, 0, 0]),
    (0.197, 0.037, [0.365, 0.0058, 0], [0, 0, 0]),
]

bodies = []
for mass, radius, pos, vel in spheres:
    node = mbs.AddNode(NodePoint(referenceCoordinates=pos, initialVelocities=vel))
    bodies.append(mbs.AddObject(MassPoint(physicsMass=mass, nodeNumber=node)))

markers = [mbs.AddMarker(MarkerBodyPosition(bodyNumber=b, localPosition=[0, 0, 0])) for b in bodies]
dataNode = mbs.AddNode(NodeGenericData(initialCoordinates=[0, 0, 0, 0], numberOfDataCoordinates=4))
mbs.AddObject(ObjectContactSphereSphere(markerNumbers=markers, nodeNumber=dataNode,
                                        spheresRadii=[spheres[0][1], spheres[1][1]],
                                        contactStiffness=27000.0, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=0.5))

velSensors = [mbs.AddSensor(SensorBody(bodyNumber=b, storeInternal=True,
                                       outputVariableType=exu.OutputVariableType.Velocity))
              for b in bodies]

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.5
simulationSettings.timeIntegration.numberOfSteps = 5000
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)

momentum = sum(spheres[i][0] * mbs.GetSensorStoredData(velSensors[i])[-1, 1:4] for i in range(2))
print("final momentum:", momentum, "initial:", spheres[0][0] * np.array(spheres[0][3]))
