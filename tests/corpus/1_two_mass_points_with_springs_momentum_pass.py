# corpus: task=two_mass_points_with_springs seed=1 expect=pass
# style: checks momentum conservation from sensors after the solve
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m1, m2 = 1.1, 1.23
half = 0.252
v1, v2 = 2.3, 1.78

p1 = mbs.CreateMassPoint(referencePosition=[-half, 0, 0], initialVelocity=[0, v1, 0], mass=m1)
p2 = mbs.CreateMassPoint(referencePosition=[half, 0, 0], initialVelocity=[0, -v2, 0], mass=m2)
mbs.CreateSpringDamper(itemNumbers=[p1, p2], stiffness=1130.0, damping=4.58)
sensors = [mbs.AddSensor(SensorBody(bodyNumber=p, storeInternal=True,
                                    outputVariableType=exu.OutputVariableType.Velocity)) for p in (p1, p2)]
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)

vel1, vel2 = (mbs.GetSensorStoredData(s) for s in sensors)
momentum = m1 * vel1[:, 1:] + m2 * vel2[:, 1:]
print("momentum drift:", np.abs(momentum - momentum[0]).max())
