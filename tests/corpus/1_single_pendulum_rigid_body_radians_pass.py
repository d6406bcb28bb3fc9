# corpus: task=single_pendulum_rigid_body seed=0 expect=pass
# style: inertia object built first and its mass printed, rotation from np.radians
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 3650.0
w, L, h = 0.0419, 1.41, 0.0124
phi0 = np.radians(22.0)
g = 9.816

inertia = InertiaCuboid(density=rho, sideLengths=[w, L, h])
print("link mass:", inertia.Mass())
com = np.array([np.sin(phi0), -np.cos(phi0), 0.0]) * L / 2

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
link = mbs.CreateRigidBody(inertia=inertia, referencePosition=com,
                           referenceRotationMatrix=RotationMatrixZ(phi0), gravity=[0, -g, 0])
mbs.CreateRevoluteJoint(itemNumbers=[ground, link], position=[0, 0, 0], axis=[0, 0, 1])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
