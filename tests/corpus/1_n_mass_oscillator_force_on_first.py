# corpus: task=n_mass_oscillator seed=0 expect=fail stage=topology_match cause="connections"
# mistake: the force acts on the first mass point instead of the last
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
masses = [mbs.CreateMassPoint(referencePosition=[i * 0.659, 0, 0], mass=1.02) for i in range(1, 8)]
chain = [ground] + masses
for a, b in zip(chain[:-1], chain[1:]):
    mbs.CreateSpringDamper(itemNumbers=[a, b], stiffness=2570.0, damping=0.746)
mbs.CreateForce(itemNumber=masses[0], loadVector=[8.4, 0, 0])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
