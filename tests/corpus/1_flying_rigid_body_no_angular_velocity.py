# corpus: task=flying_rigid_body seed=1 expect=fail stage=graph_content_match category="initial velocities"
# mistake: the initial angular velocity left out
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
body = mbs.CreateRigidBody(referencePosition=[0, 0, 0], referenceRotationMatrix=np.eye(3),
                           initialVelocity=[0.529, 0, 6.71],
                           inertia=InertiaCuboid(density=2370.0, sideLengths=[0.466, 0.104, 0.0311]),
                           gravity=[0, 0, -9.788])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
