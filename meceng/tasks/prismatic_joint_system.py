"""Task 26 (level 1): prismatic joint system — a block sliding on a vertical prismatic joint,
pushed by a constant force against gravity.

A cuboid block is guided by a prismatic joint along the global y-axis; a constant force with a
lateral component (taken by the joint) and an axial component acts at its centre of mass, gravity
acts along -y, and the block starts with an axial velocity. One degree of freedom with constant
acceleration: smooth and insensitive to the order of items.

Physics check: y(t) = v0*t + (Fy/m - g)*t^2/2 (reproduced to round-off); the block neither moves
sideways nor rotates.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=26,
    name="prismatic joint system",
    level="1",
    description="""
        A rigid block on a frictionless prismatic joint. The block is a homogeneous cuboid (brick)
        with mass m = {mass} kg and side lengths [a, b, c] = [{size_x}, {size_y}, {size_z}] m along
        its local x-, y- and z-axes; its inertia is computed with
        InertiaCuboid(density=m/(a*b*c), sideLengths=[a, b, c]), so the body's reference point is
        its center of mass. The block's reference position is [0, 0, 0] and its reference rotation
        is the identity. A prismatic joint between ground and block at [0, 0, 0] lets the block
        slide only along the global y-axis (axis [0, 1, 0]). The block starts with the initial
        velocity [0, {vel_y}, 0] m/s and zero angular velocity. A constant force
        [{force_x}, {force_y}, 0] N acts at the block's center of mass. Gravity g = {gravity} m/s^2
        acts in the negative y-direction. Create the ground, the block, the prismatic joint and then
        the force.
    """,
    open_description="""
        A rigid block sliding on a frictionless straight vertical guide. The block is a homogeneous
        cuboid of mass m = {mass} kg with edge lengths {size_x} m, {size_y} m and {size_z} m along
        the global x-, y- and z-directions; its centre of mass starts at the origin [0, 0, 0] with
        its edges parallel to the global axes. The guide lets the block translate only along the
        global y-axis; it cannot move sideways and cannot rotate. A constant force
        [{force_x}, {force_y}, 0] N (fixed in direction) acts at the block's centre of mass, and
        gravity g = {gravity} m/s^2 acts in the negative y-direction. At the start the block moves
        with the velocity [0, {vel_y}, 0] m/s and does not rotate.
    """,
    params=(
        Param("mass", 1.0, 20.0, "kg"),
        Param("size_x", 0.1, 0.8, "m"),
        Param("size_y", 0.1, 0.8, "m"),
        Param("size_z", 0.1, 0.8, "m"),
        Param("force_x", -20.0, 20.0, "N"),
        Param("force_y", 0.0, 100.0, "N"),
        Param("vel_y", -2.0, 2.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "PrismaticJoint", "Force"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBlock = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialVelocity=[0, vel_y, 0],
                                     inertia=InertiaCuboid(density=mass / (size_x * size_y * size_z),
                                                           sideLengths=[size_x, size_y, size_z]),
                                     gravity=[0, -gravity, 0])
        mbs.CreatePrismaticJoint(itemNumbers=[oGround, oBlock], position=[0, 0, 0], axis=[0, 1, 0])
        mbs.CreateForce(itemNumber=oBlock, loadVector=[force_x, force_y, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
