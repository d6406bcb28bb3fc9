"""Task 21 (level 1): mass point on elastic string — a 3D elastic spherical pendulum: a mass point on
a spring-damper to a ground point, started horizontally with a horizontal velocity, so it whirls
about the vertical z-axis while it drops under gravity.

The string is stiff (sqrt(k/m) >= 31 rad/s against whirl rates below about 17 rad/s; the
centrifugal and gravity stretch stays below about 30 % of the length even at the softest, heaviest,
fastest corner of the ranges), so the motion is regular over the simulated 2 s and a re-ordered but
correct model stays within the 1e-5 solution tolerance.

Physics checks: the angular momentum about the z-axis is conserved exactly (spring, damper and
gravity give no moment about z); mechanical energy minus the work dissipated by the damper stays
equal to the initial energy; the start state.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=21,
    name="mass point on elastic string",
    level="1",
    description="""
        A mass point on an elastic string in 3D: a mass point with mass m = {mass} kg is attached
        to a fixed point (ground) at [0, 0, 0] by an elastic string, modeled as a linear
        spring-damper between ground and the mass point with stiffness k = {stiffness} N/m and
        damping coefficient d = {damping} N*s/m. The mass point's reference position, which is also
        its initial position, is p0 = [{length}, 0, 0] m, and the string is relaxed there (relaxed
        length L = {length} m). The mass point starts with the initial velocity
        v0 = [0, {vy}, {vz}] m/s, so that it rotates predominantly about the z-axis. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. Create the ground, the mass point
        and then the spring-damper.
    """,
    open_description="""
        A point mass on an elastic string in 3D: a point mass of m = {mass} kg is tied to a fixed
        point at the origin [0, 0, 0] by a massless linear spring-damper with stiffness k =
        {stiffness} N/m, damping coefficient d = {damping} N*s/m and unstretched length L =
        {length} m; it pulls or pushes along the line between the fixed point and the point mass
        with the force k times its stretch plus d times the rate of change of its length. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. At the start the point mass is at
        [{length}, 0, 0] (the spring horizontal along +x and unstretched) and moves with the
        velocity [0, {vy}, {vz}] m/s, so that it whirls mainly about the vertical z-axis.
    """,
    params=(
        Param("mass", 0.5, 2.0, "kg"),
        Param("length", 0.3, 0.8, "m"),
        Param("stiffness", 2000.0, 5000.0, "N/m"),
        Param("damping", 0.0, 10.0, "N*s/m"),
        Param("vy", 2.0, 4.0, "m/s"),
        Param("vz", -1.0, 1.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[length, 0, 0], initialVelocity=[0, vy, vz],
                                    mass=mass, gravity=[0, 0, -gravity])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
