"""Task 19 (level 1): single pendulum / rigid body — a cuboid link on a revolute joint to ground.

The link is a homogeneous cuboid whose long side points from the pivot to its centre of mass; it
swings in the x-y plane under gravity. One degree of freedom, no contact: the motion is smooth and
insensitive to the order of items.

Physics checks: small-angle period 2*pi*sqrt(J_O/(m*g*a)) with J_O = m*(w^2 + L^2)/12 + m*a^2 and
a = L/2 (parallel-axis theorem); total energy conserved at larger angles (no damping).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=19,
    name="single pendulum / rigid body",
    level="1",
    description="""
        A physical pendulum consisting of a single rigid link that is attached to ground by a
        revolute joint. The link is a homogeneous cuboid with density rho = {density} kg/m^3 and
        side lengths [w, L, h] = [{width}, {length}, {thickness}] m along its local x-, y- and
        z-axes; its inertia is computed with InertiaCuboid(density=rho, sideLengths=[w, L, h]), so
        the body's reference point is its center of mass. The revolute joint is located at the
        ground point [0, 0, 0] at the upper end of the link, with its rotation axis along the
        global z-axis [0, 0, 1], so the pendulum swings in the x-y plane. Initially the link is
        deflected by phi0 = {angle_deg} degrees from the downward vertical towards positive x and
        starts from rest: its reference rotation matrix is RotationMatrixZ(phi0) (with phi0
        converted to radians), so that its local y-axis points along the link, and its reference
        position (center of mass) is p0 = [L/2*sin(phi0), -L/2*cos(phi0), 0]. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction. Create the ground, then the link,
        then the revolute joint between ground and link.
    """,
    open_description="""
        A physical pendulum: a homogeneous rigid bar of rectangular cross-section, density
        {density} kg/m^3, length L = {length} m, width {width} m and thickness {thickness} m. One
        end of the bar is pinned to the fixed world at the origin [0, 0, 0] by a frictionless hinge
        whose axis is the global z-axis; the bar's thickness lies along the hinge axis, and its
        width and length lie in the x-y plane, so it swings in that plane. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction. At the start the bar is at rest,
        turned {angle_deg} degrees from hanging straight down, towards positive x: its free end is
        at x > 0, y < 0.
    """,
    params=(
        Param("density", 500.0, 8000.0, "kg/m^3"),
        Param("length", 0.3, 1.5, "m"),
        Param("width", 0.02, 0.1, "m"),
        Param("thickness", 0.01, 0.05, "m"),
        Param("angle_deg", 5.0, 60.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "RevoluteJoint"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        p0 = [0.5 * length * np.sin(phi0), -0.5 * length * np.cos(phi0), 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink = mbs.CreateRigidBody(referencePosition=p0,
                                    referenceRotationMatrix=RotationMatrixZ(phi0),
                                    inertia=InertiaCuboid(density=density,
                                                          sideLengths=[width, length, thickness]),
                                    gravity=[0, -gravity, 0])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
