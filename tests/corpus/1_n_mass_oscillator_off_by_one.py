# corpus: task=n_mass_oscillator seed=1 expect=fail stage=topology_match cause="missing item types"
# mistake: range(1, n) builds n-1 mass points
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
n, L = 8, 0.55
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bodies = [ground]
for i in range(1, n):
    bodies.append(mbs.CreateMassPoint(referencePosition=[i * L, 0, 0], mass=2.38))
for i in range(len(bodies) - 1):
    mbs.CreateSpringDamper(itemNumbers=[bodies[i], bodies[i + 1]], stiffness=2690.0, damping=3.84)
mbs.CreateForce(itemNumber=bodies[-1], loadVector=[28.8, 0, 0])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
