# corpus: task=double_mass_oscillator seed=1 expect=pass
# style: masses and springs from lists in for-loops, list of bodies grown with append
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

masses = [4.24, 2.18]
stiffnesses = [1880.0, 844.0]
dampings = [2.41, 4.3]
lengths = [1.8, 0.862]
displacements = [0.0, 0.0463]

bodies = [mbs.CreateGround(referencePosition=[0, 0, 0])]
x = 0.0
for m, L, u in zip(masses, lengths, displacements):
    x += L
    bodies.append(mbs.CreateMassPoint(referencePosition=[x, 0, 0], initialDisplacement=[u, 0, 0], mass=m))

for i, (k, d) in enumerate(zip(stiffnesses, dampings)):
    mbs.CreateSpringDamper(itemNumbers=[bodies[i], bodies[i + 1]], stiffness=k, damping=d)

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
print("number of objects:", mbs.systemData.NumberOfObjects())
