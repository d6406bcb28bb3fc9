# corpus: task=pendulum_wall_impacting seed=0 expect=pass
# style: wall triangle points prepared as a list, renderer calls guarded by a flag that is off headless, angle sensor printed
import numpy as np
import exudyn as exu
from exudyn.utilities import *

useGraphics = False   # set True to watch the animation

SC = exu.SystemContainer()
mbs = SC.AddSystem()

m, r = 0.797, 0.0332
L = 0.901
phi0 = np.radians(45.0)
k, e = 14000.0, 0.94
g = 9.818

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
p0 = [-L * np.sin(phi0), 0, -L * np.cos(phi0)]
bob = mbs.CreateRigidBody(referencePosition=p0,
                          referenceRotationMatrix=RotationMatrixZ(0),
                          inertia=InertiaSphere(mass=m, radius=r),
                          gravity=[0, 0, -g])
mbs.CreateDistanceConstraint(itemNumbers=[ground, bob], localPosition0=[0, 0, 0],
                             localPosition1=[0, 0, 0], distance=L)

wall = [[r, -L, -2 * L], [r, L, -2 * L], [r, 0, 0]]   # vertical plane x = r
mbs.CreateSphereTriangleContact(itemNumbers=[bob, ground], sphereRadius=r,
                                trianglePoints=exu.Vector3DList(wall),
                                contactStiffness=k, contactDamping=0,
                                impactModel=2, restitutionCoefficient=e)

sPos = mbs.AddSensor(SensorBody(bodyNumber=bob, storeInternal=True,
                                outputVariableType=exu.OutputVariableType.Position))
mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 1.5
simulationSettings.timeIntegration.numberOfSteps = 15000
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False

if useGraphics:
    exu.StartRenderer()
    mbs.WaitForUserToContinue()
mbs.SolveDynamic(simulationSettings)
if useGraphics:
    SC.WaitForRenderEngineStopFlag()
    exu.StopRenderer()

x = mbs.GetSensorStoredData(sPos)[:, 1]
print("maximum x of the bob centre:", x.max(), "(wall contact at x = 0)")
