# corpus: task=free_fall_mass_point seed=1 expect=fail stage=topology_match cause="missing item types"
# mistake: gravity forgotten: the mass point floats
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
mbs.CreateMassPoint(referencePosition=[0.71, -0.589, 19.5], mass=4.49)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1
simulationSettings.timeIntegration.numberOfSteps = 1000
mbs.SolveDynamic(simulationSettings)
