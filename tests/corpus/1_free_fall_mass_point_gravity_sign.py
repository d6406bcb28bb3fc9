# corpus: task=free_fall_mass_point seed=0 expect=fail stage=graph_content_match category="gravity and load"
# mistake: gravity vector with the wrong sign (+z)
import exudyn as exu
from exudyn.utilities import *

g = 9.81
SC = exu.SystemContainer()
mbs = SC.AddSystem()
mbs.CreateMassPoint(referencePosition=[-0.403, 0.628, 6.38], mass=1.46, gravity=[0, 0, g])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1
simulationSettings.timeIntegration.numberOfSteps = 1000
mbs.SolveDynamic(simulationSettings)
