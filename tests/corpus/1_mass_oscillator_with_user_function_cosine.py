# corpus: task=mass_oscillator_with_user_function seed=0 expect=fail stage=solution_match
# mistake: cosine instead of sine in the user function (same items, other motion)
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
F0, omega = 2.2, 44.3


def UFforce(mbs, t, loadVector):
    return [F0 * np.cos(omega * t), 0, 0]


ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mass = mbs.CreateMassPoint(referencePosition=[0.613, 0, 0], mass=1.44)
mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=1850.0, damping=16.6)
mbs.CreateForce(itemNumber=mass, loadVector=[F0, 0, 0], loadVectorUserFunction=UFforce)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
