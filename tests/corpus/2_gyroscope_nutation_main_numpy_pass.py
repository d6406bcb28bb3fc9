# corpus: task=gyroscope_nutation seed=1 expect=pass
# style: if __name__ == "__main__" block, numpy rotation built from the axis, angular velocity sensor, prints
import numpy as np
import exudyn as exu
from exudyn.utilities import *

if __name__ == "__main__":
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()

    rho, R, t = 6950.0, 0.0828, 0.0253
    l = 0.123                 # distance support -> disc center
    alpha = 10.1 * np.pi / 180
    omegaSpin = 242.0
    g = 9.827

    u = np.array([np.cos(alpha), 0.0, np.sin(alpha)])     # axle direction
    discInertia = InertiaCylinder(density=rho, length=t, outerRadius=R, axis=0)
    print("disc mass:", discInertia.Mass())

    ground = mbs.CreateGround(referencePosition=[0, 0, 0])
    disc = mbs.CreateRigidBody(inertia=discInertia,
                               referencePosition=l * u,
                               referenceRotationMatrix=RotationMatrixY(-alpha),
                               initialVelocity=np.zeros(3),
                               initialAngularVelocity=omegaSpin * u,
                               gravity=np.array([0.0, 0.0, -g]))
    mbs.CreateSphericalJoint(itemNumbers=[ground, disc], position=[0, 0, 0])

    sOmega = mbs.AddSensor(SensorBody(bodyNumber=disc, storeInternal=True,
                                      outputVariableType=exu.OutputVariableType.AngularVelocity))
    mbs.Assemble()

    simulationSettings = exu.SimulationSettings()
    simulationSettings.timeIntegration.endTime = 1
    simulationSettings.timeIntegration.numberOfSteps = 10000
    mbs.SolveDynamic(simulationSettings)

    omega = mbs.GetSensorStoredData(sOmega)
    print("precession rate estimate (mean omega_z):", np.mean(omega[:, 3]))
