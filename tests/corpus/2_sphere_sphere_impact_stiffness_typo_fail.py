# corpus: task=sphere_sphere_impact seed=0 expect=fail stage=graph_content_match category="connector/constraint"
# mistake: contact stiffness typed as 1.9e5 N/m instead of 19000.0 N/m
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m0, r0 = 0.552, 0.057
m1, r1 = 0.222, 0.0453

s0 = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[2.37, 0, 0], mass=m0)
s1 = mbs.CreateMassPoint(referencePosition=[0.458, 0.01, 0], initialVelocity=[0, 0, 0], mass=m1)
mbs.CreateSphereSphereContact(itemNumbers=[s0, s1], spheresRadii=[r0, r1],
                              contactStiffness=1.9e5, contactDamping=0.0,
                              impactModel=2, restitutionCoefficient=0.92)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.5
simulationSettings.timeIntegration.numberOfSteps = 5000
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)
