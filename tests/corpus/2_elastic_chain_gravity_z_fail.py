# corpus: task=elastic_chain seed=0 expect=fail stage=graph_content_match category="gravity and load"
# mistake: gravity applied along -z instead of the requested -y direction
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

n = 8
L = 2.14
m = 0.459
k = 1640.0
d = 3.15
h = L / (n + 1)
l0 = 0.854 * h
g = 9.818

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
chain = [mbs.CreateMassPoint(referencePosition=[i * h, 0, 0], mass=m, gravity=[0, 0, -g])
         for i in range(1, n + 1)]

# springs from A over all mass points to B
mbs.CreateSpringDamper(itemNumbers=[ground, chain[0]], localPosition0=[0, 0, 0],
                       referenceLength=l0, stiffness=k, damping=d)
for left, right in zip(chain, chain[1:]):
    mbs.CreateSpringDamper(itemNumbers=[left, right], referenceLength=l0, stiffness=k, damping=d)
mbs.CreateSpringDamper(itemNumbers=[ground, chain[-1]], localPosition0=[L, 0, 0],
                       referenceLength=l0, stiffness=k, damping=d)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
