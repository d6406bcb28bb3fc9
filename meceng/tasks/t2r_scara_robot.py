"""Task 49 (level 2): 2R SCARA robot — two cuboid links on revolute joints with vertical axes, whose
joint angles follow a cosine trajectory through joint-space PD control torques.

The PD torques are torque loads with a load user function (Torque + LoadUserFunction): joint 1's
torque acts on link 1, joint 2's torque on link 2 and, as reaction, on link 1. The joint angles are
measured from the links' rotation angles about z; the ranges keep the absolute link angles within
+-160 degrees, so the Tait-Bryan z-angle never wraps. The torques depend on the state, so the
solver's load Jacobian is switched on (computeLoadsJacobian = 2); otherwise the modified Newton
iteration needs many iterations or fails for the stiffer gains. Gravity acts along the joint axes
and only loads the joints. A PD-controlled arm is not chaotic; 2 s cover the motion and the
settling after it.

Physics checks: the measured joint angles satisfy the Lagrange equations of the planar 2R arm,
M(q)*q'' + h(q, q') = tau with the PD torques (inertias recomputed from the parameters); the arm
settles at the end angles.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=49,
    name="2R SCARA robot",
    level="2",
    description="""
        A 2R SCARA robot arm moving in the horizontal x-y plane, consisting of two links modeled as
        homogeneous cuboid rigid bodies with density rho = {density} kg/m^3 and inertias computed
        with InertiaCuboid (reference point = center of mass): link 1 with side lengths
        [L1, 0.04, 0.04] m and link 2 with side lengths [L2, 0.04, 0.04] m, L1 = {length1} m,
        L2 = {length2} m, the local x-axis along the link. Joint 1 is a revolute joint between
        ground and link 1 at [0, 0, 0], joint 2 a revolute joint between link 1 and link 2 at the
        end of link 1; both have the axis [0, 0, 1]. The joint angle q1 is the angle of link 1
        measured counter-clockwise from the positive x-axis, q2 the angle of link 2 relative to
        link 1. The arm starts from rest at q1s = {q1_start_deg} degrees and q2s = {q2_start_deg}
        degrees (converted to radians): link 1's reference position is
        (L1/2)*[cos(q1s), sin(q1s), 0] with reference rotation matrix RotationMatrixZ(q1s); joint 2 is
        at P = L1*[cos(q1s), sin(q1s), 0]; link 2's reference position is
        P + (L2/2)*[cos(q1s + q2s), sin(q1s + q2s), 0] with RotationMatrixZ(q1s + q2s). Each joint
        angle follows the cosine trajectory q_i,d(t) = q_is + (q_ie - q_is)*(1 - cos(pi*t/T))/2 with
        the velocity q_i,d'(t) = (q_ie - q_is)*pi/(2*T)*sin(pi*t/T) for t < T, and q_i,d = q_ie,
        q_i,d' = 0 for t >= T, with the end angles q1e = {q1_end_deg} degrees,
        q2e = {q2_end_deg} degrees and the motion time T = {duration} s. The joints are driven by PD
        control torques tau_i = kP*(q_i,d - q_i) + kD*(q_i,d' - q_i') with kP = {kp} N*m/rad and
        kD = {kd} N*m*s/rad, where the measured angles are q1 = phi1, q2 = phi2 - phi1 and
        q1' = omega1, q2' = omega2 - omega1, with phi_k the rotation angle of link k about the global
        z-axis, mbs.GetObjectOutputBody(oLink_k, exu.OutputVariableType.Rotation)[2], and omega_k its
        angular velocity about z, mbs.GetObjectOutputBody(oLink_k,
        exu.OutputVariableType.AngularVelocity)[2]. The torques are applied as two torque loads with
        loadVector [0, 0, 0] and a loadVectorUserFunction: on link 1 the torque [0, 0, tau1 - tau2]
        (drive of joint 1 minus the reaction of joint 2) and on link 2 the torque [0, 0, tau2].
        Gravity g = 9.81 m/s^2 acts in the negative z-direction on both links. No friction. Create
        the ground, link 1, link 2, joint 1, joint 2, then the torque on link 1 and the torque on
        link 2.
    """,
    open_description="""
        A two-link SCARA robot arm moves in the horizontal x-y plane. Both links are homogeneous
        straight bars of density {density} kg/m^3 with a square cross-section of 0.04 m by 0.04 m;
        link 1 has the length L1 = {length1} m, link 2 the length L2 = {length2} m, and their centre
        lines lie in the plane z = 0. Joint 1, a frictionless hinge with the vertical axis
        [0, 0, 1], connects one end of link 1 to the fixed world at [0, 0, 0]; joint 2, also a
        frictionless hinge with a vertical axis, connects the other end of link 1 to one end of link
        2. The joint angle q1 is the angle of link 1 measured counter-clockwise (about the positive
        z-axis) from the positive x-axis, q2 the angle of link 2 relative to link 1, also
        counter-clockwise. The arm starts at rest with q1 = q1s = {q1_start_deg} degrees and
        q2 = q2s = {q2_start_deg} degrees: joint 2 is at L1*[cos(q1s), sin(q1s), 0] and link 2
        points from there along [cos(q1s + q2s), sin(q1s + q2s), 0]. Gravity g = 9.81 m/s^2 acts in
        the negative z-direction, along the joint axes. Each joint angle is to follow the cosine
        trajectory q_i,d(t) = q_is + (q_ie - q_is)*(1 - cos(pi*t/T))/2 with the rate
        q_i,d'(t) = (q_ie - q_is)*pi/(2*T)*sin(pi*t/T) for t < T, and q_i,d = q_ie, q_i,d' = 0 for t
        >= T, with the end angles q1e = {q1_end_deg} degrees and q2e = {q2_end_deg} degrees and the
        motion time T = {duration} s. Motors in the joints apply the PD control torques
        tau_i = k_P*(q_i,d - q_i) + k_D*(q_i,d' - q_i') (angles in radians) with k_P = {kp} N*m/rad
        and k_D = {kd} N*m*s/rad, where q_i and q_i' are the actual joint angles and rates: tau1
        acts on link 1 about the positive z-axis (its reaction goes into the fixed world), tau2 acts
        on link 2 about the positive z-axis and, as reaction, -tau2 on link 1. There is no other
        load and no friction.
    """,
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("length1", 0.3, 0.5, "m"),
        Param("length2", 0.2, 0.4, "m"),
        Param("q1_start_deg", -60.0, 60.0, "deg", digits=2),
        Param("q1_end_deg", -60.0, 60.0, "deg", digits=2),
        Param("q2_start_deg", -90.0, 90.0, "deg", digits=2),
        Param("q2_end_deg", -90.0, 90.0, "deg", digits=2),
        Param("duration", 0.8, 1.5, "s", digits=2),
        Param("kp", 200.0, 1000.0, "N*m/rad"),
        Param("kd", 10.0, 50.0, "N*m*s/rad"),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "RevoluteJoint", "Torque", "LoadUserFunction"),
    model_code="""
        q1s, q2s = q1_start_deg * np.pi / 180, q2_start_deg * np.pi / 180
        q1e, q2e = q1_end_deg * np.pi / 180, q2_end_deg * np.pi / 180
        pJoint2 = length1 * np.array([np.cos(q1s), np.sin(q1s), 0])

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink1 = mbs.CreateRigidBody(referencePosition=0.5 * pJoint2,
                                     referenceRotationMatrix=RotationMatrixZ(q1s),
                                     inertia=InertiaCuboid(density=density, sideLengths=[length1, 0.04, 0.04]),
                                     gravity=[0, 0, -9.81])
        oLink2 = mbs.CreateRigidBody(referencePosition=pJoint2 + 0.5 * length2 * np.array([np.cos(q1s + q2s),
                                                                                       np.sin(q1s + q2s), 0]),
                                     referenceRotationMatrix=RotationMatrixZ(q1s + q2s),
                                     inertia=InertiaCuboid(density=density, sideLengths=[length2, 0.04, 0.04]),
                                     gravity=[0, 0, -9.81])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink1], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oLink1, oLink2], position=pJoint2, axis=[0, 0, 1])

        def Trajectory(t, qs, qe):
            if t < duration:
                return (qs + (qe - qs) * (1 - np.cos(np.pi * t / duration)) / 2,
                        (qe - qs) * np.pi / (2 * duration) * np.sin(np.pi * t / duration))
            return qe, 0.0

        def JointTorques(t):
            phi1 = mbs.GetObjectOutputBody(oLink1, exu.OutputVariableType.Rotation)[2]
            phi2 = mbs.GetObjectOutputBody(oLink2, exu.OutputVariableType.Rotation)[2]
            omega1 = mbs.GetObjectOutputBody(oLink1, exu.OutputVariableType.AngularVelocity)[2]
            omega2 = mbs.GetObjectOutputBody(oLink2, exu.OutputVariableType.AngularVelocity)[2]
            q1d, v1d = Trajectory(t, q1s, q1e)
            q2d, v2d = Trajectory(t, q2s, q2e)
            tau1 = kp * (q1d - phi1) + kd * (v1d - omega1)
            tau2 = kp * (q2d - (phi2 - phi1)) + kd * (v2d - (omega2 - omega1))
            return tau1, tau2

        def UFtorque1(mbs, t, loadVector):
            tau1, tau2 = JointTorques(t)
            return [0, 0, tau1 - tau2]

        def UFtorque2(mbs, t, loadVector):
            tau1, tau2 = JointTorques(t)
            return [0, 0, tau2]

        mbs.CreateTorque(itemNumber=oLink1, loadVector=[0, 0, 0], loadVectorUserFunction=UFtorque1)
        mbs.CreateTorque(itemNumber=oLink2, loadVector=[0, 0, 0], loadVectorUserFunction=UFtorque2)
    """,
    sim=SimSettings(
        end_time=2.0,
        steps=2000,
        extra=("simulationSettings.timeIntegration.computeLoadsJacobian = 2",),
    ),
)
