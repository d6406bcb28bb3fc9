"""Task 33 (level 2): elastic chain — n mass points on n + 1 pretensioned spring-dampers, hung
between two ground points and released from the straight line under gravity.

The number of mass points n is drawn (3 to 8). The springs are pretensioned (relaxed length below
the spacing), so the straight reference line is an equilibrium without gravity and the sagging
chain oscillates about a well-defined static shape. The mass/stiffness ranges keep the sag moderate
(static sag below about a fifth of the span) and the spring damping makes the motion decay; over
the 2 s the solution is insensitive to round-off from a different order of adding the items
(checked with reversed connectors and the ground created last).

Physics checks: with d = 0 the total energy (kinetic + gravity + spring) is conserved; the static
equilibrium of the model (static solver, out-of-plane coordinates locked) agrees with the one
computed independently (Newton's method on the spring network); the motion is symmetric about the
middle of the span.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=33,
    name="elastic chain",
    level="2",
    description="""
        An elastic chain of n = {n_masses} mass points hanging between two fixed ground points
        A = [0, 0, 0] and B = [{span}, 0, 0]. The mass points (index i = 1 to n) each have mass
        m = {mass} kg; their reference positions lie on the straight line between A and B,
        p_i = [i*h, 0, 0] with the spacing h = L/(n + 1) and L = {span} m. Neighbouring points of the
        chain are connected by n + 1 identical linear spring-dampers with stiffness
        k = {stiffness} N/m and damping coefficient d = {damping} N*s/m: ground point A with mass
        point 1, mass point i with mass point i + 1 (i = 1 to n - 1), and ground point B with mass
        point n. The chain is pretensioned: every spring has the relaxed length (reference length)
        l0 = {length_ratio}*h, shorter than the spacing h. All mass points start from rest in their
        reference positions. Gravity g = {gravity} m/s^2 acts in the negative y-direction on all mass
        points. Create the ground, then the mass points in the order of their index, then the
        spring-dampers in the order from A to B.
    """,
    open_description="""
        An elastic chain of n = {n_masses} equal point masses, each of mass {mass} kg, hanging
        between two fixed points A = [0, 0, 0] and B = [{span}, 0, 0], L = {span} m apart. At the
        start the point masses lie evenly spaced on the straight line from A to B, at
        [i*h, 0, 0] for i = 1 to n, with the spacing h = L/(n + 1). Neighbours along the chain are
        joined by n + 1 identical massless linear spring-dampers acting along the line between
        their two ends: A with mass 1, mass i with mass i + 1, and mass n with B. Each has
        stiffness k = {stiffness} N/m, damping coefficient d = {damping} N*s/m (force proportional
        to the rate of change of its length) and the unstretched length {length_ratio}*h, shorter
        than the spacing, so the straight chain starts pretensioned. All masses start from rest.
        Gravity g = {gravity} m/s^2 acts in the negative y-direction; there is no other force.
    """,
    params=(
        Param("n_masses", 3, 8, integer=True),
        Param("span", 1.0, 3.0, "m"),
        Param("mass", 0.05, 0.5, "kg"),
        Param("stiffness", 500.0, 5000.0, "N/m"),
        Param("damping", 0.5, 5.0, "N*s/m"),
        Param("length_ratio", 0.8, 0.95, ""),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        h = span / (n_masses + 1)
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        masses = []
        for i in range(1, n_masses + 1):
            masses.append(mbs.CreateMassPoint(referencePosition=[i * h, 0, 0], mass=mass,
                                              gravity=[0, -gravity, 0]))
        mbs.CreateSpringDamper(itemNumbers=[oGround, masses[0]], localPosition0=[0, 0, 0],
                               referenceLength=length_ratio * h, stiffness=stiffness, damping=damping)
        for i in range(n_masses - 1):
            mbs.CreateSpringDamper(itemNumbers=[masses[i], masses[i + 1]],
                                   referenceLength=length_ratio * h, stiffness=stiffness, damping=damping)
        mbs.CreateSpringDamper(itemNumbers=[oGround, masses[-1]], localPosition0=[span, 0, 0],
                               referenceLength=length_ratio * h, stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
