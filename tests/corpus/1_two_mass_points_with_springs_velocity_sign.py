# corpus: task=two_mass_points_with_springs seed=0 expect=fail stage=graph_content_match category="initial velocities"
# mistake: velocity of mass point 2 with the wrong sign
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
p1 = mbs.CreateMassPoint(referencePosition=[-0.317, 0, 0], initialVelocity=[0, 1.31, 0], mass=1.55)
p2 = mbs.CreateMassPoint(referencePosition=[0.317, 0, 0], initialVelocity=[0, 2.83, 0], mass=0.971)
mbs.CreateSpringDamper(itemNumbers=[p1, p2], stiffness=1680.0, damping=0.0501)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
