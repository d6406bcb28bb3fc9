"""Task 31 (level 2): four-bar mechanism / point masses — two mass points on three massless rods
(distance constraints) between two ground pivots, swinging under gravity in the x-y plane.

The z-coordinates of the two mass points are fixed by coordinate constraints, so the model has
6 coordinates, 5 independent constraints and one degree of freedom. The link lengths are drawn
from ranges where the linkage is a Grashof crank-rocker with a margin of at least 0.05 m in every
collinearity condition: the four joints can never become collinear, so the constraint Jacobian
never loses rank and the configuration branch (joint C on the left of the line from B to D) is
kept. A conservative one-degree-of-freedom system is not chaotic, so 2 s are safe for the
re-ordering tolerance.

Physics checks: the simulated crank angle satisfies the one-degree-of-freedom equation of motion
M(theta)*theta'' + M'(theta)/2*theta'^2 + V'(theta) = 0 of the linkage (M and V recomputed from the
parameters, residual along the trajectory by central differences); the rod lengths and z = 0 are
kept.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=31,
    name="four-bar mechanism / point masses",
    level="2",
    description="""
        A planar four-bar mechanism moving in the x-y plane, modeled with two mass points and three
        massless rigid links. The ground pivots are A = [0, 0, 0] (crank pivot) and
        D = [{ground_length}, 0, 0] (rocker pivot), i.e. the ground link has length
        d = {ground_length} m. The crank AB has length a = {crank_length} m, the coupler BC length
        b = {coupler_length} m and the rocker CD length c = {rocker_length} m. Mass point B (the joint
        between crank and coupler) has mass m_B = {mass_b} kg and mass point C (the joint between
        coupler and rocker) has mass m_C = {mass_c} kg. The three links are modeled as distance
        constraints with the distances a, b and c: the crank between ground point A and mass point B,
        the coupler between mass point B and mass point C, and the rocker between ground point D and
        mass point C. Initially the crank is at the angle theta0 = {crank_angle_deg} degrees,
        measured counter-clockwise from the positive x-axis (converted to radians), so
        B = [a*cos(theta0), a*sin(theta0), 0]. Joint C is the intersection of the circles of radius
        b about B and radius c about D on the left of the direction from B to D: with e = D - B,
        f = |e|, s = (b^2 - c^2 + f^2)/(2*f) and h = sqrt(b^2 - s^2),
        C = B + (s/f)*e + (h/f)*[-e_y, e_x, 0]. B and C are the reference positions of the mass
        points; both start from rest. Gravity g = {gravity} m/s^2 acts in the negative y-direction
        on both mass points. To keep the mechanism in the x-y plane, the z-coordinate of each mass
        point is fixed to its reference value by a coordinate constraint to ground (coordinate
        index 2). No friction or damping. Create the ground, mass point B, mass point C, then the
        distance constraints of the crank, the coupler and the rocker, then the coordinate
        constraints of B and C.
    """,
    open_description="""
        A planar four-bar linkage in the x-y plane with its mass lumped in two point masses. The
        fixed pivots are A = [0, 0, 0] (crank pivot) and D = [{ground_length}, 0, 0] (rocker
        pivot). A massless rigid crank of length a = {crank_length} m joins A to point mass B
        (m_B = {mass_b} kg), a massless rigid coupler of length b = {coupler_length} m joins B to
        point mass C (m_C = {mass_c} kg), and a massless rigid rocker of length
        c = {rocker_length} m joins C to D. The rods carry force only along their length (ideal
        frictionless pins at both ends), and both point masses are held in the plane z = 0. At the
        start the crank points from A at the angle {crank_angle_deg} degrees measured
        counter-clockwise from the positive x-axis, so B = [a*cos(theta0), a*sin(theta0), 0] with
        theta0 = {crank_angle_deg} degrees; C is the point at distance b from B and c from D that
        lies on the left-hand side of the line from B towards D (above that line). Both masses
        start from rest. Gravity g = {gravity} m/s^2 acts in the negative y-direction; there is no
        friction and no damping.
    """,
    params=(
        Param("ground_length", 0.4, 0.5, "m"),
        Param("crank_length", 0.08, 0.15, "m"),
        Param("coupler_length", 0.4, 0.5, "m"),
        Param("rocker_length", 0.3, 0.4, "m"),
        Param("mass_b", 0.2, 2.0, "kg"),
        Param("mass_c", 0.2, 2.0, "kg"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint", "CoordinateConstraint"),
    model_code="""
        theta0 = crank_angle_deg * np.pi / 180
        pB = np.array([crank_length * np.cos(theta0), crank_length * np.sin(theta0), 0])
        pD = np.array([ground_length, 0, 0])
        e = pD - pB
        f = np.linalg.norm(e)
        s = (coupler_length**2 - rocker_length**2 + f**2) / (2 * f)
        h = np.sqrt(coupler_length**2 - s**2)
        pC = pB + (s / f) * e + (h / f) * np.array([-e[1], e[0], 0])

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oB = mbs.CreateMassPoint(referencePosition=pB, mass=mass_b, gravity=[0, -gravity, 0])
        oC = mbs.CreateMassPoint(referencePosition=pC, mass=mass_c, gravity=[0, -gravity, 0])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oB], localPosition0=[0, 0, 0],
                                     distance=crank_length)
        mbs.CreateDistanceConstraint(itemNumbers=[oB, oC], distance=coupler_length)
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oC], localPosition0=pD,
                                     distance=rocker_length)
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oB], coordinates=[None, 2])
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oC], coordinates=[None, 2])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
