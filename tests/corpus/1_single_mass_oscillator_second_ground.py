# corpus: task=single_mass_oscillator seed=0 expect=fail stage=topology_match cause="surplus inert items only"
# mistake: two grounds: one for the spring and an unused one created at the top
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
oGround = mbs.CreateGround()
support = mbs.CreateGround(referencePosition=[0, 0, 0])
oMass = mbs.CreateMassPoint(referencePosition=[1.37, 0, 0], initialDisplacement=[0.0369, 0, 0], mass=0.885)
mbs.CreateSpringDamper(itemNumbers=[support, oMass], stiffness=550.0, damping=4.01)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
