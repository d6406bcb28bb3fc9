# corpus: task=single_mass_oscillator_with_gravity seed=1 expect=fail stage=graph_content_match category="gravity and load"
# mistake: gravity along -z while the oscillator hangs along -y
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mass = mbs.CreateMassPoint(referencePosition=[0, -0.592, 0], initialDisplacement=[0, 0.152, 0], mass=4.91,
                           gravity=[0, 0, -9.782])
mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=981.0, damping=0.727)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
