# corpus: task=pendulum_wall_impacting seed=1 expect=fail stage=finished_assemble
# mistake: the bob is modeled as a mass point instead of a rigid body, the sphere-triangle contact needs a rigid-body marker
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m, r = 0.814, 0.0274
L = 0.583
phi0 = np.deg2rad(42.0)
k, e = 43000.0, 0.76
g = 9.818

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bob = mbs.CreateMassPoint(referencePosition=[-L * np.sin(phi0), 0, -L * np.cos(phi0)],
                          mass=m, gravity=[0, 0, -g])
mbs.CreateDistanceConstraint(itemNumbers=[ground, bob], distance=L)
mbs.CreateSphereTriangleContact(itemNumbers=[bob, ground], sphereRadius=r,
                                trianglePoints=exu.Vector3DList([[r, -L, -2 * L], [r, L, -2 * L], [r, 0, 0]]),
                                contactStiffness=k, contactDamping=0,
                                impactModel=2, restitutionCoefficient=e)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1.5
simulationSettings.timeIntegration.numberOfSteps = 15000
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)
