"""Task 23 (level 1): flying rigid body — a free cuboid with initial velocity and spin under gravity.

The cuboid's side lengths are ordered a > b > c, so its local z-axis is the axis of largest
inertia; the initial angular velocity is dominated by its z-component (stable spin about the major
axis with a wobble), far from the sensitive intermediate-axis regime.

Physics checks: the centre of mass follows the projectile formula p(t) = v0*t + g*t^2/2; the
angular momentum vector R*J*R^T*omega and the rotational kinetic energy are conserved.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=23,
    name="flying rigid body",
    level="1",
    description="""
        A single free rigid body flying under gravity. The body is a homogeneous cuboid with
        density rho = {density} kg/m^3 and side lengths [a, b, c] = [{size_x}, {size_y}, {size_z}] m
        along its local x-, y- and z-axes; its inertia is computed with
        InertiaCuboid(density=rho, sideLengths=[a, b, c]), so the body's reference point is its
        center of mass. The body's reference position is [0, 0, 0] and its reference rotation is
        the identity (local axes aligned with the global axes). It starts with the initial velocity
        v0 = [{vel_x}, 0, {vel_z}] m/s and the initial angular velocity
        omega0 = [{omega_x}, {omega_y}, {omega_z}] rad/s, both given in global coordinates. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. There are no joints, no other bodies,
        no ground object and no other loads; no air resistance.
    """,
    open_description="""
        A single free rigid body flying under gravity: a homogeneous brick (rectangular cuboid) of
        density {density} kg/m^3 with edge lengths a = {size_x} m, b = {size_y} m and c = {size_z}
        m. At the start its centre is at the origin [0, 0, 0] and its edges of length a, b and c
        lie along the global x-, y- and z-axes respectively. It starts with the velocity of its
        centre v0 = [{vel_x}, 0, {vel_z}] m/s and the angular velocity omega0 = [{omega_x},
        {omega_y}, {omega_z}] rad/s, both given in global coordinates. Gravity g = {gravity} m/s^2
        acts in the negative z-direction. Nothing else acts on it: no supports, no other bodies,
        no air resistance.
    """,
    params=(
        Param("density", 500.0, 3000.0, "kg/m^3"),
        Param("size_x", 0.3, 0.6, "m"),
        Param("size_y", 0.1, 0.25, "m"),
        Param("size_z", 0.02, 0.08, "m"),
        Param("vel_x", 0.5, 3.0, "m/s"),
        Param("vel_z", 2.0, 8.0, "m/s"),
        Param("omega_x", -2.0, 2.0, "rad/s"),
        Param("omega_y", -2.0, 2.0, "rad/s"),
        Param("omega_z", 5.0, 15.0, "rad/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("RigidBody", "InertiaCuboid"),
    model_code="""
        oBody = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialVelocity=[vel_x, 0, vel_z],
                                    initialAngularVelocity=[omega_x, omega_y, omega_z],
                                    inertia=InertiaCuboid(density=density,
                                                          sideLengths=[size_x, size_y, size_z]),
                                    gravity=[0, 0, -gravity])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
