# corpus: task=single_pendulum seed=1 expect=pass
# style: math module for the angle, helper returning the initial position, explicit settings object
import math
import exudyn as exu
from exudyn.utilities import *


def initial_position(length, angle_deg):
    phi = math.radians(angle_deg)
    return [length * math.sin(phi), -length * math.cos(phi), 0.0]


SC = exu.SystemContainer()
mbs = SC.AddSystem()

L = 1.87
m = 0.767
g = 9.811
p0 = initial_position(L, 56.0)

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bob = mbs.CreateMassPoint(referencePosition=p0, mass=m, gravity=[0, -g, 0])
mbs.CreateDistanceConstraint(itemNumbers=[ground, bob], distance=L)
mbs.Assemble()

settings = exu.SimulationSettings()
settings.timeIntegration.endTime = 2
settings.timeIntegration.numberOfSteps = 2000
settings.solutionSettings.writeSolutionToFile = False
mbs.SolveDynamic(settings)
