"""Task 48 (level 2): gyroscope nutation — a fast spinning disc on a massless axle, supported at the
axle's end by a spherical joint (heavy symmetric top), released with pure spin under gravity.

The heavy symmetric top is integrable (energy, vertical angular momentum and spin are conserved),
so the motion is regular: the axis nutates between its initial inclination and a lower turning
angle while it precesses. Spin rates of 100-250 rad/s are resolved with 10000 steps in 1 s (at most
0.025 rad per step), so that the integrator's phase error stays small and a re-ordered model stays
within the solution tolerance.

Physics checks: the axis inclination follows the reduced one-degree-of-freedom equation of the heavy
symmetric top, which rests on the conservation of energy, of the vertical angular momentum about
the pivot and of the spin (integrated independently), and reaches the closed-form lower turning
point of the nutation; the disc center keeps its distance from the pivot.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=48,
    name="gyroscope nutation",
    level="2",
    description="""
        A gyroscope (heavy symmetric top) consisting of a homogeneous disc with density
        rho = {density} kg/m^3, radius R = {disc_radius} m and thickness t = {thickness} m, mounted
        on a massless axle along the disc's symmetry axis. The disc is a rigid body whose inertia is
        computed with InertiaCylinder(density=rho, length=t, outerRadius=R, axis=0), so the disc
        axis is its local x-axis and its reference point is its center of mass. The end of the
        axle is supported at the fixed point O = [0, 0, 0] by a spherical joint between ground and
        disc (all three translations constrained, rotations free). The disc center is at the
        distance l = {axle_length} m from O along the axle. Initially the axle lies in the x-z plane,
        raised by the angle alpha = {elevation_deg} degrees above the horizontal (converted to
        radians): the axis direction is u = [cos(alpha), 0, sin(alpha)], the disc's reference
        position is l*u and its reference rotation matrix is RotationMatrixY(-alpha) (which maps
        the local x-axis to u). The disc starts with zero translational velocity and spins about
        its axis with the initial angular velocity {spin}*u rad/s (no initial precession). Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. No friction. Create the ground, the
        disc and then the spherical joint.
    """,
    open_description="""
        A gyroscope (heavy symmetric top): a homogeneous disc of density {density} kg/m^3, radius
        R = {disc_radius} m and thickness {thickness} m, fixed on a massless rigid axle that lies
        along the disc's symmetry axis. The free end of the axle is held at the fixed point
        O = [0, 0, 0] by a frictionless ball joint (the point is fixed, every rotation is free); the
        disc's centre is on the axle at the distance l = {axle_length} m from O. At the start the
        axle lies in the x-z plane, pointing from O towards +x and raised by the angle
        {elevation_deg} degrees above the horizontal, along u = [cos(alpha), 0, sin(alpha)] with
        alpha = {elevation_deg} degrees; the disc's centre is at l*u. The disc's centre starts at
        rest and the disc spins about its own axis with the angular velocity {spin}*u rad/s (that
        is {spin} rad/s about u, no initial precession). Gravity g = {gravity} m/s^2 acts in the
        negative z-direction; there is no friction.
    """,
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("disc_radius", 0.06, 0.1, "m"),
        Param("thickness", 0.01, 0.03, "m"),
        Param("axle_length", 0.08, 0.15, "m"),
        Param("elevation_deg", 0.0, 30.0, "deg"),
        Param("spin", 100.0, 250.0, "rad/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "SphericalJoint"),
    model_code="""
        alpha = elevation_deg * np.pi / 180
        u = np.array([np.cos(alpha), 0, np.sin(alpha)])
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=axle_length * u,
                                    referenceRotationMatrix=RotationMatrixY(-alpha),
                                    initialVelocity=[0, 0, 0],
                                    initialAngularVelocity=spin * u,
                                    inertia=InertiaCylinder(density=density, length=thickness,
                                                            outerRadius=disc_radius, axis=0),
                                    gravity=[0, 0, -gravity])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0])
    """,
    sim=SimSettings(end_time=1.0, steps=10000),
)
