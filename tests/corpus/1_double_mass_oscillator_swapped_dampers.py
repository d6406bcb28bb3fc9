# corpus: task=double_mass_oscillator seed=0 expect=fail stage=graph_content_match category="connector/constraint"
# mistake: damping coefficients of the two springs swapped
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
m1 = mbs.CreateMassPoint(referencePosition=[1.79, 0, 0], mass=4.42)
m2 = mbs.CreateMassPoint(referencePosition=[1.79 + 1.88, 0, 0], initialDisplacement=[0.0221, 0, 0], mass=1.79)
mbs.CreateSpringDamper(itemNumbers=[ground, m1], stiffness=1290.0, damping=4.58)
mbs.CreateSpringDamper(itemNumbers=[m1, m2], stiffness=1600.0, damping=3.58)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
