# corpus: task=2r_scara_robot seed=0 expect=pass
# style: parameter dict, links built in a loop into a list, one PD controller function shared by both torque user functions
import numpy as np
import exudyn as exu
from exudyn.utilities import *

SC = exu.SystemContainer()
mbs = SC.AddSystem()

P = dict(rho=4180.0, L=[0.419, 0.278], qStart=[15.0, -88.0], qEnd=[19.0, 50.0],
         T=1.5, kP=607.0, kD=14.5, g=9.81)
qs = np.deg2rad(P["qStart"])
qe = np.deg2rad(P["qEnd"])

ground = mbs.CreateGround(referencePosition=[0, 0, 0])

links = []
jointPos = np.zeros(3)
angle = 0.0
for i in range(2):
    angle += qs[i]
    direction = np.array([np.cos(angle), np.sin(angle), 0.0])
    links.append(mbs.CreateRigidBody(referencePosition=jointPos + 0.5 * P["L"][i] * direction,
                                     referenceRotationMatrix=RotationMatrixZ(angle),
                                     inertia=InertiaCuboid(density=P["rho"],
                                                           sideLengths=[P["L"][i], 0.04, 0.04]),
                                     gravity=[0, 0, -P["g"]]))
    if i == 0:
        joint2 = jointPos + P["L"][0] * direction
    jointPos = jointPos + P["L"][i] * direction

mbs.CreateRevoluteJoint(itemNumbers=[ground, links[0]], position=[0, 0, 0], axis=[0, 0, 1])
mbs.CreateRevoluteJoint(itemNumbers=[links[0], links[1]], position=joint2, axis=[0, 0, 1])


def Desired(t):
    """desired joint angles and velocities (cosine profile)"""
    if t >= P["T"]:
        return qe, np.zeros(2)
    x = np.pi * t / P["T"]
    return qs + (qe - qs) * (1 - np.cos(x)) / 2, (qe - qs) * np.pi / (2 * P["T"]) * np.sin(x)


def Control(mbs, t):
    phi = [mbs.GetObjectOutputBody(b, exu.OutputVariableType.Rotation)[2] for b in links]
    om = [mbs.GetObjectOutputBody(b, exu.OutputVariableType.AngularVelocity)[2] for b in links]
    q = np.array([phi[0], phi[1] - phi[0]])
    qd = np.array([om[0], om[1] - om[0]])
    qRef, vRef = Desired(t)
    return P["kP"] * (qRef - q) + P["kD"] * (vRef - qd)


def TorqueLink1(mbs, t, loadVector):
    tau = Control(mbs, t)
    return [0, 0, tau[0] - tau[1]]


def TorqueLink2(mbs, t, loadVector):
    tau = Control(mbs, t)
    return [0, 0, tau[1]]


mbs.CreateTorque(itemNumber=links[0], loadVector=[0, 0, 0], loadVectorUserFunction=TorqueLink1)
mbs.CreateTorque(itemNumber=links[1], loadVector=[0, 0, 0], loadVectorUserFunction=TorqueLink2)

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2
simulationSettings.timeIntegration.numberOfSteps = 2000
simulationSettings.timeIntegration.computeLoadsJacobian = 2
mbs.SolveDynamic(simulationSettings)
