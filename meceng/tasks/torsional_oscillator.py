"""Task 15 (level 1): torsional oscillator — a disc on a revolute joint with a torsional spring-damper.

The disc (a short solid cylinder, axis along global z) turns about the global z-axis on a revolute
joint; a torsional spring-damper to ground about the same axis and a constant torque act on it, and
it starts with an initial spin. Gravity is neglected. A linear one-degree-of-freedom oscillator:
smooth and insensitive to the order of items. The ranges keep the natural frequency between about
10 and 120 rad/s, so 1 ms steps resolve it and 2 s show several periods.

Physics check: the rotation angle is the closed-form solution of J*phi'' + d*phi' + k*phi = T with
phi(0) = 0, phi'(0) = omega0 and J = m*r^2/2; the centre of mass stays at the origin.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=15,
    name="torsional oscillator",
    level="1",
    description="""
        A torsional oscillator consisting of a disc on a frictionless revolute joint with a
        torsional spring-damper. The disc is a homogeneous solid cylinder with mass m = {mass} kg,
        radius r = {radius} m and width (thickness along its axis) w = {width} m; its inertia is
        computed with InertiaCylinder(density=m/(pi*r^2*w), length=w, outerRadius=r, axis=2), so
        the disc axis is its local z-axis and the body's reference point is its center of mass. The
        disc's reference position is [0, 0, 0] and its reference rotation is the identity, so its
        axis is the global z-axis. A revolute joint between ground and disc is located at [0, 0, 0]
        with the rotation axis [0, 0, 1]. A torsional spring-damper between ground and disc at
        [0, 0, 0] about the axis [0, 0, 1] has the torsional stiffness k = {stiffness} N*m/rad and
        the torsional damping d = {damping} N*m*s/rad; it is relaxed in the reference configuration
        (offset 0). The disc starts with the initial angular velocity [0, 0, {omega0}] rad/s (zero
        initial translational velocity) and a constant torque [0, 0, {torque}] N*m acts on the disc.
        Gravity is neglected. Create the ground, the disc, the revolute joint, the torsional
        spring-damper and then the torque.
    """,
    open_description="""
        A torsional oscillator: a disc turning on a frictionless hinge against a torsional spring.
        The disc is a homogeneous solid cylinder of mass m = {mass} kg, radius r = {radius} m and
        thickness w = {width} m. Its centre is at the origin [0, 0, 0] and its axis of symmetry
        lies along the global z-axis, which is also the hinge axis: the centre stays fixed and the
        disc can only turn about the z-axis. A linear torsional spring-damper between the fixed
        world and the disc acts about the z-axis with stiffness k = {stiffness} N*m/rad and
        damping coefficient d = {damping} N*m*s/rad; it is relaxed at the starting angle. A
        constant torque of {torque} N*m about the positive z-axis acts on the disc. Gravity is
        neglected. At the start the disc is at the relaxed angle and turns with the angular
        velocity {omega0} rad/s about the positive z-axis (angular velocity vector [0, 0,
        {omega0}] rad/s).
    """,
    params=(
        Param("mass", 5.0, 20.0, "kg"),
        Param("radius", 0.15, 0.3, "m"),
        Param("width", 0.02, 0.06, "m"),
        Param("stiffness", 100.0, 800.0, "N*m/rad"),
        Param("damping", 0.0, 2.0, "N*m*s/rad"),
        Param("omega0", 2.0, 15.0, "rad/s"),
        Param("torque", 0.5, 20.0, "N*m"),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "RevoluteJoint", "TorsionalSpringDamper", "Torque"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialAngularVelocity=[0, 0, omega0],
                                    inertia=InertiaCylinder(density=mass / (np.pi * radius**2 * width),
                                                            length=width, outerRadius=radius, axis=2))
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1],
                                        stiffness=stiffness, damping=damping)
        mbs.CreateTorque(itemNumber=oDisc, loadVector=[0, 0, torque])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
