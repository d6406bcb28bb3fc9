# corpus: task=torsional_oscillator seed=0 expect=pass
# style: main(), inertia density computed from the mass, every Create call with keyword names
import numpy as np
import exudyn as exu
from exudyn.utilities import *


def main():
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    m, r, w = 15.4, 0.272, 0.0338
    rho = m / (np.pi * r**2 * w)
    disc_inertia = InertiaCylinder(density=rho, length=w, outerRadius=r, axis=2)

    ground = mbs.CreateGround(referencePosition=[0, 0, 0])
    disc = mbs.CreateRigidBody(inertia=disc_inertia, referencePosition=[0, 0, 0],
                               referenceRotationMatrix=np.eye(3), initialAngularVelocity=[0, 0, 3.9])
    mbs.CreateRevoluteJoint(itemNumbers=[ground, disc], position=[0, 0, 0], axis=[0, 0, 1])
    mbs.CreateTorsionalSpringDamper(itemNumbers=[ground, disc], position=[0, 0, 0], axis=[0, 0, 1],
                                    stiffness=131.0, damping=1.14)
    mbs.CreateTorque(itemNumber=disc, loadVector=[0, 0, 14.5])
    mbs.Assemble()

    simulationSettings = exu.SimulationSettings()
    simulationSettings.timeIntegration.endTime = 2
    simulationSettings.timeIntegration.numberOfSteps = 2000
    mbs.SolveDynamic(simulationSettings)
    print("static twist angle:", 14.5 / 131.0, "rad")


if __name__ == "__main__":
    main()
