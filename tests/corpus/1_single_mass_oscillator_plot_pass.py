# corpus: task=single_mass_oscillator seed=1 expect=pass
# style: sensor, matplotlib plot saved to a file (Agg backend), eigenfrequency printed
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

mass, k, d = 1.64, 874.0, 1.71
L = 1.14
x0 = 0.117

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
body = mbs.CreateMassPoint(referencePosition=[L, 0, 0], initialDisplacement=[x0, 0, 0], mass=mass)
mbs.CreateSpringDamper(itemNumbers=[ground, body], stiffness=k, damping=d)
sensor = mbs.AddSensor(SensorBody(bodyNumber=body, storeInternal=True,
                                  outputVariableType=exu.OutputVariableType.Displacement))
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)

print(f"natural frequency: {np.sqrt(k / mass) / (2 * np.pi):.3f} Hz")
result = mbs.GetSensorStoredData(sensor)
plt.plot(result[:, 0], result[:, 1], label="x displacement")
plt.xlabel("time (s)")
plt.legend()
plt.savefig("displacement.png")
