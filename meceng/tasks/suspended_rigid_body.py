"""Task 24 (level 1): suspended rigid body — a cuboid hung at its four upper corners on Cartesian
spring-dampers to ground (the paper's model uses Cartesian spring-dampers at the corners).

The body starts in the relaxed reference configuration with a horizontal velocity; gravity makes
it sag and the push excites the coupled sway/rocking motion in both horizontal directions. All four
mounts have the same stiffness (horizontal kh, vertical kv) and damping; the system is a damped,
nearly linear six-degree-of-freedom oscillator (small rotations), so the motion is regular and
insensitive to the order of items. The ranges keep the body mass at 12-384 kg and the highest
natural frequency below about 150 rad/s, resolved by the 1 ms steps.

Physics checks: with no lateral velocity the body only moves vertically, exactly as the damped
oscillator m*y'' + 4*d*y' + 4*kv*y = -m*g; without damping the total energy (kinetic + gravity +
spring energy of the four mounts) is conserved.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=24,
    name="suspended rigid body",
    level="1",
    description="""
        A rigid body suspended at its four upper corners by four Cartesian spring-dampers attached to
        ground. The body is a homogeneous cuboid (brick) with density rho = {density} kg/m^3 and side
        lengths [a, b, c] = [{size_x}, {size_y}, {size_z}] m along its local x-, y- and z-axes; its
        inertia is computed with InertiaCuboid(density=rho, sideLengths=[a, b, c]), so the body's
        reference point is its center of mass. The body's reference position is [0, 0, 0] and its
        reference rotation is the identity. Its four upper corners are the local points
        [sx*a/2, b/2, sz*c/2] for (sx, sz) = (-1, -1), (1, -1), (-1, 1), (1, 1), in this order. Each
        corner is connected to ground by a Cartesian spring-damper between the ground point at the
        same global position (the corner's position in the reference configuration) and the body at
        that local corner point, so the mounts are relaxed in the reference configuration (offset
        [0, 0, 0]). All four Cartesian spring-dampers have the stiffness
        [{stiffness_h}, {stiffness_v}, {stiffness_h}] N/m and the damping [d, d, d] with
        d = {damping} N*s/m in the global x-, y- and z-directions. The body starts from the reference
        configuration with the initial velocity [{vel_x}, 0, {vel_z}] m/s and zero angular
        velocity.
        Gravity g = {gravity} m/s^2 acts in the negative y-direction. Create the ground, the body and
        then the four spring-dampers in the order of the corners.
    """,
    open_description="""
        A rigid brick suspended at its four upper corners by four elastic mounts to the fixed
        world. The brick is a homogeneous rectangular cuboid of density {density} kg/m^3 with edge
        lengths a = {size_x} m, b = {size_y} m and c = {size_z} m; at the start its centre is at
        the origin [0, 0, 0] and its edges of length a, b and c lie along the global x-, y- and
        z-axes (y is vertical). Its four upper corners are the ones at y = b/2, i.e. at [sx*a/2,
        b/2, sz*c/2] with each of sx and sz either -1 or 1. Each of these corners is held by a
        linear spring-damper to a fixed point at the corner's starting position; it acts
        separately along the global x-, y- and z-directions: along each of these directions it
        pulls the corner back towards its fixed point with the stiffness of that direction times
        the corner's displacement from the fixed point along that direction, plus d times the
        corner's velocity along that direction. The stiffness is {stiffness_h} N/m in the
        horizontal x- and z-directions and {stiffness_v} N/m in the vertical y-direction, the
        damping coefficient is d = {damping} N*s/m in all three directions, and all four mounts
        are equal and relaxed at the start. The brick starts with the velocity of its centre
        [{vel_x}, 0, {vel_z}] m/s and without rotation. Gravity g = {gravity} m/s^2 acts in the
        negative y-direction.
    """,
    params=(
        Param("density", 500.0, 2000.0, "kg/m^3"),
        Param("size_x", 0.4, 0.8, "m"),
        Param("size_y", 0.2, 0.4, "m"),
        Param("size_z", 0.3, 0.6, "m"),
        Param("stiffness_h", 1000.0, 5000.0, "N/m"),
        Param("stiffness_v", 5000.0, 20000.0, "N/m"),
        Param("damping", 0.0, 50.0, "N*s/m"),
        Param("vel_x", 0.1, 0.5, "m/s"),
        Param("vel_z", 0.1, 0.5, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "CartesianSpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBody = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialVelocity=[vel_x, 0, vel_z],
                                    inertia=InertiaCuboid(density=density, sideLengths=[size_x, size_y, size_z]),
                                    gravity=[0, -gravity, 0])
        for sx, sz in [(-1, -1), (1, -1), (-1, 1), (1, 1)]:
            corner = [sx * 0.5 * size_x, 0.5 * size_y, sz * 0.5 * size_z]
            mbs.CreateCartesianSpringDamper(itemNumbers=[oGround, oBody], localPosition0=corner,
                                            localPosition1=corner,
                                            stiffness=[stiffness_h, stiffness_v, stiffness_h],
                                            damping=[damping] * 3)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
