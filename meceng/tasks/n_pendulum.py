"""Task 13 (level 1): n-pendulum — a chain of n identical mass points on n massless rigid rods
(distance constraints) hanging from ground, in the x-y plane under gravity; n = 2..6 is drawn per
instance.

Multiple pendulums are chaotic at large amplitudes. The chain starts straight and deflected by at
most 12 degrees, where the motion is close to the linear normal-mode superposition and regular over
the simulated 2 s, so a re-ordered but correct model stays within the 1e-5 solution tolerance.

Physics checks: total energy conserved (no damping), all rod lengths kept, planar motion; the
support force of rod 1 balances gravity and the inertia forces of all masses (which catches the
mass, since the motion itself does not depend on it); at a small deflection the motion equals the
superposition of the linear normal modes of M*theta'' + K*theta = 0 with
M_ij = m*L^2*(n - max(i, j)), K_ii = m*g*L*(n - i) (0-based).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=13,
    name="n-pendulum",
    level="1",
    description="""
        An n-pendulum moving in the x-y plane: a chain of n = {n_masses} identical mass points
        (index i = 1 to n), each with mass m = {mass} kg, connected by n massless rigid rods of
        length L = {length} m, each modeled as a distance constraint with distance L. Rod 1
        connects a fixed support (ground) at [0, 0, 0] with mass point 1, and rod i (i = 2 to n)
        connects mass point i-1 with mass point i. Initially the chain is straight and deflected
        by phi0 = {angle_deg} degrees (converted to radians) from the downward vertical towards
        positive x, i.e. mass point i is at p_i = [i*L*sin(phi0), -i*L*cos(phi0), 0]; use p_i as
        the reference positions. All mass points start from rest. Gravity g = {gravity} m/s^2
        acts in the negative y-direction on every mass point. Create the ground, then the mass
        points in the order of their index, then the distance constraints in the order of the
        rods.
    """,
    open_description="""
        A chain pendulum in the x-y plane: n = {n_masses} identical point masses, each of mass
        {mass} kg, numbered i = 1 to n from the top. Point mass 1 hangs from a fixed pivot at the
        origin [0, 0, 0] on a massless rigid rod of length L = {length} m, and point mass i (i = 2
        to n) hangs from point mass i-1 on another massless rigid rod of length L. The rods are
        pinned at both ends without friction: each only keeps the distance between its two ends at
        L. Gravity g = {gravity} m/s^2 acts in the negative y-direction on every point mass. At
        the start all point masses are at rest and the chain is straight, turned {angle_deg}
        degrees from hanging straight down towards positive x: point mass i is at the distance i*L
        from the pivot along that line, at [i*L*sin(phi0), -i*L*cos(phi0), 0] with phi0 =
        {angle_deg} degrees.
    """,
    params=(
        Param("n_masses", 2, 6, "", integer=True),
        Param("mass", 0.2, 2.0, "kg"),
        Param("length", 0.2, 0.6, "m"),
        Param("angle_deg", 3.0, 12.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint"),
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
            mbs.CreateDistanceConstraint(itemNumbers=[bodies[i], bodies[i + 1]], distance=length)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
