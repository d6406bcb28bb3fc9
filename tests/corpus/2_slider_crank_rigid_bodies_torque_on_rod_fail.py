# corpus: task=slider_crank_rigid_bodies seed=0 expect=fail stage=topology_match cause="connections"
# mistake: the driving torque is applied to the connecting rod instead of the crank
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 4030.0
r = 0.169          # crank
l = 0.584          # connecting rod
w = 0.0389
s = 0.0439         # slider cube
theta0 = 0.312 * np.pi / 180
g = 9.825

pB = np.array([r * np.cos(theta0), r * np.sin(theta0), 0])
pC = np.array([r * np.cos(theta0) + np.sqrt(l**2 - (r * np.sin(theta0))**2), 0, 0])
beta0 = -np.arcsin(r * np.sin(theta0) / l)

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
crank = mbs.CreateRigidBody(referencePosition=pB / 2, referenceRotationMatrix=RotationMatrixZ(theta0),
                            inertia=InertiaCuboid(rho, [r, w, w]), gravity=[0, -g, 0])
rod = mbs.CreateRigidBody(referencePosition=(pB + pC) / 2, referenceRotationMatrix=RotationMatrixZ(beta0),
                          inertia=InertiaCuboid(rho, [l, w, w]), gravity=[0, -g, 0])
slider = mbs.CreateRigidBody(referencePosition=pC, referenceRotationMatrix=np.eye(3),
                             inertia=InertiaCuboid(rho, [s, s, s]), gravity=[0, -g, 0])

mbs.CreateRevoluteJoint(itemNumbers=[ground, crank], position=[0, 0, 0], axis=[0, 0, 1])
mbs.CreateRevoluteJoint(itemNumbers=[crank, rod], position=pB, axis=[0, 0, 1])
mbs.CreateSphericalJoint(itemNumbers=[rod, slider], position=pC, constrainedAxes=[1, 1, 0])
mbs.CreatePrismaticJoint(itemNumbers=[ground, slider], position=pC, axis=[1, 0, 0])
mbs.CreateTorque(itemNumber=rod, loadVector=[0, 0, 0.254])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
