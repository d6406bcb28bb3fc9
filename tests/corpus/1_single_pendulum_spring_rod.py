# corpus: task=single_pendulum seed=0 expect=fail stage=topology_match cause="missing item types"
# mistake: the rigid rod modelled as a stiff spring-damper instead of a distance constraint
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
L, phi0 = 1.15, np.radians(38.0)
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
bob = mbs.CreateMassPoint(referencePosition=[L * np.sin(phi0), -L * np.cos(phi0), 0], mass=0.56,
                          gravity=[0, -9.781, 0])
mbs.CreateSpringDamper(itemNumbers=[ground, bob], stiffness=1e6, damping=100)
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
