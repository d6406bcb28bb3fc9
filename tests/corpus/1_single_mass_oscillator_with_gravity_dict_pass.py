# corpus: task=single_mass_oscillator_with_gravity seed=1 expect=pass
# style: parameters in a dict, unpacked with ** into a builder function
import numpy as np
import exudyn as exu
from exudyn.utilities import *

parameters = {"m": 4.91, "k": 981.0, "d": 0.727, "L": 0.592, "lift": 0.152, "g": 9.782}


def create_oscillator(mbs, m, k, d, L, lift, g):
    ground = mbs.CreateGround(referencePosition=[0, 0, 0])
    mass = mbs.CreateMassPoint(referencePosition=np.array([0, -L, 0]),
                               initialDisplacement=np.array([0, lift, 0]),
                               mass=m, gravity=np.array([0, -g, 0]))
    spring = mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=k, damping=d)
    return ground, mass, spring


SC = exu.SystemContainer()
mbs = SC.AddSystem()
items = create_oscillator(mbs, **parameters)
print("created items:", items)
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
