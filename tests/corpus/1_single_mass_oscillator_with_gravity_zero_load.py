# corpus: task=single_mass_oscillator_with_gravity seed=0 expect=fail stage=topology_match cause="surplus inert items only"
# mistake: an extra force with a zero vector "for later excitation"
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mass = mbs.CreateMassPoint(referencePosition=[0, -0.621, 0], initialDisplacement=[0, 0.129, 0], mass=4.74,
                           gravity=[0, -9.799, 0])
mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=1120.0, damping=4.88)
excitation = mbs.CreateForce(itemNumber=mass, loadVector=[0, 0, 0])  # no excitation for now
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
