# corpus: task=flying_mass_point seed=0 expect=pass
# style: everything inside main() called under if __name__ == "__main__", numpy vectors, version print
import numpy as np
import exudyn as exu
from exudyn.utilities import *


def build_model(mbs):
    params = {"mass": 2.8, "z0": 4.75, "v0": np.array([2.3, 2.69, 5.12]), "g": 9.801}
    mbs.CreateMassPoint(referencePosition=np.array([0.0, 0.0, params["z0"]]),
                        initialVelocity=params["v0"], mass=params["mass"],
                        gravity=np.array([0.0, 0.0, -params["g"]]))


def main():
    print("Exudyn version", exu.__version__)
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    build_model(mbs)
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = 2.0
    settings.timeIntegration.numberOfSteps = 1000
    settings.solutionSettings.writeSolutionToFile = False
    mbs.SolveDynamic(settings)
    print("done")


if __name__ == "__main__":
    main()
