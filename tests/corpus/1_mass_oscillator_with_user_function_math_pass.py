# corpus: task=mass_oscillator_with_user_function seed=0 expect=pass
# style: user function with math.sin and its own argument names, defined after the parameters
import math
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m, k, d = 1.44, 1850.0, 16.6
L = 0.613
F0, Omega = 2.2, 44.3


def excitation(mbs, time, load):
    return [F0 * math.sin(Omega * time), 0.0, 0.0]


ground = mbs.CreateGround(referencePosition=[0, 0, 0])
body = mbs.CreateMassPoint(referencePosition=[L, 0, 0], mass=m)
mbs.CreateSpringDamper(itemNumbers=[ground, body], stiffness=k, damping=d)
mbs.CreateForce(itemNumber=body, loadVector=[F0, 0, 0], loadVectorUserFunction=excitation)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
