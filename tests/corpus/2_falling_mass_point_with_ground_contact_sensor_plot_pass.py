# corpus: task=falling_mass_point_with_ground_contact seed=0 expect=pass
# style: numpy arrays for the inputs, height sensor, bounce count printed and a plot written to disk
import numpy as np
import exudyn as exu
from exudyn.utilities import *
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m = 0.757
r = 0.0755
R = 1000.0            # radius of the sphere that represents the ground plane z = 0
k = 38000.0
e = 0.92
g = np.array([0.0, 0.0, -9.804])
p0 = np.array([0.0, 0.0, 0.959])
v0 = np.array([0.154, 0.0, 0.0])

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
ball = mbs.CreateMassPoint(referencePosition=p0, initialVelocity=v0, mass=m, gravity=g)
mbs.CreateSphereSphereContact(itemNumbers=[ground, ball],
                              localPosition0=[0, 0, -R], localPosition1=[0, 0, 0],
                              spheresRadii=[R, r], contactStiffness=k, contactDamping=0.0,
                              impactModel=2, restitutionCoefficient=e)

sensorPos = mbs.AddSensor(SensorBody(bodyNumber=ball, storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.Position))
mbs.Assemble()

sims = exu.SimulationSettings()
sims.timeIntegration.endTime = 1.0
sims.timeIntegration.numberOfSteps = 10000
sims.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(sims)

pos = mbs.GetSensorStoredData(sensorPos)
z = pos[:, 3]
contacts = np.sum((z[1:] < r) & (z[:-1] >= r))
print("number of ground contacts:", contacts)
print("lowest point of the centre:", z.min())

fig, ax = plt.subplots()
ax.plot(pos[:, 0], z)
ax.axhline(r, color='gray', ls='--')
ax.set_xlabel('t [s]')
ax.set_ylabel('z [m]')
fig.savefig('bouncing_ball.png')
