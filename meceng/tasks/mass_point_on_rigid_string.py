"""Task 20 (level 1): mass point on rigid string — a spherical pendulum in 3D: a mass point on a
massless rigid string (distance constraint) to a ground point, started horizontally with a
horizontal velocity, so it whirls about the vertical z-axis while it drops under gravity.

The spherical pendulum is integrable (energy and the angular momentum about the vertical are
conserved), so the motion is regular and a re-ordered model stays within the 1e-5 solution
tolerance. The initial velocity is perpendicular to the string, as the constraint requires.

Physics checks: energy and the angular momentum about the z-axis are conserved; the string length
is kept; the string force equals m*(v^2/L - g.e) with e the unit vector from the mass towards the
support (this catches the mass, which does not change the motion).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=20,
    name="mass point on rigid string",
    level="1",
    description="""
        A mass point on a rigid string in 3D (a spherical pendulum): a mass point with mass
        m = {mass} kg is attached to a fixed point (ground) at [0, 0, 0] by a massless rigid
        string of length L = {length} m, modeled as a distance constraint with distance L between
        ground and the mass point. The mass point's reference position, which is also its initial
        position, is p0 = [{length}, 0, 0] m, and it starts with the initial velocity
        v0 = [0, {vy}, {vz}] m/s, so that it rotates predominantly about the z-axis. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. Create the ground, the mass point
        and then the distance constraint.
    """,
    open_description="""
        A spherical pendulum in 3D: a point mass of m = {mass} kg hangs on a massless rigid string
        of length L = {length} m from a fixed point at the origin [0, 0, 0]; the string is pinned
        without friction at both ends and keeps the distance between the fixed point and the point
        mass at exactly L (it can take tension and compression, like a rigid rod). Gravity g =
        {gravity} m/s^2 acts in the negative z-direction. At the start the point mass is at
        [{length}, 0, 0] (the string horizontal along +x) and moves with the velocity [0, {vy},
        {vz}] m/s, so that it whirls mainly about the vertical z-axis.
    """,
    params=(
        Param("mass", 0.5, 3.0, "kg"),
        Param("length", 0.3, 1.0, "m"),
        Param("vy", 2.0, 5.0, "m/s"),
        Param("vz", -1.0, 1.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[length, 0, 0], initialVelocity=[0, vy, vz],
                                    mass=mass, gravity=[0, 0, -gravity])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], distance=length)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
