# corpus: task=cantilever_beam seed=0 expect=pass
# style: everything in main() under __main__, parameter dict, numpy vectors, tip sensor with storeInternal, prints
import numpy as np
import exudyn as exu
from exudyn.itemInterface import MarkerBodyRigid, GenericJoint, Force, SensorMarker
from exudyn.FEM import FEMinterface

params = {
    'beam_length': 0.714,   # m
    'g': 9.81,              # m/s^2
    'tip_force': 19.3,      # N
    'end_time': 0.1,        # s
    'n_steps': 200,
}


def main():
    print('Exudyn version:', exu.__version__)
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()

    # flexible beam, own frame = global frame
    fem = FEMinterface()
    fem.LoadFromFile('beam.npz')
    gravity = np.array([0.0, 0.0, -params['g']])
    beamDict = mbs.CreateFFRFReducedOrderObject('beam', fem,
                                                referencePosition=np.zeros(3),
                                                referenceRotationMatrix=np.eye(3),
                                                gravity=gravity)
    mLeft = beamDict['beam:left']
    mRight = beamDict['beam:right']

    # clamp the left end to the ground
    ground = mbs.CreateGround(referencePosition=[0, 0, 0])
    mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
    mbs.AddObject(GenericJoint(markerNumbers=[mGround, mLeft], constrainedAxes=[1] * 6))

    # tip load at the right end face
    tipLoad = np.array([0.0, 0.0, -params['tip_force']])
    mbs.AddLoad(Force(markerNumber=mRight, loadVector=tipLoad))

    # tip displacement sensor
    sTip = mbs.AddSensor(SensorMarker(markerNumber=mRight, outputVariableType=exu.OutputVariableType.Position,
                                      storeInternal=True, writeToFile=False))

    mbs.Assemble()

    sim = exu.SimulationSettings()
    sim.timeIntegration.endTime = params['end_time']
    sim.timeIntegration.numberOfSteps = params['n_steps']
    sim.timeIntegration.verboseMode = 1
    sim.solution.file.write = False
    mbs.SolveDynamic(sim)

    tip = mbs.GetSensorValues(sTip)
    print('tip position at t_end:', tip[-1, 1:])
    print('tip deflection in z:', tip[-1, 3] - tip[0, 3])


if __name__ == "__main__":
    main()
