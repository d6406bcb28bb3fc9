# corpus: task=double_pendulum seed=0 expect=pass
# style: prints exu.__version__, angles in a list converted with a comprehension, list.remove on a work list
import numpy as np
import exudyn as exu
from exudyn.utilities import *

print("Exudyn", exu.__version__)
SC = exu.SystemContainer()
mbs = SC.AddSystem()

masses = [0.902, 2.85]
lengths = [0.527, 0.515]
angles = [np.radians(a) for a in [17.0, -22.0]]
g = 9.814

points = []
p = np.zeros(3)
for L, phi in zip(lengths, angles):
    p = p + np.array([L * np.sin(phi), -L * np.cos(phi), 0])
    points.append(p.copy())

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bodies = [mbs.CreateMassPoint(referencePosition=list(pt), mass=m, gravity=[0, -g, 0])
          for pt, m in zip(points, masses)]

todo = [ground] + bodies
while len(todo) > 1:
    a = todo[0]
    todo.remove(a)
    mbs.CreateDistanceConstraint(itemNumbers=[a, todo[0]], distance=lengths[len(bodies) - len(todo)])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
