# corpus: task=flying_rigid_body seed=0 expect=fail stage=graph_content_match category="inertia and mass"
# mistake: side lengths along x and y swapped in InertiaCuboid
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
body = mbs.CreateRigidBody(referencePosition=[0, 0, 0], referenceRotationMatrix=np.eye(3),
                           initialVelocity=[2.13, 0, 7.12], initialAngularVelocity=[-1.19, -1.13, 12.2],
                           inertia=InertiaCuboid(density=2230.0, sideLengths=[0.119, 0.492, 0.0268]),
                           gravity=[0, 0, -9.804])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
