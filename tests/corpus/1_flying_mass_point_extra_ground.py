# corpus: task=flying_mass_point seed=1 expect=fail stage=topology_match cause="surplus inert items only"
# mistake: a ground object added out of habit, nothing refers to it
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()
ground = mbs.CreateGround(referencePosition=[0, 0, 0])
projectile = mbs.CreateMassPoint(referencePosition=[0, 0, 3.06], initialVelocity=[5.57, -2.06, 10.0],
                                 mass=1.99, gravity=[0, 0, -9.781])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 1000
mbs.SolveDynamic(simulationSettings)
