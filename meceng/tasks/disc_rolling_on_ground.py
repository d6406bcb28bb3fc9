"""Task 32 (level 2): disc rolling on ground — an upright disc rolls without slipping on the floor.

A homogeneous disc (rigid body, InertiaCylinder with its axis along the local x-axis) stands upright
on the plane z = 0 and rolls with the ideal rolling-disc constraint in the horizontal direction given
by the heading angle psi. Its initial velocity and angular velocity are consistent with rolling. The
speeds (2-4 m/s) are well above the critical speed sqrt(g*r/3) < 1.2 m/s below which an upright
disc falls over, so the upright rolling is stable and a re-ordered but correct model stays within
round-off of the ground truth.

Physics checks: the center moves on a straight line with constant velocity at height r; the angular
velocity stays -v/r about the disc axis (rolling without slipping, contact point at rest).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=32,
    name="disc rolling on ground",
    level="2",
    description="""
        A homogeneous disc with density rho = {density} kg/m^3, radius r = {radius} m and width
        (thickness) w = {width} m rolls without slipping on the ground plane z = 0. The disc is a
        rigid body with inertia InertiaCylinder(density=rho, length=w, outerRadius=r, axis=0), i.e.
        its axis is the local x-axis. It stands upright: its reference position (the disc center)
        is [{x0}, {y0}, r] and its reference rotation matrix is RotationMatrixZ(psi) with the
        heading angle psi = {heading_deg} degrees (converted to radians), so the disc axis is
        a = [cos(psi), sin(psi), 0]. The disc rolls in the direction d = [-sin(psi), cos(psi), 0]
        with the speed v = {velocity} m/s: its initial velocity is v*d and its initial angular
        velocity is -(v/r)*a, so that the contact point is at rest. Gravity g = {gravity} m/s^2 acts
        in the negative z-direction. The ideal rolling is modeled with a rolling disc joint between
        the ground (created at [0, 0, 0]) and the disc, with the disc center axisPosition = [0, 0, 0]
        and the disc axis axisVector = [1, 0, 0] in the disc's local coordinates, the disc radius r,
        and the ground plane through [0, 0, 0] with the normal [0, 0, 1]. Create the ground, the
        disc and then the rolling disc joint.
    """,
    open_description="""
        A homogeneous disc (a short solid cylinder) of density {density} kg/m^3, radius
        r = {radius} m and thickness {width} m rolls upright on the flat horizontal ground z = 0.
        The disc rolls without slipping: its contact point with the ground has no velocity in any
        direction (neither sliding along nor sideways), and it stays in contact with the ground
        (it never lifts off). The disc's centre starts at [{x0}, {y0}, r], with its symmetry axis
        (axle direction) horizontal along a = [cos(psi), sin(psi), 0], where the heading angle
        psi = {heading_deg} degrees is measured counter-clockwise from the positive x-axis about
        the vertical. At the start the disc rolls in the horizontal direction
        d = [-sin(psi), cos(psi), 0] with the speed v = {velocity} m/s: its centre moves with the
        velocity v*d and its angular velocity is -(v/r)*a, consistent with rolling without
        slipping. Gravity g = {gravity} m/s^2 acts in the negative z-direction; there is no rolling
        resistance and no other force.
    """,
    params=(
        Param("density", 1000.0, 8000.0, "kg/m^3"),
        Param("radius", 0.1, 0.4, "m"),
        Param("width", 0.01, 0.05, "m"),
        Param("x0", -1.0, 1.0, "m"),
        Param("y0", -1.0, 1.0, "m"),
        Param("heading_deg", 0.0, 360.0, "deg"),
        Param("velocity", 2.0, 4.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "RollingDisc"),
    model_code="""
        psi = heading_deg * np.pi / 180
        axis = np.array([np.cos(psi), np.sin(psi), 0])
        direction = np.array([-np.sin(psi), np.cos(psi), 0])
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[x0, y0, radius],
                                    referenceRotationMatrix=RotationMatrixZ(psi),
                                    initialVelocity=velocity * direction,
                                    initialAngularVelocity=-velocity / radius * axis,
                                    inertia=InertiaCylinder(density=density, length=width,
                                                            outerRadius=radius, axis=0),
                                    gravity=[0, 0, -gravity])
        mbs.CreateRollingDisc(bodyNumbers=[oGround, oDisc], axisPosition=[0, 0, 0], axisVector=[1, 0, 0],
                              discRadius=radius, planePosition=[0, 0, 0], planeNormal=[0, 0, 1])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
