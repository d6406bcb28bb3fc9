# corpus: task=single_pendulum_rigid_body seed=1 expect=fail stage=graph_content_match category="kinematics/marker"
# mistake: revolute axis along x instead of z
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L = 1.14
phi = np.radians(49.0)
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
link = mbs.CreateRigidBody(referencePosition=[0.5 * L * np.sin(phi), -0.5 * L * np.cos(phi), 0],
                           referenceRotationMatrix=RotationMatrixZ(phi),
                           inertia=InertiaCuboid(density=4140.0, sideLengths=[0.0379, L, 0.0373]),
                           gravity=[0, -9.781, 0])
mbs.CreateRevoluteJoint(itemNumbers=[ground, link], position=[0, 0, 0], axis=[1, 0, 0])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
