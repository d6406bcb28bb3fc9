# corpus: task=double_mass_oscillator seed=1 expect=fail stage=topology_match cause="connections"
# mistake: spring 2 attached to ground instead of mass point 1 (both springs hang on the wall)
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
m1 = mbs.CreateMassPoint(referencePosition=[1.8, 0, 0], mass=4.24)
m2 = mbs.CreateMassPoint(referencePosition=[1.8 + 0.862, 0, 0], initialDisplacement=[0.0463, 0, 0], mass=2.18)
mbs.CreateSpringDamper(itemNumbers=[ground, m1], stiffness=1880.0, damping=2.41)
mbs.CreateSpringDamper(itemNumbers=[ground, m2], stiffness=844.0, damping=4.3, referenceLength=0.862)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
