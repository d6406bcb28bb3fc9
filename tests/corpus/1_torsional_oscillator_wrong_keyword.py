# corpus: task=torsional_oscillator seed=1 expect=fail stage=finished_assemble
# mistake: a keyword that CreateTorsionalSpringDamper does not have (rotationAxis)
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
m, r, w = 10.7, 0.167, 0.0528
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
disc = mbs.CreateRigidBody(referencePosition=[0, 0, 0], initialAngularVelocity=[0, 0, 12.3],
                           inertia=InertiaCylinder(density=m / (np.pi * r**2 * w), length=w, outerRadius=r, axis=2))
mbs.CreateRevoluteJoint(itemNumbers=[ground, disc], position=[0, 0, 0], axis=[0, 0, 1])
mbs.CreateTorsionalSpringDamper(itemNumbers=[ground, disc], position=[0, 0, 0], rotationAxis=[0, 0, 1],
                                stiffness=226.0, damping=1.29)
mbs.CreateTorque(itemNumber=disc, loadVector=[0, 0, 18.4])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
