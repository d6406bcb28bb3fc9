# corpus: task=slider_crank_rigid_bodies seed=1 expect=pass
# style: version print, helper function for the cuboid bodies, slider position sensor and a matplotlib plot saved to a file
import numpy as np
import exudyn as exu
from exudyn.utilities import *
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

print("using exudyn", exu.__version__)

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 7390.0
r, l, w, s = 0.13, 0.457, 0.0285, 0.0597
g = 9.83
theta0 = np.deg2rad(240.0)
M = 0.0812

B = np.array([r * np.cos(theta0), r * np.sin(theta0), 0.0])
C = np.array([r * np.cos(theta0) + np.sqrt(l**2 - r**2 * np.sin(theta0)**2), 0.0, 0.0])
beta0 = -np.arcsin(r * np.sin(theta0) / l)


def AddCuboid(position, angle, sides):
    """homogeneous cuboid, reference point = center of mass, rotated about z"""
    return mbs.CreateRigidBody(referencePosition=position,
                               referenceRotationMatrix=RotationMatrixZ(angle),
                               inertia=InertiaCuboid(density=rho, sideLengths=sides),
                               gravity=[0, -g, 0])


ground = mbs.CreateGround()
crank = AddCuboid(B / 2, theta0, [r, w, w])
rod = AddCuboid((B + C) / 2, beta0, [l, w, w])
slider = AddCuboid(C, 0.0, [s, s, s])

ez = [0, 0, 1]
mbs.CreateRevoluteJoint(itemNumbers=[ground, crank], position=[0, 0, 0], axis=ez)
mbs.CreateRevoluteJoint(itemNumbers=[crank, rod], position=B, axis=ez)
mbs.CreateSphericalJoint(itemNumbers=[rod, slider], position=C, constrainedAxes=[1, 1, 0])
mbs.CreatePrismaticJoint(itemNumbers=[ground, slider], position=C, axis=[1, 0, 0])
mbs.CreateTorque(itemNumber=crank, loadVector=[0, 0, M])

sSlider = mbs.AddSensor(SensorBody(bodyNumber=slider, storeInternal=True,
                                   outputVariableType=exu.OutputVariableType.Position))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)

data = mbs.GetSensorStoredData(sSlider)
plt.plot(data[:, 0], data[:, 1], label="slider x")
plt.xlabel("time (s)")
plt.ylabel("x (m)")
plt.legend()
plt.savefig("slider_crank_slider_position.png")
