# corpus: task=newtons_cradle seed=1 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: spheres spaced by one diameter 2*r, the 0.002 m gap between neighbours left out
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m, r, L = 0.454, 0.0243, 0.417
g = 9.815
k, e = 49000.0, 0.78
nBalls = 4
dx = 2 * r   # spheres touching each other

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
balls = []
for i in range(nBalls):
    pos = [-L, 0, L] if i == 0 else [i * dx, 0, 0]
    balls.append(mbs.CreateMassPoint(referencePosition=pos, mass=m, gravity=[0, 0, -g]))

for i, ball in enumerate(balls):
    mbs.CreateDistanceConstraint(itemNumbers=[ground, ball], localPosition0=[i * dx, 0, L], distance=L)

for b0, b1 in zip(balls[:-1], balls[1:]):
    mbs.CreateSphereSphereContact(itemNumbers=[b0, b1], spheresRadii=[r, r],
                                  contactStiffness=k, contactDamping=0,
                                  impactModel=2, restitutionCoefficient=e)

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.6
simulationSettings.timeIntegration.numberOfSteps = 6000
simulationSettings.timeIntegration.discontinuous.iterationTolerance = 1e-3
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)
