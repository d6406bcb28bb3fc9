# corpus: task=single_pendulum seed=1 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: np.sin of the angle in degrees
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L, phi0 = 1.87, 56.0
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bob = mbs.CreateMassPoint(referencePosition=[L * np.sin(phi0), -L * np.cos(phi0), 0], mass=0.767,
                          gravity=[0, -9.811, 0])
mbs.CreateDistanceConstraint(itemNumbers=[ground, bob], distance=L)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
