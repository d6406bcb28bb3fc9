# corpus: task=single_pendulum_rigid_body seed=0 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: RotationMatrixZ given the angle in degrees
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L, phi_deg = 1.41, 22.0
phi = np.radians(phi_deg)
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
link = mbs.CreateRigidBody(referencePosition=[0.5 * L * np.sin(phi), -0.5 * L * np.cos(phi), 0],
                           referenceRotationMatrix=RotationMatrixZ(phi_deg),
                           inertia=InertiaCuboid(density=3650.0, sideLengths=[0.0419, L, 0.0124]),
                           gravity=[0, -9.816, 0])
mbs.CreateRevoluteJoint(itemNumbers=[ground, link], position=[0, 0, 0], axis=[0, 0, 1])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
