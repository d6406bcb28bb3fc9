# corpus: task=double_pendulum seed=1 expect=pass
# style: explicit step by step, trigonometry with np.pi/180, comments on each item
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m1 = 1.96   # kg
m2 = 1.33   # kg
L1 = 0.302  # m
L2 = 1.3    # m
phi1 = 19.0 * np.pi / 180   # absolute angle of rod 1
phi2 = -27.0 * np.pi / 180  # absolute angle of rod 2
g = 9.825

# positions of the two bobs
x1, y1 = L1 * np.sin(phi1), -L1 * np.cos(phi1)
x2, y2 = x1 + L2 * np.sin(phi2), y1 - L2 * np.cos(phi2)

ground = mbs.CreateGround(referencePosition=[0, 0, 0])             # fixed support
bob1 = mbs.CreateMassPoint(referencePosition=[x1, y1, 0], mass=m1, gravity=[0, -g, 0])
bob2 = mbs.CreateMassPoint(referencePosition=[x2, y2, 0], mass=m2, gravity=[0, -g, 0])
mbs.CreateDistanceConstraint(itemNumbers=[ground, bob1], distance=L1)  # rod 1
mbs.CreateDistanceConstraint(itemNumbers=[bob1, bob2], distance=L2)    # rod 2

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
simulationSettings.timeIntegration.verboseMode = 1
mbs.SolveDynamic(simulationSettings)
