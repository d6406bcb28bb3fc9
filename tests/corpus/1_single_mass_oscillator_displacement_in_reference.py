# corpus: task=single_mass_oscillator seed=1 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: the initial displacement folded into the reference position, so the spring is relaxed at the start
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L, u0 = 1.14, 0.117
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mass = mbs.CreateMassPoint(referencePosition=[L + u0, 0, 0], mass=1.64)
mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=874.0, damping=1.71)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
