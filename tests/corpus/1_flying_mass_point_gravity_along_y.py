# corpus: task=flying_mass_point seed=0 expect=fail stage=graph_content_match category="gravity and load"
# mistake: gravity along -y (the y-up habit) although the description says -z
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
mbs.CreateMassPoint(referencePosition=[0, 0, 4.75], initialVelocity=[2.3, 2.69, 5.12], mass=2.8,
                    gravity=[0, -9.801, 0])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 1000
mbs.SolveDynamic(simulationSettings)
