"""Task 27 (level 1): two mass points with springs — two free mass points connected by one
spring-damper, started with opposite transverse velocities, so the pair spins and stretches the
spring; no ground, no gravity.

The relative motion is a central-force problem (regular, not chaotic); the spring stays stretched
(it starts relaxed with a purely transverse relative velocity) and never collapses, so a re-ordered
model stays within the 1e-5 solution tolerance.

Physics checks: total linear momentum and the angular momentum are conserved exactly (internal
central force); kinetic + spring energy minus the work dissipated by the damper stays equal to the
initial energy; the motion stays in the x-y plane.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=27,
    name="two mass points with springs",
    level="1",
    description="""
        Two free mass points connected by a spring. Mass point 1 with mass m1 = {mass1} kg has the
        reference position p1 = [-{half_distance}, 0, 0] m and mass point 2 with mass
        m2 = {mass2} kg the reference position p2 = [{half_distance}, 0, 0] m; these are also
        their initial positions. Mass point 1 starts with the initial velocity [0, {velocity1}, 0]
        m/s and mass point 2 with [0, -{velocity2}, 0] m/s. The two mass points are connected by a
        linear spring-damper with stiffness k = {stiffness} N/m and damping coefficient
        d = {damping} N*s/m, which is relaxed in the initial configuration (relaxed length
        2*{half_distance} m). The system is attached to nothing (no ground object is needed); there
        is no gravity and no other force. Create mass point 1, mass point 2 and then the
        spring-damper.
    """,
    open_description="""
        Two point masses, free in space, joined by a massless linear spring-damper. Point mass 1,
        m1 = {mass1} kg, starts at [-{half_distance}, 0, 0] m with the velocity [0, {velocity1}, 0]
        m/s; point mass 2, m2 = {mass2} kg, starts at [{half_distance}, 0, 0] m with the velocity
        [0, -{velocity2}, 0] m/s. The spring-damper acts along the line between the two masses,
        with stiffness k = {stiffness} N/m, damping coefficient d = {damping} N*s/m (force
        proportional to the rate of change of the distance) and unstretched length equal to the
        initial distance 2*{half_distance} m, so it is relaxed at the start. Nothing else acts: the
        pair is not attached to anything, there is no gravity and no other force.
    """,
    params=(
        Param("mass1", 0.5, 2.0, "kg"),
        Param("mass2", 0.5, 2.0, "kg"),
        Param("half_distance", 0.25, 0.8, "m"),
        Param("velocity1", 0.5, 3.0, "m/s"),
        Param("velocity2", 0.5, 3.0, "m/s"),
        Param("stiffness", 500.0, 2000.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
    ),
    components=("MassPoint", "SpringDamper"),
    model_code="""
        oMass1 = mbs.CreateMassPoint(referencePosition=[-half_distance, 0, 0],
                                     initialVelocity=[0, velocity1, 0], mass=mass1)
        oMass2 = mbs.CreateMassPoint(referencePosition=[half_distance, 0, 0],
                                     initialVelocity=[0, -velocity2, 0], mass=mass2)
        mbs.CreateSpringDamper(itemNumbers=[oMass1, oMass2], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
