# corpus: task=mass_oscillator_with_user_function seed=1 expect=pass
# style: user function as a lambda, resonance ratio printed
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

mass = 1.66
k = 668.0
d = 7.84
L = 0.58
F0 = 2.73
omega = 27.6
print("excitation / natural frequency:", omega / np.sqrt(k / mass))

oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
oMass = mbs.CreateMassPoint(referencePosition=[L, 0, 0], mass=mass)
mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=k, damping=d)
mbs.CreateForce(itemNumber=oMass, loadVector=[F0, 0, 0],
                loadVectorUserFunction=lambda mbs, t, load: [F0 * np.sin(omega * t), 0, 0])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
