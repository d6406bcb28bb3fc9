# corpus: task=four_bar_mechanism_point_masses seed=0 expect=fail stage=graph_content_match category="rigid body configuration"
# mistake: crank angle 17.9 passed to cos/sin in degrees, not converted to radians
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

a, b, c, d = 0.0847, 0.467, 0.347, 0.49
mB, mC = 1.42, 0.271
g = 9.789
theta0 = 17.9  # crank angle

B = np.array([a * np.cos(theta0), a * np.sin(theta0), 0])
D = np.array([d, 0, 0])
e = D - B
f = np.linalg.norm(e)
s = (b**2 - c**2 + f**2) / (2 * f)
hh = np.sqrt(b**2 - s**2)
C = B + (s / f) * e + (hh / f) * np.array([-e[1], e[0], 0])

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
pointB = mbs.CreateMassPoint(referencePosition=B, mass=mB, gravity=[0, -g, 0])
pointC = mbs.CreateMassPoint(referencePosition=C, mass=mC, gravity=[0, -g, 0])
mbs.CreateDistanceConstraint(itemNumbers=[ground, pointB], localPosition0=[0, 0, 0], distance=a)
mbs.CreateDistanceConstraint(itemNumbers=[pointB, pointC], distance=b)
mbs.CreateDistanceConstraint(itemNumbers=[ground, pointC], localPosition0=D, distance=c)
mbs.CreateCoordinateConstraint(itemNumbers=[None, pointB], coordinates=[None, 2])
mbs.CreateCoordinateConstraint(itemNumbers=[None, pointC], coordinates=[None, 2])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
