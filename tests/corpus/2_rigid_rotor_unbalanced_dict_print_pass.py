# corpus: task=rigid_rotor_unbalanced seed=1 expect=pass
# style: dictionary of parameters, inertia built in two steps and printed, bearing positions in a list, sensor on the angular velocity
import numpy as np
import exudyn as exu
from exudyn.utilities import *

params = {
    'density': 7780.0,
    'length': 0.327,
    'radius': 0.0995,
    'unbalanceMass': 0.092,
    'omega0': 2.85,
    'torque': 0.0857,
    'g': 9.782,
}

SC = exu.SystemContainer()
mbs = SC.AddSystem()

inertiaCylinder = InertiaCylinder(density=params['density'], length=params['length'],
                                  outerRadius=params['radius'], axis=0)
inertiaUnbalance = InertiaMassPoint(mass=params['unbalanceMass']).Translated([0, 0, params['radius']])
rotorInertia = inertiaCylinder + inertiaUnbalance
print("rotor mass:", rotorInertia.Mass(), "COM:", rotorInertia.COM())

ground = mbs.CreateGround()
rotor = mbs.CreateRigidBody(inertia=rotorInertia,
                            referencePosition=[0, 0, 0],
                            initialAngularVelocity=[params['omega0'], 0, 0],
                            gravity=[0, 0, -params['g']])

bearings = [[-params['length'] / 2, 0, 0], [params['length'] / 2, 0, 0]]
mbs.CreateSphericalJoint(itemNumbers=[ground, rotor], position=bearings[0])
mbs.CreateGenericJoint(itemNumbers=[ground, rotor], position=bearings[1],
                       constrainedAxes=[0, 1, 1, 0, 0, 0])
mbs.CreateTorque(itemNumber=rotor, loadVector=[params['torque'], 0, 0])

sOmega = mbs.AddSensor(SensorBody(bodyNumber=rotor, storeInternal=True,
                                  outputVariableType=exu.OutputVariableType.AngularVelocity))

mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 2.0
simulationSettings.timeIntegration.numberOfSteps = 2000
mbs.SolveDynamic(simulationSettings)
print("final spin speed:", mbs.GetSensorStoredData(sOmega)[-1, 1])
