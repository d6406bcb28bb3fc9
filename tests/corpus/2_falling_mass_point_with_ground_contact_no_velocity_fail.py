# corpus: task=falling_mass_point_with_ground_contact seed=1 expect=fail stage=graph_content_match category="initial velocities"
# mistake: the initial horizontal velocity of the ball is forgotten (ball dropped from rest)
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 0.606
r = 0.0494
R = 1000.0
k = 49000.0
e = 0.9
g = 9.83

oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
oBall = mbs.CreateMassPoint(referencePosition=[0, 0, 0.719], mass=m, gravity=[0, 0, -g])
mbs.CreateSphereSphereContact(itemNumbers=[oGround, oBall], localPosition0=[0, 0, -R],
                              localPosition1=[0, 0, 0], spheresRadii=[R, r],
                              contactStiffness=k, contactDamping=0,
                              impactModel=2, restitutionCoefficient=e)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1.0
simulationSettings.timeIntegration.numberOfSteps = 10000
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)
print("done")
