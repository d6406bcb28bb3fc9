"""Task 25 (level 1): gyroscope on spherical joint — a fast spinning disc whose axis is held at one
end by a spherical joint, precessing under gravity (a heavy symmetric top released horizontally).

The disc axis starts horizontal along x with the centre of mass at distance a from the joint and
the disc spinning about its axis; gravity (negative z) makes the axis precess about the vertical
with a small nutation. The ranges keep the top fast (spin 100-200 rad/s, J3*omega^2 >> m*g*a; the
nutation amplitude is below about 3 degrees), and a symmetric top is integrable, so the motion is
regular; 2 s show between about 0.2 and 2 rad of precession. Steps of 0.5 ms keep the spin angle
per step at most 0.1 rad.

Physics checks: the centre-of-mass trajectory agrees with an independent RK4 integration of the
heavy top (Euler's equations about the fixed point); the mean precession rate is close to the
gyroscopic estimate m*g*a/(J3*omega) with J3 = m*r^2/2; energy, the vertical angular momentum and
the spin about the disc axis are conserved.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=25,
    name="gyroscope on spherical joint",
    level="1",
    description="""
        A gyroscope modeled as a rigid disc on a spherical joint. The disc is a homogeneous solid
        cylinder with mass m = {mass} kg, radius r = {radius} m and width (thickness along its axis)
        w = {width} m; its inertia is computed with
        InertiaCylinder(density=m/(pi*r^2*w), length=w, outerRadius=r, axis=0), so the disc axis is
        its local x-axis and the body's reference point is its center of mass. The disc's reference
        position (center of mass) is [{offset}, 0, 0] and its reference rotation is the identity, so
        its axis initially points along the global x-axis. The disc is connected to ground by a
        spherical joint at [0, 0, 0] that constrains all three translations. The disc starts with
        the initial angular velocity [{omega0}, 0, 0] rad/s (spinning about its own axis) and zero
        initial velocity. Gravity g = {gravity} m/s^2 acts in the negative z-direction; no other
        forces and no damping. Create the ground, the disc and then the spherical joint.
    """,
    open_description="""
        A gyroscope (a heavy symmetric top): a homogeneous solid disc (cylinder) of mass m =
        {mass} kg, radius r = {radius} m and thickness w = {width} m. At the start its axis of
        symmetry is horizontal along the global x-axis and its centre is at [{offset}, 0, 0]. The
        point [0, 0, 0] on the extension of the disc's axis, at the distance {offset} m from its
        centre, is rigidly attached to the disc (by a massless rigid axle) and held fixed by a
        frictionless ball joint: that point cannot move, while the disc can rotate freely about it
        in every direction. At the start the centre of the disc is at rest and the disc spins
        about its own axis with the angular velocity [{omega0}, 0, 0] rad/s (spin vector along
        positive x). Gravity g = {gravity} m/s^2 acts in the negative z-direction; there are no
        other forces and no damping.
    """,
    params=(
        Param("mass", 5.0, 30.0, "kg"),
        Param("radius", 0.2, 0.3, "m"),
        Param("width", 0.02, 0.05, "m"),
        Param("offset", 0.1, 0.2, "m"),
        Param("omega0", 100.0, 200.0, "rad/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "SphericalJoint"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[offset, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialAngularVelocity=[omega0, 0, 0],
                                    inertia=InertiaCylinder(density=mass / (np.pi * radius**2 * width),
                                                            length=width, outerRadius=radius, axis=0),
                                    gravity=[0, 0, -gravity])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=4000),
)
