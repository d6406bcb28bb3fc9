# corpus: task=2r_scara_robot seed=1 expect=fail stage=topology_match cause="surplus inert items only"
# mistake: a second, unused ground object (a "base plate") is created besides the ground the joints use
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

rho = 4360.0
L1, L2 = 0.349, 0.395
q1s, q2s = np.radians(38.0), np.radians(-69.0)
q1e, q2e = np.radians(53.0), np.radians(86.0)
T = 1.2
kP, kD = 541.0, 42.3

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
basePlate = mbs.CreateGround(referencePosition=[0, 0, -0.05])  # robot base (visual only)

P = L1 * np.array([np.cos(q1s), np.sin(q1s), 0])
link1 = mbs.CreateRigidBody(referencePosition=0.5 * P, referenceRotationMatrix=RotationMatrixZ(q1s),
                            inertia=InertiaCuboid(density=rho, sideLengths=[L1, 0.04, 0.04]),
                            gravity=[0, 0, -9.81])
link2 = mbs.CreateRigidBody(referencePosition=P + 0.5 * L2 * np.array([np.cos(q1s + q2s), np.sin(q1s + q2s), 0]),
                            referenceRotationMatrix=RotationMatrixZ(q1s + q2s),
                            inertia=InertiaCuboid(density=rho, sideLengths=[L2, 0.04, 0.04]),
                            gravity=[0, 0, -9.81])
mbs.CreateRevoluteJoint(itemNumbers=[ground, link1], position=[0, 0, 0], axis=[0, 0, 1])
mbs.CreateRevoluteJoint(itemNumbers=[link1, link2], position=P, axis=[0, 0, 1])


def CosineProfile(t, qs, qe):
    if t < T:
        return qs + (qe - qs) * (1 - np.cos(np.pi * t / T)) / 2, (qe - qs) * np.pi / (2 * T) * np.sin(np.pi * t / T)
    return qe, 0.0


def PD(t):
    phi1 = mbs.GetObjectOutputBody(link1, exu.OutputVariableType.Rotation)[2]
    phi2 = mbs.GetObjectOutputBody(link2, exu.OutputVariableType.Rotation)[2]
    w1 = mbs.GetObjectOutputBody(link1, exu.OutputVariableType.AngularVelocity)[2]
    w2 = mbs.GetObjectOutputBody(link2, exu.OutputVariableType.AngularVelocity)[2]
    q1d, v1d = CosineProfile(t, q1s, q1e)
    q2d, v2d = CosineProfile(t, q2s, q2e)
    tau1 = kP * (q1d - phi1) + kD * (v1d - w1)
    tau2 = kP * (q2d - (phi2 - phi1)) + kD * (v2d - (w2 - w1))
    return tau1, tau2


mbs.CreateTorque(itemNumber=link1, loadVector=[0, 0, 0],
                 loadVectorUserFunction=lambda mbs, t, load: [0, 0, PD(t)[0] - PD(t)[1]])
mbs.CreateTorque(itemNumber=link2, loadVector=[0, 0, 0],
                 loadVectorUserFunction=lambda mbs, t, load: [0, 0, PD(t)[1]])

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
simulationSettings.timeIntegration.computeLoadsJacobian = 2
mbs.SolveDynamic(simulationSettings)
