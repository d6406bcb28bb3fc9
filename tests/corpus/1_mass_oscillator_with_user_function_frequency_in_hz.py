# corpus: task=mass_oscillator_with_user_function seed=1 expect=fail stage=solution_match
# mistake: omega taken as a frequency in Hz: sin(2*pi*omega*t)
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
F0, f = 2.73, 27.6
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mass = mbs.CreateMassPoint(referencePosition=[0.58, 0, 0], mass=1.66)
mbs.CreateSpringDamper(itemNumbers=[ground, mass], stiffness=668.0, damping=7.84)
mbs.CreateForce(itemNumber=mass, loadVector=[F0, 0, 0],
                loadVectorUserFunction=lambda mbs, t, load: [F0 * np.sin(2 * np.pi * f * t), 0, 0])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
