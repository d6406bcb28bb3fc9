"""Task 44 (level 2): billiard with 4 spheres — a cue ball breaks a triangle of three balls.

Four equal balls (mass points) move in the plane z = 0 of a frictionless table (gravity is balanced
by the table and neglected, so the balls stay in the plane); a sphere-sphere contact acts between
every pair. The cue ball hits the apex ball slightly off-centre, which then hits the two rear balls.
The speed and distance ranges put the first impact at 0.06-0.25 s, so the 0.5 s end time covers the
whole break. The moderate contact stiffness (1e4-5e4 N/m) and fixed contact steps
(useRecommendedStepSize = False) keep a re-ordered but correct model within round-off of the ground
truth.

Physics checks: total momentum conserved exactly; kinetic energy never increases and is kept for
e = 1; a head-on impact of the cue ball on the apex ball with a rack far away gives the classical
velocities v*(1 - e)/2 and v*(1 + e)/2.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=44,
    name="billiard with 4 spheres",
    level="2",
    description="""
        A billiard break with 4 equal balls (index 0 to 3) on a frictionless horizontal table in the
        x-y plane. Each ball is modeled as a mass point with mass m = {mass} kg and radius
        r = {radius} m; the table is not modeled (no ground object) and gravity is neglected, so all
        balls stay in the plane z = 0. The cue ball 0 starts at [0, {offset}, 0] m with the initial velocity
        [{velocity}, 0, 0] m/s. The other three balls are at rest in a triangle: with the center
        distance s = 2*r + {gap} m (a gap of {gap} m between neighbouring balls), ball 1 is at
        [{distance}, 0, 0] m, ball 2 at [{distance} + s*sqrt(3)/2, s/2, 0] m and ball 3 at
        [{distance} + s*sqrt(3)/2, -s/2, 0] m. Every pair of balls has a sphere-sphere contact with
        contact stiffness k = {stiffness} N/m, no additional contact damping, the impact model 2
        and a restitution coefficient e = {restitution}; friction is neglected. Create the balls in
        the order of their index, then the contacts for the pairs (0, 1), (0, 2), (0, 3), (1, 2),
        (1, 3), (2, 3) in this order, with the lower index as the first item.
    """,
    open_description="""
        A billiard break with 4 equal balls (index 0 to 3), each of mass m = {mass} kg and radius
        r = {radius} m, treated as point masses (no rotation) that slide without friction in the
        horizontal plane z = 0; gravity is balanced by the table and left out, so nothing acts on
        the balls but their contacts. Cue ball 0 starts at [0, {offset}, 0] m with the velocity
        [{velocity}, 0, 0] m/s. The other three balls are at rest in a triangle: with the centre
        distance s = 2*r + {gap} m (a gap of {gap} m between neighbouring balls), ball 1 is at
        [{distance}, 0, 0] m, ball 2 at [{distance} + s*sqrt(3)/2, s/2, 0] m and ball 3 at
        [{distance} + s*sqrt(3)/2, -s/2, 0] m. Any two balls can collide; each contact is a penalty
        contact: while the two balls overlap, a linear spring of stiffness k = {stiffness} N/m acts
        on the overlap along the line of centres, with no viscous damping, plus the hysteresis
        damping of Gonthier et al. / Carvalho-Martins that gives the coefficient of restitution
        e = {restitution}; no friction.
    """,
    params=(
        Param("mass", 0.1, 0.3, "kg"),
        Param("radius", 0.025, 0.04, "m"),
        Param("velocity", 2.0, 4.0, "m/s"),
        Param("offset", 0.002, 0.01, "m", digits=2),
        Param("distance", 0.3, 0.5, "m"),
        Param("gap", 0.002, 0.01, "m", digits=2),
        Param("stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.8, 0.98, "", digits=2),
    ),
    components=("MassPoint", "SphereSphereContact"),
    model_code="""
        s = 2 * radius + gap
        positions = [[0, offset, 0],
                     [distance, 0, 0],
                     [distance + s * np.sqrt(3) / 2, s / 2, 0],
                     [distance + s * np.sqrt(3) / 2, -s / 2, 0]]
        balls = []
        for i in range(4):
            v0 = [velocity, 0, 0] if i == 0 else [0, 0, 0]
            balls.append(mbs.CreateMassPoint(referencePosition=positions[i], initialVelocity=v0, mass=mass))
        for i, j in [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]:
            mbs.CreateSphereSphereContact(itemNumbers=[balls[i], balls[j]], spheresRadii=[radius, radius],
                                          contactStiffness=stiffness, contactDamping=0,
                                          impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=0.5,
        steps=5000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
