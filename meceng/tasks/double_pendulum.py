"""Task 12 (level 1): double pendulum — two mass points on two massless rigid rods (distance
constraints) under gravity.

The double pendulum is chaotic at large amplitudes; the initial angles are limited to a regime
where the motion is regular over the simulated 2 s, so that a re-ordered but correct model stays
within the 1e-5 solution tolerance.

Physics checks: total energy conserved (no damping); both rod lengths kept.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=12,
    name="double pendulum",
    level="1",
    description="""
        A double pendulum moving in the x-y plane, consisting of two mass points. Mass point 1
        with mass m1 = {mass1} kg hangs from a fixed support (ground) at [0, 0, 0] on a massless
        rigid rod of length L1 = {length1} m, modeled as a distance constraint between ground and
        mass point 1. Mass point 2 with mass m2 = {mass2} kg hangs from mass point 1 on a massless
        rigid rod of length L2 = {length2} m, modeled as a distance constraint between mass point 1
        and mass point 2. Initially rod 1 is deflected by phi1 = {angle1_deg} degrees and rod 2 by
        phi2 = {angle2_deg} degrees from the downward vertical (both angles absolute, measured
        from the vertical; a positive angle deflects towards positive x), i.e. the mass points are at
        p1 = [L1*sin(phi1), -L1*cos(phi1), 0] and p2 = p1 + [L2*sin(phi2), -L2*cos(phi2), 0]. Both
        start from rest. Gravity g = {gravity} m/s^2 acts in the negative y-direction. Define the
        mass points' reference positions as p1 and p2. Create mass point 1, then mass point 2, then
        the distance constraint of rod 1, then that of rod 2.
    """,
    open_description="""
        A double pendulum in the x-y plane made of two point masses (no rotational inertia) and two
        massless rigid rods with frictionless pins; each rod only keeps the distance between its two
        ends fixed. Rod 1, of length L1 = {length1} m, runs from a fixed support at the origin
        [0, 0, 0] to mass 1 (m1 = {mass1} kg); rod 2, of length L2 = {length2} m, runs from mass 1
        to mass 2 (m2 = {mass2} kg). Gravity g = {gravity} m/s^2 acts in the negative y-direction.
        At the start both masses are at rest; rod 1 is turned phi1 = {angle1_deg} degrees and rod 2
        phi2 = {angle2_deg} degrees from hanging straight down (both angles absolute, measured from
        the downward vertical, a positive angle towards positive x), so mass 1 is at
        p1 = [L1*sin(phi1), -L1*cos(phi1), 0] and mass 2 at p1 + [L2*sin(phi2), -L2*cos(phi2), 0].
    """,
    params=(
        Param("mass1", 0.2, 3.0, "kg"),
        Param("mass2", 0.2, 3.0, "kg"),
        Param("length1", 0.3, 1.5, "m"),
        Param("length2", 0.3, 1.5, "m"),
        Param("angle1_deg", 5.0, 40.0, "deg", digits=2),
        Param("angle2_deg", -40.0, 40.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint"),
    model_code="""
        phi1 = angle1_deg * np.pi / 180
        phi2 = angle2_deg * np.pi / 180
        p1 = [length1 * np.sin(phi1), -length1 * np.cos(phi1), 0]
        p2 = [p1[0] + length2 * np.sin(phi2), p1[1] - length2 * np.cos(phi2), 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass1 = mbs.CreateMassPoint(referencePosition=p1, mass=mass1, gravity=[0, -gravity, 0])
        oMass2 = mbs.CreateMassPoint(referencePosition=p2, mass=mass2, gravity=[0, -gravity, 0])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass1], distance=length1)
        mbs.CreateDistanceConstraint(itemNumbers=[oMass1, oMass2], distance=length2)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
