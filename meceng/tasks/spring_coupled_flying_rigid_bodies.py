"""Task 14 (level 1): spring coupled flying rigid bodies — two free cuboids joined end to end by a
Cartesian spring-damper, thrown with opposite transverse velocities (no gravity).

The two equal bars lie along the x-axis and touch at [a, 0, 0], where the Cartesian spring-damper
joins their ends; opposite initial velocities in +-y make them spin about their common centre of
mass in the x-y plane while the joint stretches and oscillates. The motion stays planar and the
spring is stiff compared with the spin, so the system behaves like a slightly elastic hinged
dumbbell: regular over the simulated 2 s (checked with re-ordered models). The ranges keep each
body at 2-15 kg, the gap in the joint below about 8 % of a and the highest (transverse joint)
frequency sqrt(8*k/m) below about 300 rad/s, which the 1 ms steps integrate stably.

Physics checks: linear momentum is conserved (the centre of mass of the pair stays at [a, 0, 0]);
without damping the total energy (kinetic + spring energy) and the angular momentum are conserved.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=14,
    name="spring coupled flying rigid bodies",
    level="1",
    description="""
        Two free flying rigid bodies coupled by a Cartesian spring-damper. Both bodies are
        homogeneous cuboids (bricks) with density rho = {density} kg/m^3 and side lengths
        [a, b, c] = [{size_x}, {size_y}, {size_z}] m along their local x-, y- and z-axes; their
        inertia is computed with InertiaCuboid(density=rho, sideLengths=[a, b, c]), so each body's
        reference point is its center of mass. Both have the identity reference rotation. Body 1's
        reference position is [a/2, 0, 0] and body 2's is [3*a/2, 0, 0], so the two bodies touch at
        [a, 0, 0]. A Cartesian spring-damper is attached between body 1 at its local position
        [a/2, 0, 0] and body 2 at its local position [-a/2, 0, 0] (both points are at [a, 0, 0] in
        the reference configuration, so the spring is relaxed there with offset [0, 0, 0]); it has
        the stiffness [k, k, k] with k = {stiffness} N/m and the damping [d, d, d] with
        d = {damping} N*s/m in the global x-, y- and z-directions. Body 1 has the initial velocity
        [0, {velocity}, 0] m/s and body 2 the initial velocity [0, -{velocity}, 0] m/s; both have
        zero initial angular velocity. There is no gravity, no ground object and no other load.
        Create body 1, then body 2, then the spring-damper.
    """,
    open_description="""
        Two identical free rigid bars flying in space, joined end to end by an elastic coupling;
        there is no gravity and no other load. Each bar is a homogeneous brick (rectangular
        cuboid) of density {density} kg/m^3 with edge lengths a = {size_x} m, b = {size_y} m and c
        = {size_z} m, which at the start lie along the global x-, y- and z-axes. At the start the
        centre of bar 1 is at [a/2, 0, 0] and the centre of bar 2 at [3*a/2, 0, 0], so the bars
        lie end to end along the x-axis and touch at [a, 0, 0]. The coupling joins the centre of
        bar 1's end face at +x to the centre of bar 2's end face at -x (both at [a, 0, 0] at the
        start): it is a zero-length linear spring-damper that pulls these two points together with
        the force k times their separation vector plus d times their relative velocity vector, the
        same in every direction, with k = {stiffness} N/m and d = {damping} N*s/m; it is relaxed
        at the start. Bar 1 starts with the velocity [0, {velocity}, 0] m/s and bar 2 with [0,
        -{velocity}, 0] m/s; neither bar rotates at the start.
    """,
    params=(
        Param("density", 1000.0, 2000.0, "kg/m^3"),
        Param("size_x", 0.4, 0.6, "m"),
        Param("size_y", 0.1, 0.15, "m"),
        Param("size_z", 0.05, 0.08, "m"),
        Param("stiffness", 5000.0, 20000.0, "N/m"),
        Param("damping", 0.0, 20.0, "N*s/m"),
        Param("velocity", 0.5, 2.0, "m/s"),
    ),
    components=("RigidBody", "InertiaCuboid", "CartesianSpringDamper"),
    model_code="""
        inertia = InertiaCuboid(density=density, sideLengths=[size_x, size_y, size_z])
        oBody1 = mbs.CreateRigidBody(referencePosition=[0.5 * size_x, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialVelocity=[0, velocity, 0],
                                     inertia=inertia)
        oBody2 = mbs.CreateRigidBody(referencePosition=[1.5 * size_x, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialVelocity=[0, -velocity, 0],
                                     inertia=inertia)
        mbs.CreateCartesianSpringDamper(itemNumbers=[oBody1, oBody2],
                                        localPosition0=[0.5 * size_x, 0, 0],
                                        localPosition1=[-0.5 * size_x, 0, 0],
                                        stiffness=[stiffness] * 3, damping=[damping] * 3)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
