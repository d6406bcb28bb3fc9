# corpus: task=flexible_pendulum seed=0 expect=fail stage=graph_content_match category="connector/constraint"
# mistake: revolute joint frees the rotation about the global x-axis ([1,1,1,0,1,1]) instead of the y-axis
import numpy as np
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface

SC = exu.SystemContainer()
mbs = SC.AddSystem()

beam_length = 0.723
theta0_deg = 73.3
g = 9.81
theta0 = np.deg2rad(theta0_deg)

femBeam = FEMinterface()
femBeam.LoadFromFile('beam.npz')
beam = mbs.CreateFFRFReducedOrderObject('beam', femBeam, referencePosition=[0, 0, 0],
                                        referenceRotationMatrix=RotationMatrixY(np.pi/2 - theta0),
                                        gravity=[0, 0, -g])

oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
# pendulum swings in the x-z plane -> free rotation
mbs.AddObject(GenericJoint(markerNumbers=[mGround, beam['beam:left']],
                           constrainedAxes=[1, 1, 1, 0, 1, 1]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.5
simulationSettings.timeIntegration.numberOfSteps = 250
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
