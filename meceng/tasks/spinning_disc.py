"""Task 8 (level 1): spinning disc — a disc on a revolute joint about its axis, driven by a torque.

The disc (a short solid cylinder with its axis along global z) is held at its centre by a revolute
joint about the global z-axis; it starts spinning with omega0 and is accelerated by a constant
torque about z. Gravity (negative y) only loads the joint. One degree of freedom, no contact: the
motion is smooth and insensitive to the order of items. The ranges keep the angular acceleration
T/J below 23 rad/s^2, so the spin stays below about 75 rad/s and 1 ms steps (at most 0.075 rad per
step) resolve it over the 2 s.

Physics check: the spin rate grows as omega(t) = omega0 + T*t/J with J = m*r^2/2, i.e. the rotation
angle is omega0*t + T*t^2/(2*J); the centre of mass stays at the origin.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=8,
    name="spinning disc",
    level="1",
    description="""
        A spinning disc mounted on a frictionless revolute joint. The disc is a homogeneous solid
        cylinder with mass m = {mass} kg, radius r = {radius} m and width (thickness along its axis)
        w = {width} m; its inertia is computed with
        InertiaCylinder(density=m/(pi*r^2*w), length=w, outerRadius=r, axis=2), so the disc axis is
        its local z-axis and the body's reference point is its center of mass. The disc's reference
        position is [0, 0, 0] and its reference rotation is the identity, so its axis is the global
        z-axis. A revolute joint between ground and disc is located at [0, 0, 0] with the rotation
        axis [0, 0, 1]. The disc starts with the initial angular velocity [0, 0, {omega0}] rad/s
        (zero initial translational velocity) and is driven by a constant torque
        [0, 0, {torque}] N*m applied to the disc. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction on the disc. Create the ground, the disc, the revolute joint and then the torque.
    """,
    open_description="""
        A spinning disc: a homogeneous solid cylinder (a disc) with mass m = {mass} kg, radius
        r = {radius} m and thickness w = {width} m along its axis. Its centre is at the origin
        [0, 0, 0] and its axis of symmetry is the global z-axis. It is held by a frictionless hinge
        at its centre that keeps the centre fixed and lets the disc turn only about the global
        z-axis. At the start the disc spins with the angular velocity {omega0} rad/s about the
        positive z-axis (angular velocity vector [0, 0, {omega0}] rad/s), its centre at rest. A
        constant torque of {torque} N*m about the positive z-axis drives the disc. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction (it only loads the hinge).
    """,
    params=(
        Param("mass", 2.0, 20.0, "kg"),
        Param("radius", 0.15, 0.4, "m"),
        Param("width", 0.01, 0.05, "m"),
        Param("omega0", 5.0, 30.0, "rad/s"),
        Param("torque", 0.05, 0.5, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "RevoluteJoint", "Torque"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialAngularVelocity=[0, 0, omega0],
                                    inertia=InertiaCylinder(density=mass / (np.pi * radius**2 * width),
                                                            length=width, outerRadius=radius, axis=2),
                                    gravity=[0, -gravity, 0])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorque(itemNumber=oDisc, loadVector=[0, 0, torque])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
