"""Task 9 (level 1): double mass oscillator — two mass points in series on two spring-dampers
(ground - mass 1 - mass 2) along the x-axis.

Physics checks: with d1 = d2 = 0 the motion is the superposition of the two normal modes of the
2x2 eigenproblem K*phi = omega^2*M*phi, and the total energy is conserved. The displacement is
limited so that neither spring can collapse (|x1| <= u2*sqrt(k2/k1) < L1).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=9,
    name="double mass oscillator",
    level="1",
    description="""
        A double mass oscillator along the x-axis consisting of two mass points connected in
        series by two linear spring-dampers. Mass point 1 has mass m1 = {mass1} kg and the
        reference position p1 = [{length1}, 0, 0] m; mass point 2 has mass m2 = {mass2} kg and
        the reference position p2 = [{length1} + {length2}, 0, 0] m. Spring-damper 1 with
        stiffness k1 = {stiffness1} N/m and damping coefficient d1 = {damping1} N*s/m connects
        ground at [0, 0, 0] with mass point 1; spring-damper 2 with stiffness k2 = {stiffness2} N/m
        and damping coefficient d2 = {damping2} N*s/m connects mass point 1 with mass point 2. The
        springs are relaxed in the reference configuration, i.e. their relaxed lengths are
        L1 = {length1} m and L2 = {length2} m. Mass point 1 starts at its reference position and
        mass point 2 with an initial displacement of [{displacement}, 0, 0] m from its reference
        position; both start with zero velocity. Gravity is neglected. Create mass point 1, then
        mass point 2, then spring-damper 1, then spring-damper 2.
    """,
    open_description="""
        A double mass oscillator along the x-axis without gravity: two point masses (no rotational
        inertia) in series on two linear spring-dampers, each acting along the line between its two
        end points, with damping force proportional to the rate of change of its length.
        Spring-damper 1 (stiffness k1 = {stiffness1} N/m, damping coefficient d1 = {damping1} N*s/m,
        unstretched length L1 = {length1} m) joins a fixed point at the origin [0, 0, 0] to mass 1
        (m1 = {mass1} kg); spring-damper 2 (stiffness k2 = {stiffness2} N/m, damping coefficient
        d2 = {damping2} N*s/m, unstretched length L2 = {length2} m) joins mass 1 to mass 2
        (m2 = {mass2} kg). With both springs unstretched, mass 1 sits at [{length1}, 0, 0] m and
        mass 2 at [{length1} + {length2}, 0, 0] m. At the start both masses are at rest; mass 1 is
        at its unstretched position and mass 2 is pulled {displacement} m further in the positive
        x-direction from its unstretched position, so only spring 2 is stretched, by
        {displacement} m.
    """,
    params=(
        Param("mass1", 0.5, 5.0, "kg"),
        Param("mass2", 0.5, 5.0, "kg"),
        Param("stiffness1", 200.0, 2000.0, "N/m"),
        Param("stiffness2", 200.0, 2000.0, "N/m"),
        Param("damping1", 0.0, 5.0, "N*s/m"),
        Param("damping2", 0.0, 5.0, "N*s/m"),
        Param("length1", 0.5, 2.0, "m"),
        Param("length2", 0.5, 2.0, "m"),
        Param("displacement", 0.02, 0.1, "m"),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass1 = mbs.CreateMassPoint(referencePosition=[length1, 0, 0], mass=mass1)
        oMass2 = mbs.CreateMassPoint(referencePosition=[length1 + length2, 0, 0],
                                     initialDisplacement=[displacement, 0, 0],
                                     mass=mass2)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass1], stiffness=stiffness1, damping=damping1)
        mbs.CreateSpringDamper(itemNumbers=[oMass1, oMass2], stiffness=stiffness2, damping=damping2)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
