# corpus: task=flying_rigid_body seed=0 expect=pass
# style: numpy vectors for every input, dict of settings, no ground (as asked)
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 2230.0
sides = np.array([0.492, 0.119, 0.0268])
v0 = np.array([2.13, 0.0, 7.12])
w0 = np.array([-1.19, -1.13, 12.2])
g = np.array([0, 0, -9.804])

body = mbs.CreateRigidBody(inertia=InertiaCuboid(rho, sides), referencePosition=np.zeros(3),
                           referenceRotationMatrix=np.eye(3), initialVelocity=v0,
                           initialAngularVelocity=w0, gravity=g)
mbs.Assemble()

config = {"endTime": 2.0, "numberOfSteps": 2000}
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = config["endTime"]
simulationSettings.timeIntegration.numberOfSteps = config["numberOfSteps"]
mbs.SolveDynamic(simulationSettings)
