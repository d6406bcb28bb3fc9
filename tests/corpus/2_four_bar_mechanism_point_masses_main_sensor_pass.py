# corpus: task=four_bar_mechanism_point_masses seed=1 expect=pass
# style: main() under if __name__ == "__main__", numpy vectors, geometry helper, position sensor and prints
import numpy as np
import exudyn as exu
from exudyn.utilities import *


def CirclesIntersection(pB, pD, b, c):
    """point C at distance b from B and c from D, left of the direction B->D"""
    e = pD - pB
    f = np.linalg.norm(e)
    s = (b**2 - c**2 + f**2) / (2 * f)
    h = np.sqrt(b**2 - s**2)
    return pB + s / f * e + h / f * np.array([-e[1], e[0], 0.])


def main():
    print("Exudyn version", exu.__version__)
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()

    a, b, c, d = 0.106, 0.407, 0.309, 0.421
    mB, mC = 0.669, 1.52
    g = np.array([0., -9.815, 0.])
    theta0 = np.radians(32.8)

    pA = np.zeros(3)
    pD = np.array([d, 0., 0.])
    pB = a * np.array([np.cos(theta0), np.sin(theta0), 0.])
    pC = CirclesIntersection(pB, pD, b, c)
    print("B =", pB, "C =", pC)

    ground = mbs.CreateGround(referencePosition=list(pA))
    massB = mbs.CreateMassPoint(referencePosition=pB, initialVelocity=[0, 0, 0], mass=mB, gravity=g)
    massC = mbs.CreateMassPoint(referencePosition=pC, initialVelocity=[0, 0, 0], mass=mC, gravity=g)

    mbs.CreateDistanceConstraint(itemNumbers=[ground, massB], localPosition0=pA, localPosition1=[0, 0, 0], distance=a)
    mbs.CreateDistanceConstraint(itemNumbers=[massB, massC], distance=b)
    mbs.CreateDistanceConstraint(itemNumbers=[ground, massC], localPosition0=pD, distance=c)
    for body in [massB, massC]:
        mbs.CreateCoordinateConstraint(itemNumbers=[None, body], coordinates=[None, 2])

    sensC = mbs.AddSensor(SensorBody(bodyNumber=massC, storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.Position))
    mbs.Assemble()

    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = 2.0
    settings.timeIntegration.numberOfSteps = 2000
    mbs.SolveDynamic(settings)

    data = mbs.GetSensorStoredData(sensC)
    print("final position of C:", data[-1, 1:])
    print("constraint check |C-D| =", np.linalg.norm(data[-1, 1:4] - pD))


if __name__ == "__main__":
    main()
