# corpus: task=newtons_cradle seed=0 expect=pass
# style: legacy AddNode/AddObject/AddMarker API, parameters in a dict, for-loops over the spheres
import exudyn as exu
from exudyn.itemInterface import *
import numpy as np

SC = exu.SystemContainer()
mbs = SC.AddSystem()

p = {"m": 0.344, "r": 0.0213, "L": 0.208, "g": 9.822, "k": 33000.0, "e": 0.77, "nSpheres": 4}
spacing = 2 * p["r"] + 0.002

oGround = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))

bodies = []
for i in range(p["nSpheres"]):
    if i == 0:
        pos = [-p["L"], 0, p["L"]]  # first sphere lifted to the horizontal
    else:
        pos = [i * spacing, 0, 0]
    n = mbs.AddNode(NodePoint(referenceCoordinates=pos))
    b = mbs.AddObject(MassPoint(physicsMass=p["m"], nodeNumber=n))
    mMass = mbs.AddMarker(MarkerBodyMass(bodyNumber=b))
    mbs.AddLoad(LoadMassProportional(markerNumber=mMass, loadVector=[0, 0, -p["g"]]))
    bodies.append(b)

# pendulum strings
for i, b in enumerate(bodies):
    mTop = mbs.AddMarker(MarkerBodyPosition(bodyNumber=oGround, localPosition=[i * spacing, 0, p["L"]]))
    mSphere = mbs.AddMarker(MarkerBodyPosition(bodyNumber=b, localPosition=[0, 0, 0]))
    mbs.AddObject(DistanceConstraint(markerNumbers=[mTop, mSphere], distance=p["L"]))

# contacts between neighbours
for i in range(p["nSpheres"] - 1):
    m0 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodies[i], localPosition=[0, 0, 0]))
    m1 = mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodies[i + 1], localPosition=[0, 0, 0]))
    nData = mbs.AddNode(NodeGenericData(initialCoordinates=[0, 0, 0, 0], numberOfDataCoordinates=4))
    mbs.AddObject(ObjectContactSphereSphere(markerNumbers=[m0, m1], nodeNumber=nData,
                                            spheresRadii=[p["r"], p["r"]],
                                            contactStiffness=p["k"], contactDamping=0.0,
                                            impactModel=2, restitutionCoefficient=p["e"]))

mbs.Assemble()

simulationSettings = exu.SimulationSettings()
simulationSettings.timeIntegration.endTime = 0.6
simulationSettings.timeIntegration.numberOfSteps = 6000
simulationSettings.timeIntegration.discontinuous.iterationTolerance = 1e-3
simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False
mbs.SolveDynamic(simulationSettings)
print("simulation finished")
