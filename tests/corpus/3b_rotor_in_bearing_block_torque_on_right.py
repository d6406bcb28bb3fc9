# corpus: task=rotor_in_bearing_block seed=0 expect=fail stage=topology_match cause="connections"
# mistake: the drive torque is applied at the rotor's 'right' seat instead of its 'left' interface
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()

shaft_radius = 0.015
bearing_width = 0.0461
axis_height = 0.105
bearing_span = 0.448
omega0 = 48.8
torque = 1.06
g = 9.81
rotor_x = -bearing_width / 2

def load_part(name, **kwargs):
    fem = FEMinterface()
    fem.LoadFromFile(name + '.npz')
    return mbs.CreateFFRFReducedOrderObject(name, fem, gravity=[0, 0, -g], **kwargs)

block = load_part('block', referencePosition=[0, 0, 0])
rotor = load_part('rotor', referencePosition=[rotor_x, 0, axis_height],
                  initialAngularVelocity=[omega0, 0, 0])

oGround = mbs.CreateGround()
mG0 = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mG1 = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[bearing_span, 0, axis_height]))

mbs.AddObject(GenericJoint(markerNumbers=[mG0, block['block:bottom']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[block['block:bore'], rotor['rotor:left']], constrainedAxes=[1, 1, 1, 0, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[mG1, rotor['rotor:right']], constrainedAxes=[0, 1, 1, 0, 0, 0]))

# drive torque about the shaft axis
mbs.AddLoad(Torque(markerNumber=rotor['rotor:right'], loadVector=[torque, 0, 0]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.2
simulationSettings.timeIntegration.numberOfSteps = 200
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
