"""Level 1-2 components: loads, contacts, sensors and joint control."""

from __future__ import annotations

from meceng.catalog.common import rigid_example
from meceng.catalog.component import Component, text_block

FORCE = Component(
    name="Force",
    description=(
        "constant force vector applied to a mass point or a rigid body (optionally at a point of the body); "
        "for applied external loads, not for gravity"
    ),
    context=text_block("""
        mbs.CreateForce(itemNumber=oBody, loadVector=[Fx, Fy, Fz], localPosition=[0, 0, 0], bodyFixed=False)
        - itemNumber (singular) is the body (mass point or rigid body); returns a LoadIndex.
        - loadVector [N] in GLOBAL coordinates; bodyFixed=True: in body-local coordinates, rotating with the
          body (follower force).
        - localPosition: point of application in body-local coordinates (rigid bodies; off the center of mass
          it also creates a moment); keep [0, 0, 0] for mass points.
        - Gravity is NOT a force load: give it with gravity= of CreateMassPoint/CreateRigidBody.
        - On a flexible part the force acts at an interface marker: see InterfaceLoad.
        - A time-dependent force uses loadVectorUserFunction, see LoadUserFunction.
    """),
    example=rigid_example("""
        # a mass point on a spring to ground, pulled by a constant force of 20 N in x-direction
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], mass=1.0)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=1000.0, damping=5.0)
        mbs.CreateForce(itemNumber=oMass, loadVector=[20.0, 0, 0])
    """),
)

TORQUE = Component(
    name="Torque",
    description=(
        "constant torque (moment) vector applied to a rigid body; for drive torques of cranks, rotors, "
        "motors and external moments"
    ),
    context=text_block("""
        mbs.CreateTorque(itemNumber=oBody, loadVector=[Tx, Ty, Tz], bodyFixed=False)
        - loadVector: torque [N*m] in GLOBAL coordinates (bodyFixed=True: body-local, rotating with the body);
          e.g. a drive about the global z-axis: [0, 0, T].
        - Rigid bodies (a mass point has no rotation); itemNumber (singular) is the body. On a flexible part the
          torque acts at an interface marker: see InterfaceLoad.
        - A time-dependent torque uses loadVectorUserFunction, see LoadUserFunction.
    """),
    example=rigid_example("""
        # a disc on a revolute joint about global z, driven from rest by a constant torque of 0.5 N*m
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    inertia=InertiaCylinder(density=7850, length=0.02,
                                                            outerRadius=0.1, axis=2))
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorque(itemNumber=oDisc, loadVector=[0, 0, 0.5])
    """),
    dependencies=("RigidBody",),
)

LOAD_USER_FUNCTION = Component(
    name="LoadUserFunction",
    description=(
        "time-dependent force or torque given by a Python function of time (harmonic excitation, ramps, "
        "pulses, switched loads)"
    ),
    context=text_block("""
        def UFforce(mbs, t, loadVector):
            return [F0 * np.sin(omega * t), 0, 0]
        mbs.CreateForce(itemNumber=oMass, loadVector=[F0, 0, 0], loadVectorUserFunction=UFforce)
        - Signature (mbs, t, loadVector) -> list of 3 floats: t is the simulation time [s]; loadVector is the
          constant loadVector given to CreateForce (a list); the returned vector replaces it in every step.
        - The same works for mbs.CreateTorque(itemNumber=oBody, loadVector=..., loadVectorUserFunction=UFtorque).
        - Define the function before the Create call; use np.sin, np.cos, if/else on t; return a plain list.
        - Do not print or write files inside the function: it is called many times per time step.
    """),
    example=rigid_example("""
        # a mass-spring oscillator excited by the harmonic force F0*sin(omega*t) in x-direction
        F0 = 10.0
        omega = 2 * np.pi * 3.0

        def UFforce(mbs, t, loadVector):
            return [F0 * np.sin(omega * t), 0, 0]

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], mass=1.0)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=400.0, damping=2.0)
        mbs.CreateForce(itemNumber=oMass, loadVector=[F0, 0, 0], loadVectorUserFunction=UFforce)
    """),
    dependencies=("Force",),
)

SPHERE_SPHERE_CONTACT = Component(
    name="SphereSphereContact",
    description=(
        "penalty contact (impact) between two spheres attached to mass points or rigid bodies, with contact "
        "stiffness, damping and restitution coefficient; for colliding balls, Newton's cradle"
    ),
    context=text_block("""
        mbs.CreateSphereSphereContact(itemNumbers=[oBall0, oBall1], spheresRadii=[r0, r1], contactStiffness=k,
                                      contactDamping=0, impactModel=2, restitutionCoefficient=e)
        - The sphere centers are the items' reference points (mass point or rigid body center); spheresRadii [m],
          contactStiffness [N/m], contactDamping [N*s/m]. localPosition0/localPosition1 shift a sphere center
          in the item's frame, e.g. a ground sphere centered below the floor: itemNumbers=[oGround, oBall],
          localPosition0=[0, 0, -R].
        - restitutionCoefficient is only used with impactModel=2 (or 1); with the default impactModel=0 it is
          ignored and only the linear contactDamping acts. For a given e use impactModel=2 and
          contactDamping=0.
        - impactModel=2 (Gonthier / Carvalho-Martins) sets its hysteresis damping so that an isolated impact
          restitutes exactly e at any impact speed: the normal relative velocity after it is -e times the one
          before (to 1e-4 for e = 0.6-0.95, 0.5-3 m/s).
        - One contact object per pair of spheres that can touch (e.g. neighbours 0-1, 1-2, 2-3).
        - dynamicFriction > 0 needs rigid bodies; without friction mass points are enough.
        - Contact needs small time steps (about 1e-4 s). Where the solver stops at an impact, set both
          simulationSettings.timeIntegration.discontinuous.iterationTolerance = 1e-3 and
          simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False: the
          tolerance alone can stop it at the first impact of a ball on a floor triangle.
    """),
    example=rigid_example(
        """
        # two balls (mass points) colliding head-on along x, restitution coefficient 0.8
        r = 0.05
        oBall0 = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[1.0, 0, 0], mass=0.2)
        oBall1 = mbs.CreateMassPoint(referencePosition=[0.15, 0, 0], mass=0.2)
        mbs.CreateSphereSphereContact(itemNumbers=[oBall0, oBall1], spheresRadii=[r, r],
                                      contactStiffness=1e5, contactDamping=0,
                                      impactModel=2, restitutionCoefficient=0.8)
        """,
        end_time=0.2,
        steps=2000,
    ),
)

SPHERE_TRIANGLE_CONTACT = Component(
    name="SphereTriangleContact",
    description=(
        "penalty contact between a rigid sphere and a triangle fixed to ground or to a body, with stiffness, "
        "damping and restitution; for a ball bouncing or rolling on a flat (triangular) surface"
    ),
    context=text_block("""
        mbs.CreateSphereTriangleContact(itemNumbers=[oBall, oGround], sphereRadius=r,
                                        trianglePoints=exu.Vector3DList([[0, 0, 0], [1, 0, 0], [0, 1, 0]]),
                                        contactStiffness=k, contactDamping=0, impactModel=2,
                                        restitutionCoefficient=e)
        - itemNumbers[0] is the sphere and must be a RIGID BODY (e.g. with InertiaSphere); a mass point fails
          in mbs.Assemble(). itemNumbers[1] carries the triangle (usually the ground object).
        - trianglePoints: exactly 3 points in the LOCAL coordinates of itemNumbers[1], wrapped in
          exu.Vector3DList([...]); a plain list or numpy array is rejected with a type error.
        - Make the triangle large enough to cover where the sphere touches; includeEdges=7 (default) also
          gives contact with the three edges.
        - restitutionCoefficient needs impactModel=2 (with contactDamping=0): an isolated impact restitutes e
          (without other forces), as in SphereSphereContact; dynamicFriction [-] is optional.
        - Use small time steps (about 1e-4 s) for impacts.
    """),
    example=rigid_example(
        """
        # a ball dropped from 0.2 m onto a triangle in the floor plane z = 0, restitution 0.7
        r = 0.05
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBall = mbs.CreateRigidBody(referencePosition=[0.2, 0.2, 0.2],
                                    inertia=InertiaSphere(mass=0.5, radius=r),
                                    gravity=[0, 0, -9.81])
        mbs.CreateSphereTriangleContact(itemNumbers=[oBall, oGround], sphereRadius=r,
                                        trianglePoints=exu.Vector3DList([[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]),
                                        contactStiffness=1e5, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=0.7)
        """,
        end_time=0.5,
        steps=5000,
    ),
    dependencies=("Ground", "RigidBody"),
)

SENSOR = Component(
    name="Sensor",
    description=(
        "records a body or node quantity (position, displacement, velocity, rotation, angular velocity, ...) "
        "or a connector force over time in memory; when a result has to be measured or evaluated"
    ),
    context=text_block("""
        sPos = mbs.AddSensor(SensorBody(bodyNumber=oBody, localPosition=[0, 0, 0], storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Position))
        sVel = mbs.AddSensor(SensorNode(nodeNumber=nMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Velocity))
        - Add sensors before mbs.Assemble(); after mbs.SolveDynamic(...) read them with
          data = mbs.GetSensorStoredData(sPos): a numpy array with columns [t, x, y, z], one row every
          simulationSettings.solution.sensors.writePeriod (default 0.01 s).
        - Always storeInternal=True and no fileName: the program must not write files (no sensor files, no
          plots, no prints needed).
        - OutputVariableType for bodies and nodes: Position, Displacement, Velocity, Acceleration; rigid bodies
          also Rotation, RotationMatrix, AngularVelocity. SensorBody measures at localPosition (body-local).
        - Connector or joint forces: SensorObject(objectNumber=oJoint, storeInternal=True,
          outputVariableType=exu.OutputVariableType.Force).
    """),
    example=rigid_example("""
        # a mass point pendulum with sensors for the position, the node velocity and the rod force
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[0.5, 0, 0], mass=1.0, gravity=[0, -9.81, 0])
        oRod = mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass])
        nMass = mbs.GetObject(oMass)['nodeNumber']
        sPos = mbs.AddSensor(SensorBody(bodyNumber=oMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Position))
        sVel = mbs.AddSensor(SensorNode(nodeNumber=nMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Velocity))
        sForce = mbs.AddSensor(SensorObject(objectNumber=oRod, storeInternal=True,
                                            outputVariableType=exu.OutputVariableType.Force))
    """),
)


JOINT_PD_CONTROL = Component(
    name="JointPDControl",
    description=(
        "PD-controlled joint drive that makes the angle of a revolute joint follow a prescribed trajectory "
        "q_d(t) (torsional spring-damper with a torque user function); for robot joints, servo drives, "
        "prescribed joint motion"
    ),
    context=text_block("""
        def UFjoint(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
            qd, vd = JointTrajectory(t)        # desired joint angle [rad] and rate [rad/s] at time t
            return stiffness * (rotation - qd) + damping * (angularVelocity - vd)
        mbs.CreateRevoluteJoint(itemNumbers=[oParent, oChild], position=p, axis=a)
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oParent, oChild], position=p, axis=a,
                                        stiffness=kP, damping=kD, springTorqueUserFunction=UFjoint)
        - The torsional spring-damper measures the joint angle itself: rotation [rad] is the rotation of
          itemNumbers[1] relative to itemNumbers[0] about the GLOBAL axis a (right-hand rule), zero in the reference
          configuration and counted over several turns; angularVelocity [rad/s] is its rate.
        - The returned value replaces the connector torque k*(rotation - offset) + d*angularVelocity, which like
          any spring's resists the rotation: itemNumbers[1] receives minus the returned value (itemNumbers[0] the
          reaction, plus it). The function above returns kP*(q - qd) + kD*(q' - vd), q = rotation, with the
          gains passed as stiffness and damping, so that itemNumbers[1] is driven by tau = kP*(qd - q) + kD*(vd - q'),
          the PD control torque that pulls q towards qd.
        - The joint angle is measured from the reference configuration: build the bodies in the start pose and
          give qd relative to it (subtract the start angle if the trajectory is given in absolute angles).
        - Signature exactly (mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset) -> float;
          one revolute joint + one torsional spring-damper (same items, position and axis) per driven joint, each
          with its own function (e.g. created by a factory function with the joint's trajectory data).
        - The connector enters the solver's Jacobian, so also stiff gains converge without special solver settings.
    """),
    example=rigid_example("""
        # a link (long side along local x) on a revolute joint about global z, moved from 0 to 60 degrees by
        # a cosine trajectory in 0.8 s and then held; gravity in -z is carried by the joint
        qEnd = 60 * np.pi / 180
        duration = 0.8

        def JointTrajectory(t):
            if t < duration:
                return (qEnd * (1 - np.cos(np.pi * t / duration)) / 2,
                        qEnd * np.pi / (2 * duration) * np.sin(np.pi * t / duration))
            return qEnd, 0.0

        def UFjoint(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
            qd, vd = JointTrajectory(t)
            return stiffness * (rotation - qd) + damping * (angularVelocity - vd)

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink = mbs.CreateRigidBody(referencePosition=[0.25, 0, 0],
                                    inertia=InertiaCuboid(density=2700, sideLengths=[0.5, 0.05, 0.05]),
                                    gravity=[0, 0, -9.81])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1],
                                        stiffness=200.0, damping=10.0, springTorqueUserFunction=UFjoint)
    """),
    dependencies=("RevoluteJoint", "TorsionalSpringDamper"),
)
