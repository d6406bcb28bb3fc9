# corpus: task=flexible_table_with_load seed=0 expect=pass
# style: lift and foot positions computed from the table geometry, feet from sign pairs in a loop, sensor on the load pad
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

print(exu.__version__)

SC = exu.SystemContainer()
mbs = SC.AddSystem()

# table geometry (m)
table_length = 0.684
table_width = 0.537
plate_thickness = 0.0252
leg_height = 0.659
leg_size = 0.0574
leg_inset = 0.0371
# loading
load_force = 504.0   # N
g = 9.81             # m/s^2

lift = plate_thickness / 2 + leg_height                  # feet end on the floor z = 0
foot_x = table_length / 2 - leg_inset - leg_size / 2
foot_y = table_width / 2 - leg_inset - leg_size / 2
print(f"lift = {lift:.5f}, foot_x = {foot_x:.4f}, foot_y = {foot_y:.4f}")

femTable = FEMinterface()
femTable.LoadFromFile('table.npz')
tableMarkers = mbs.CreateFFRFReducedOrderObject('table', femTable,
                                                referencePosition=np.array([0., 0., lift]),
                                                gravity=np.array([0., 0., -g]))

oGround = mbs.CreateGround()

# foot1..foot4 go counter-clockwise starting at (-x, -y)
signs = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
for k, (sx, sy) in enumerate(signs, start=1):
    footCentre = [sx * foot_x, sy * foot_y, 0.]
    mGroundFoot = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=footCentre))
    mbs.AddObject(GenericJoint(markerNumbers=[mGroundFoot, tableMarkers['table:foot%d' % k]],
                               constrainedAxes=[1, 1, 1, 1, 1, 1]))

mLoad = tableMarkers['table:load']
mbs.AddLoad(Force(markerNumber=mLoad, loadVector=[0., 0., -load_force]))

sPad = mbs.AddSensor(SensorMarker(markerNumber=mLoad, outputVariableType=exu.OutputVariableType.Displacement,
                                  writeToFile=False, storeInternal=True))

mbs.Assemble()

simSettings = exu.SimulationSettings()
simSettings.timeIntegration.numberOfSteps = 500
simSettings.timeIntegration.endTime = 0.1
simSettings.solution.file.write = False
mbs.SolveDynamic(simSettings)

u = mbs.GetSensorValues(sPad)
print('load pad displacement at the end:', u[-1, 1:])
