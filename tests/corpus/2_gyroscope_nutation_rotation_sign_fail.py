# corpus: task=gyroscope_nutation seed=0 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: reference rotation RotationMatrixY(+alpha) instead of RotationMatrixY(-alpha), the disc axis tilts downwards
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 4330.0
R = 0.0838
t = 0.0203
l = 0.129
alpha = np.deg2rad(19.6)
omega = 229.0
g = 9.809

axis = np.array([np.cos(alpha), 0, np.sin(alpha)])
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
disc = mbs.CreateRigidBody(referencePosition=l * axis,
                           referenceRotationMatrix=RotationMatrixY(alpha),
                           initialVelocity=[0, 0, 0],
                           initialAngularVelocity=omega * axis,
                           inertia=InertiaCylinder(density=rho, length=t, outerRadius=R, axis=0),
                           gravity=[0, 0, -g])
mbs.CreateSphericalJoint(itemNumbers=[ground, disc], position=[0, 0, 0])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1.0
simulationSettings.timeIntegration.numberOfSteps = 10000
mbs.SolveDynamic(simulationSettings)
