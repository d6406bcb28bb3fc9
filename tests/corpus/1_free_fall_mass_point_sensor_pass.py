# corpus: task=free_fall_mass_point seed=1 expect=pass
# style: position sensor stored internally, compares with the analytical solution and prints it
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 4.49
g = 9.782
p0 = np.array([0.71, -0.589, 19.5])

mass = mbs.CreateMassPoint(referencePosition=p0, mass=m, gravity=[0, 0, -g])
sPos = mbs.AddSensor(SensorBody(bodyNumber=mass, storeInternal=True,
                                outputVariableType=exu.OutputVariableType.Position))
mbs.Assemble()

sims = exu.SimulationSettings()
sims.timeIntegration.numberOfSteps = 1000
sims.timeIntegration.endTime = 1
sims.timeIntegration.verboseMode = 1
mbs.SolveDynamic(sims)

data = mbs.GetSensorStoredData(sPos)
z_exact = p0[2] - 0.5 * g * data[:, 0] ** 2
print("max error in z:", np.max(np.abs(data[:, 3] - z_exact)))
