"""Task 18 (level 1): n-pendulum elastic spring — a chain of n identical mass points on n identical
elastic strings (spring-dampers) hanging from ground, in the x-y plane under gravity; n = 2..6 is
drawn per instance.

The chain starts straight, deflected by at most 15 degrees, with relaxed springs, and the springs are
stiff (sqrt(k/m) >= 44 rad/s; the static stretch of the top spring n*m*g/k stays below 15 % of its
length), so the motion is regular over the simulated 2 s and a re-ordered but correct model stays
within the 1e-5 solution tolerance.

Physics checks: mechanical energy (kinetic + gravity + springs) minus the work dissipated by the
dampers stays equal to the initial energy; the start state; planar motion.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=18,
    name="n-pendulum elastic spring",
    level="1",
    description="""
        An n-pendulum with elastic springs moving in the x-y plane: a chain of n = {n_masses}
        identical mass points (index i = 1 to n), each with mass m = {mass} kg, connected by n
        identical linear spring-dampers with stiffness k = {stiffness} N/m and damping
        coefficient d = {damping} N*s/m. Spring-damper 1 connects a fixed support (ground) at
        [0, 0, 0] with mass point 1, and spring-damper i (i = 2 to n) connects mass point i-1 with
        mass point i. Initially the chain is straight and deflected by phi0 = {angle_deg} degrees
        (converted to radians) from the downward vertical towards positive x, i.e. mass point i is
        at p_i = [i*L*sin(phi0), -i*L*cos(phi0), 0] with L = {length} m; use p_i as the reference
        positions, so every spring is relaxed in the reference configuration (relaxed length L).
        All mass points start from rest. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction on every mass point. Create the ground, then the mass points in the order of
        their index, then the spring-dampers in the order of their index.
    """,
    open_description="""
        A chain pendulum with elastic strings in the x-y plane: n = {n_masses} identical point
        masses, each of mass {mass} kg, numbered i = 1 to n from the top. Point mass 1 hangs from
        a fixed pivot at the origin [0, 0, 0] on a massless linear spring-damper, and point mass i
        (i = 2 to n) hangs from point mass i-1 on another such spring-damper. All n spring-dampers
        are equal: unstretched length L = {length} m, stiffness k = {stiffness} N/m and damping
        coefficient d = {damping} N*s/m; each pulls or pushes along the line between its two ends
        with the force k times its stretch plus d times the rate of change of its length. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on every point mass. At the start all
        point masses are at rest, every spring is unstretched and the chain is straight, turned
        {angle_deg} degrees from hanging straight down towards positive x: point mass i is at
        [i*L*sin(phi0), -i*L*cos(phi0), 0] with phi0 = {angle_deg} degrees.
    """,
    params=(
        Param("n_masses", 2, 6, "", integer=True),
        Param("mass", 0.2, 1.0, "kg"),
        Param("length", 0.2, 0.6, "m"),
        Param("stiffness", 2000.0, 10000.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
        Param("angle_deg", 5.0, 15.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        masses = []
        for i in range(1, n_masses + 1):
            masses.append(mbs.CreateMassPoint(referencePosition=[i * length * np.sin(phi0),
                                                                 -i * length * np.cos(phi0), 0],
                                              mass=mass, gravity=[0, -gravity, 0]))
        bodies = [oGround] + masses
        for i in range(n_masses):
            mbs.CreateSpringDamper(itemNumbers=[bodies[i], bodies[i + 1]], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
