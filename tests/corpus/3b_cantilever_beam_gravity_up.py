# corpus: task=cantilever_beam seed=1 expect=fail stage=graph_content_match category="gravity and load"
# mistake: gravity vector written as [0, 0, g] (acts in +z) while the tip force correctly points in -z
import exudyn as exu
from exudyn.utilities import *
from exudyn.FEM import FEMinterface
import numpy as np

SC = exu.SystemContainer()
mbs = SC.AddSystem()

L = 0.463          # beam length
g = 9.81
F_tip = 24.0       # N

fem = FEMinterface()
fem.LoadFromFile('beam.npz')

beam = mbs.CreateFFRFReducedOrderObject('beam', fem, referencePosition=[0, 0, 0],
                                        gravity=[0, 0, g])

ground = mbs.CreateGround(referencePosition=[0, 0, 0])
mClamp = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mClamp, beam['beam:left']],
                           constrainedAxes=[1, 1, 1, 1, 1, 1]))

mbs.AddLoad(Force(markerNumber=beam['beam:right'], loadVector=[0, 0, -F_tip]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.1
simulationSettings.timeIntegration.numberOfSteps = 200
simulationSettings.solution.file.write = False
mbs.SolveDynamic(simulationSettings)
print("done")
