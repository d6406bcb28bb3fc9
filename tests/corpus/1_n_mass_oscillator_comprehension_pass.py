# corpus: task=n_mass_oscillator seed=0 expect=pass
# style: list comprehension for the bodies, numpy positions, static deflection printed
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

nMasses = 7
mass, stiffness, damping = 1.02, 2570.0, 0.746
spacing = 0.659
force = 8.4

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
positions = [np.array([i * spacing, 0.0, 0.0]) for i in range(1, nMasses + 1)]
points = [mbs.CreateMassPoint(referencePosition=p, mass=mass) for p in positions]
chain = [ground] + points
springs = [mbs.CreateSpringDamper(itemNumbers=[a, b], stiffness=stiffness, damping=damping)
           for a, b in zip(chain[:-1], chain[1:])]
mbs.CreateForce(itemNumber=points[-1], loadVector=[force, 0, 0])
print("static elongation of each spring:", force / stiffness)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
