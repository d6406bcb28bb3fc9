# corpus: task=rigid_rotor_unbalanced seed=0 expect=fail stage=graph_content_match category="inertia and mass"
# mistake: the unbalance mass is left out of the rotor inertia (only the homogeneous cylinder)
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho, L, r = 7000.0, 0.374, 0.0697
m_u = 0.137   # unbalance mass on the surface
omega0 = 5.87
M = 0.162
g = 9.824

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
rotor = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                            referenceRotationMatrix=np.eye(3),
                            initialAngularVelocity=[omega0, 0, 0],
                            inertia=InertiaCylinder(density=rho, length=L, outerRadius=r, axis=0),
                            gravity=[0, 0, -g])
mbs.CreateSphericalJoint(itemNumbers=[ground, rotor], position=[-L / 2, 0, 0])
mbs.CreateGenericJoint(itemNumbers=[ground, rotor], position=[L / 2, 0, 0],
                       constrainedAxes=[0, 1, 1, 0, 0, 0])
mbs.CreateTorque(itemNumber=rotor, loadVector=[M, 0, 0])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
