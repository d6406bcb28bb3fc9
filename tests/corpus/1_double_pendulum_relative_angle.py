# corpus: task=double_pendulum seed=0 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: rod 2 angle taken relative to rod 1 although the description says absolute
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L1, L2 = 0.527, 0.515
phi1, phi2 = np.radians(17.0), np.radians(-22.0)
p1 = [L1 * np.sin(phi1), -L1 * np.cos(phi1), 0]
p2 = [p1[0] + L2 * np.sin(phi1 + phi2), p1[1] - L2 * np.cos(phi1 + phi2), 0]
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
b1 = mbs.CreateMassPoint(referencePosition=p1, mass=0.902, gravity=[0, -9.814, 0])
b2 = mbs.CreateMassPoint(referencePosition=p2, mass=2.85, gravity=[0, -9.814, 0])
mbs.CreateDistanceConstraint(itemNumbers=[ground, b1], distance=L1)
mbs.CreateDistanceConstraint(itemNumbers=[b1, b2], distance=L2)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
