"""Task 50 (level 2): RRR articulated robot with 3D cubic trajectory — a vertical column (base yaw),
an upper arm (shoulder) and a forearm (elbow) as cuboid rigid bodies on revolute joints; every joint
angle follows a cubic polynomial from the start to the end angle through PD control.

Each joint drive is a torsional spring-damper at the revolute joint whose torque is replaced by a
user function, kP*(rotation - q_d(t)) + kD*(angularVelocity - q_d'(t)) (component JointPDControl):
the connector measures the relative joint rotation itself and applies the torque with its reaction,
and the solver's connector Jacobian includes the drive, so the PD gains converge fast. The start
pose (all joint angles zero, arm stretched horizontally) is the reference configuration. The PD
control has no gravity compensation; the gains keep the static sag below about 0.1 rad. Base yaw
within +-90 degrees, shoulder raised 10-60 degrees, elbow -90-0 degrees: no singular pose is
reached. A PD-controlled arm is not chaotic; 2 s cover the motion and part of the settling.

Physics checks: the rate of kinetic + potential energy equals the power of the three joint torques
(work balance with the PD torques recomputed from the measured joint angles); the arm settles near
the end pose with the static PD sag predicted from the gravity torques of the links.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=50,
    name="RRR articulated robot with 3D cubic trajectory",
    level="2",
    description="""
        An RRR articulated robot arm with three links modeled as homogeneous cuboid rigid bodies with
        density rho = {density} kg/m^3, a square cross-section of side 0.05 m and inertias computed
        with InertiaCuboid (reference point = center of mass). The start pose is the reference
        configuration (all joint angles zero, identity rotations): link 1 is a vertical column with
        side lengths [0.05, 0.05, L1], L1 = {length1} m, reference position [0, 0, L1/2]; link 2 (upper
        arm) has side lengths [L2, 0.05, 0.05], L2 = {length2} m, reference position [L2/2, 0, L1];
        link 3 (forearm) has side lengths [L3, 0.05, 0.05], L3 = {length3} m, reference position
        [L2 + L3/2, 0, L1]. Joints (positions and axes global, in the reference configuration): joint 1
        (base) is a revolute joint between ground and link 1 at [0, 0, 0] with axis [0, 0, 1]; joint 2
        (shoulder) a revolute joint between link 1 and link 2 at [0, 0, L1] with axis [0, -1, 0];
        joint 3 (elbow) a revolute joint between link 2 and link 3 at [L2, 0, L1] with axis
        [0, -1, 0] (a positive angle raises the arm). Each joint angle q_i follows a cubic
        trajectory from 0 to its end angle: q_i,d(t) = q_ie*(3*s^2 - 2*s^3) and
        q_i,d'(t) = q_ie*6*(s - s^2)/T with s = t/T for t < T, and q_i,d = q_ie, q_i,d' = 0 for
        t >= T, with q1e = {q1_end_deg} degrees, q2e = {q2_end_deg} degrees, q3e = {q3_end_deg}
        degrees (converted to radians) and the motion time T = {duration} s. Each joint is driven by
        PD control through a torsional spring-damper between the same two items, in the same order
        (the item named first, e.g. the ground for joint 1, is itemNumbers[0]), at the same position
        and axis as its revolute joint, with stiffness kP = {kp} N*m/rad and damping
        kD = {kd} N*m*s/rad, whose springTorqueUserFunction returns
        kP*(rotation - q_i,d(t)) + kD*(angularVelocity - q_i,d'(t)), rotation and angularVelocity
        being the joint angle and rate measured by the connector. Gravity g = 9.81 m/s^2 acts in the
        negative z-direction on all links; there is no gravity compensation. The arm starts from rest.
        Create the ground, links 1 to 3, the revolute joints 1 to 3, then the torsional
        spring-dampers of joints 1 to 3.
    """,
    open_description="""
        An articulated robot arm with three revolute joints (RRR). Its three links are homogeneous
        straight bars of density {density} kg/m^3 with a square cross-section of 0.05 m by 0.05 m.
        In the start pose (all joint angles zero) link 1, a vertical column of length L1 = {length1}
        m, stands from [0, 0, 0] to [0, 0, L1]; link 2 (upper arm), of length L2 = {length2} m,
        points horizontally from [0, 0, L1] to [L2, 0, L1]; link 3 (forearm), of length
        L3 = {length3} m, continues from [L2, 0, L1] to [L2 + L3, 0, L1]. The joints are
        frictionless hinges: joint 1 (base) connects link 1 to the fixed world at [0, 0, 0] with the
        vertical axis [0, 0, 1]; joint 2 (shoulder) connects link 1 and link 2 at [0, 0, L1], and
        joint 3 (elbow) connects link 2 and link 3 at [L2, 0, L1], both with the axis [0, -1, 0] in
        the start pose (these two axes turn with the column). The joint angle q1 is the rotation of
        link 1 relative to the ground about [0, 0, 1]; q2 is the rotation of link 2 relative to link
        1 and q3 that of link 3 relative to link 2, both about their joint axis [0, -1, 0], so that
        a positive angle raises the arm. Gravity g = 9.81 m/s^2 acts in the negative z-direction on
        all links. The arm starts at rest in the start pose. Each joint angle is to follow a cubic
        trajectory from 0 to its end angle q_ie: q_i,d(t) = q_ie*(3*s^2 - 2*s^3) with the rate
        q_i,d'(t) = q_ie*6*(s - s^2)/T, s = t/T, for t < T, and q_i,d = q_ie, q_i,d' = 0 for t >= T,
        with q1e = {q1_end_deg} degrees, q2e = {q2_end_deg} degrees, q3e = {q3_end_deg} degrees and
        the motion time T = {duration} s. A motor in each joint applies the PD control torque
        tau_i = k_P*(q_i,d - q_i) + k_D*(q_i,d' - q_i') (angles in radians) with k_P = {kp} N*m/rad
        and k_D = {kd} N*m*s/rad, q_i and q_i' being the actual joint angle and rate: tau_i acts
        about the joint axis, in the sense of a positive q_i, on the outer link and, as reaction,
        oppositely on the inner link (on the fixed world for joint 1). There is no gravity
        compensation and no other load.
    """,
    params=(
        Param("density", 2000.0, 3000.0, "kg/m^3"),
        Param("length1", 0.3, 0.5, "m"),
        Param("length2", 0.3, 0.5, "m"),
        Param("length3", 0.2, 0.4, "m"),
        Param("q1_end_deg", -90.0, 90.0, "deg", digits=2),
        Param("q2_end_deg", 10.0, 60.0, "deg", digits=2),
        Param("q3_end_deg", -90.0, 0.0, "deg", digits=2),
        Param("duration", 1.0, 1.5, "s", digits=2),
        Param("kp", 500.0, 2000.0, "N*m/rad"),
        Param("kd", 20.0, 80.0, "N*m*s/rad"),
    ),
    components=(
        "Ground",
        "RigidBody",
        "InertiaCuboid",
        "RevoluteJoint",
        "TorsionalSpringDamper",
        "JointPDControl",
    ),
    model_code="""
        w = 0.05
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink1 = mbs.CreateRigidBody(referencePosition=[0, 0, 0.5 * length1],
                                     referenceRotationMatrix=np.eye(3),
                                     inertia=InertiaCuboid(density=density, sideLengths=[w, w, length1]),
                                     gravity=[0, 0, -9.81])
        oLink2 = mbs.CreateRigidBody(referencePosition=[0.5 * length2, 0, length1],
                                     referenceRotationMatrix=np.eye(3),
                                     inertia=InertiaCuboid(density=density, sideLengths=[length2, w, w]),
                                     gravity=[0, 0, -9.81])
        oLink3 = mbs.CreateRigidBody(referencePosition=[length2 + 0.5 * length3, 0, length1],
                                     referenceRotationMatrix=np.eye(3),
                                     inertia=InertiaCuboid(density=density, sideLengths=[length3, w, w]),
                                     gravity=[0, 0, -9.81])

        joints = [([oGround, oLink1], [0, 0, 0], [0, 0, 1], q1_end_deg * np.pi / 180),
                  ([oLink1, oLink2], [0, 0, length1], [0, -1, 0], q2_end_deg * np.pi / 180),
                  ([oLink2, oLink3], [length2, 0, length1], [0, -1, 0], q3_end_deg * np.pi / 180)]
        for items, position, axis, qEnd in joints:
            mbs.CreateRevoluteJoint(itemNumbers=items, position=position, axis=axis)

        def CubicTrajectory(t, qEnd):
            if t < duration:
                s = t / duration
                return qEnd * (3 * s**2 - 2 * s**3), qEnd * 6 * (s - s**2) / duration
            return qEnd, 0.0

        def PDUserFunction(qEnd):
            def UFjoint(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
                qd, vd = CubicTrajectory(t, qEnd)
                return stiffness * (rotation - qd) + damping * (angularVelocity - vd)
            return UFjoint

        for items, position, axis, qEnd in joints:
            mbs.CreateTorsionalSpringDamper(itemNumbers=items, position=position, axis=axis,
                                            stiffness=kp, damping=kd,
                                            springTorqueUserFunction=PDUserFunction(qEnd))
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
