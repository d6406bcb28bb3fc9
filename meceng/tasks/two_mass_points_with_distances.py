"""Task 28 (level 1): two mass points with distances — two free mass points connected by a massless
rigid rod (distance constraint), started with opposite transverse velocities: a dumbbell that
spins in the x-y plane while its centre of mass drifts; no ground, no gravity.

The initial velocities are perpendicular to the rod, as the constraint requires. The motion has a
closed form and is regular, so a re-ordered model stays within the 1e-5 solution tolerance.

Physics checks: the centre of mass moves with the constant velocity (m1*v1 - m2*v2)/(m1 + m2) in y,
and the rod turns about it with the constant angular velocity -(v1 + v2)/(2*a) about z; the rod force
equals the centripetal force mu*omega^2*2a with the reduced mass mu = m1*m2/(m1 + m2).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=28,
    name="two mass points with distances",
    level="1",
    description="""
        Two free mass points connected by a massless rigid rod. Mass point 1 with mass
        m1 = {mass1} kg has the reference position p1 = [-{half_distance}, 0, 0] m and mass point 2
        with mass m2 = {mass2} kg the reference position p2 = [{half_distance}, 0, 0] m; these are
        also their initial positions. Mass point 1 starts with the initial velocity
        [0, {velocity1}, 0] m/s and mass point 2 with [0, -{velocity2}, 0] m/s. The rod is modeled
        as a distance constraint between the two mass points with distance 2*{half_distance} m.
        The system is attached to nothing (no ground object is needed); there is no gravity and no
        other force. Create mass point 1, mass point 2 and then the distance constraint.
    """,
    open_description="""
        A dumbbell floating freely in space: two point masses joined by a massless rigid rod that
        keeps their distance constant at 2*{half_distance} m. Point mass 1, m1 = {mass1} kg, starts
        at [-{half_distance}, 0, 0] m with the velocity [0, {velocity1}, 0] m/s; point mass 2,
        m2 = {mass2} kg, starts at [{half_distance}, 0, 0] m with the velocity
        [0, -{velocity2}, 0] m/s. The rod carries force only along its length. The dumbbell is not
        attached to anything; there is no gravity and no other force.
    """,
    params=(
        Param("mass1", 0.5, 2.0, "kg"),
        Param("mass2", 0.5, 2.0, "kg"),
        Param("half_distance", 0.25, 0.8, "m"),
        Param("velocity1", 0.5, 4.0, "m/s"),
        Param("velocity2", 0.5, 4.0, "m/s"),
    ),
    components=("MassPoint", "DistanceConstraint"),
    model_code="""
        oMass1 = mbs.CreateMassPoint(referencePosition=[-half_distance, 0, 0],
                                     initialVelocity=[0, velocity1, 0], mass=mass1)
        oMass2 = mbs.CreateMassPoint(referencePosition=[half_distance, 0, 0],
                                     initialVelocity=[0, -velocity2, 0], mass=mass2)
        mbs.CreateDistanceConstraint(itemNumbers=[oMass1, oMass2], distance=2 * half_distance)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
