# corpus: task=single_pendulum_rigid_body seed=1 expect=pass
# style: main() with sensors on the link's angular velocity, results printed at the end
import numpy as np
import exudyn as exu
from exudyn.utilities import *


def run():
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    density, L, width, thickness = 4140.0, 1.14, 0.0379, 0.0373
    phi = 49.0 / 180 * np.pi
    gravity = 9.781

    oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
    oLink = mbs.CreateRigidBody(
        referencePosition=[0.5 * L * np.sin(phi), -0.5 * L * np.cos(phi), 0],
        referenceRotationMatrix=RotationMatrixZ(phi),
        inertia=InertiaCuboid(density=density, sideLengths=[width, L, thickness]),
        gravity=[0, -gravity, 0])
    mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1])
    sOmega = mbs.AddSensor(SensorBody(bodyNumber=oLink, storeInternal=True,
                                      outputVariableType=exu.OutputVariableType.AngularVelocity))
    mbs.Assemble()

    simulationSettings = exu.SimulationSettings()
    simulationSettings.timeIntegration.endTime = 2
    simulationSettings.timeIntegration.numberOfSteps = 2000
    mbs.SolveDynamic(simulationSettings)
    omega = mbs.GetSensorStoredData(sOmega)
    print("max angular velocity about z:", np.abs(omega[:, 3]).max())


if __name__ == "__main__":
    run()
