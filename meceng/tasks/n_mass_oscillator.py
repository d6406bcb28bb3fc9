"""Task 10 (level 1): n-mass oscillator — n identical mass points in series on n identical
spring-dampers (ground - mass 1 - ... - mass n) along the x-axis, the last mass pulled by a constant
force; the number of masses n = 2..8 is drawn per instance.

The force only stretches the springs (static elongation F/k <= 0.06 m per spring, dynamic at most
about twice that, against spring lengths >= 0.3 m), so no spring collapses and the motion is exactly
linear and not sensitive to round-off.

Physics checks: with equal springs and dampers the damping matrix is proportional to the stiffness
matrix, and the displacements equal the closed-form solution of M*x'' + D*x' + K*x = f from rest
(first-order eigen-decomposition); the static equilibrium is x_i = i*F/k; with d = 0 the energy
balance E_kin + E_spring = F*x_n holds.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=10,
    name="n-mass oscillator",
    level="1",
    description="""
        An n-mass oscillator along the x-axis: a serial chain of n = {n_masses} identical mass
        points (index i = 1 to n), each with mass m = {mass} kg, connected by n identical linear
        spring-dampers with stiffness k = {stiffness} N/m and damping coefficient
        d = {damping} N*s/m. Mass point i has the reference position [i*L, 0, 0] with
        L = {length} m. Spring-damper 1 connects ground at [0, 0, 0] with mass point 1, and
        spring-damper i (i = 2 to n) connects mass point i-1 with mass point i; all springs are
        relaxed in the reference configuration (relaxed length L). All mass points start at their
        reference positions with zero velocity. A constant force [{force}, 0, 0] N acts on the last
        mass point (index n). Gravity is neglected. Create the ground, then the mass points in the
        order of their index, then the spring-dampers in the order of their index, then the force.
    """,
    open_description="""
        An n-mass oscillator along the x-axis without gravity: a chain of n = {n_masses} identical
        point masses (no rotational inertia), each of mass m = {mass} kg, numbered i = 1 to n from
        the fixed end, linked by n identical linear spring-dampers with stiffness
        k = {stiffness} N/m, damping coefficient d = {damping} N*s/m (force proportional to the rate
        of change of its length, acting along the line between its end points) and unstretched
        length L = {length} m. Spring-damper 1 joins a fixed point at the origin [0, 0, 0] to mass
        1, and spring-damper i (i = 2 to n) joins mass i-1 to mass i. At the start all springs are
        unstretched, so mass i is at [i*L, 0, 0], and all masses are at rest. A constant force of
        {force} N in the positive x-direction acts on the last mass (mass n) from the start on.
    """,
    params=(
        Param("n_masses", 2, 8, "", integer=True),
        Param("mass", 0.5, 3.0, "kg"),
        Param("stiffness", 500.0, 3000.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
        Param("length", 0.3, 1.0, "m"),
        Param("force", 5.0, 30.0, "N"),
    ),
    components=("Ground", "MassPoint", "SpringDamper", "Force"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        masses = []
        for i in range(1, n_masses + 1):
            masses.append(mbs.CreateMassPoint(referencePosition=[i * length, 0, 0], mass=mass))
        bodies = [oGround] + masses
        for i in range(n_masses):
            mbs.CreateSpringDamper(itemNumbers=[bodies[i], bodies[i + 1]], stiffness=stiffness, damping=damping)
        mbs.CreateForce(itemNumber=masses[-1], loadVector=[force, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
