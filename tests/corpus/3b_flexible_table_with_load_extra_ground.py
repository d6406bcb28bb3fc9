# corpus: task=flexible_table_with_load seed=1 expect=fail stage=topology_match cause="surplus inert items only"
# mistake: a second ground object is created at the start out of habit and never used
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()

oGroundUnused = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))

plate_thickness = 0.0295
leg_height = 0.66
load_force = 482.0
g = 9.81
lift = plate_thickness / 2 + leg_height
foot_x = 0.2548
foot_y = 0.1873

femTable = FEMinterface()
femTable.LoadFromFile('table.npz')
table = mbs.CreateFFRFReducedOrderObject('table', femTable, referencePosition=[0, 0, lift], gravity=[0, 0, -g])

oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
footPoints = {'foot1': [-foot_x, -foot_y, 0], 'foot2': [foot_x, -foot_y, 0],
              'foot3': [foot_x, foot_y, 0], 'foot4': [-foot_x, foot_y, 0]}
for foot, point in footPoints.items():
    mFoot = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=point))
    mbs.AddObject(GenericJoint(markerNumbers=[mFoot, table['table:' + foot]], constrainedAxes=[1, 1, 1, 1, 1, 1]))

mbs.AddLoad(Force(markerNumber=table['table:load'], loadVector=[0, 0, -load_force]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.1
simulationSettings.timeIntegration.numberOfSteps = 500
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
