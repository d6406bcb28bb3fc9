"""Task 40 (level 2): falling mass point with ground contact — a ball (mass point) thrown from a
height bounces on the ground.

A mass point can only have sphere-sphere contact (sphere-triangle contact needs a rigid body), so
the ground is represented by a very large sphere (radius 1000 m) fixed to the ground object, whose
top touches the plane z = 0; over the at most 1 m of horizontal travel it deviates from the plane
by less than 0.5 mm. The heights put the first impact at 0.2-0.45 s, so the 1 s end time contains
one or two impacts. Moderate contact stiffness (1e4-5e4 N/m) and fixed contact steps
(discontinuous.useRecommendedStepSize = False, see sphere_sphere_impact) keep a re-ordered but
correct model within round-off of the ground truth.

Physics checks: free flight is a parabola; the vertical velocity after the impact is -e times the
one before (measured where the gap closes and opens again); the horizontal velocity is kept.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=40,
    name="falling mass point with ground contact",
    level="2",
    description="""
        A ball modeled as a mass point with mass m = {mass} kg and radius r = {radius} m falls
        onto the ground under gravity g = {gravity} m/s^2 acting in the negative z-direction. It
        starts at [0, 0, {height}] m with the initial velocity [{velocity}, 0, 0] m/s. The ground
        is the plane z = 0; it is represented by a very large sphere with radius R = 1000 m fixed
        to the ground object, whose center lies 1000 m below the origin, so that its top touches
        the plane z = 0. Create the ground object at [0, 0, 0] and model the ground contact with a
        sphere-sphere contact between the ground object (first item, sphere radius R, sphere
        center given by localPosition0 = [0, 0, -1000] in ground coordinates) and the mass point
        (second item, sphere radius r, localPosition1 = [0, 0, 0]) with contact stiffness
        k = {stiffness} N/m, no additional contact damping, the impact model 2 and a restitution
        coefficient e = {restitution}. Friction is neglected. Create the ground, the mass point and
        then the contact.
    """,
    open_description="""
        A ball of mass m = {mass} kg and radius r = {radius} m, treated as a point mass (no
        rotation) at its centre, is thrown horizontally and bounces on the ground. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. The ball's centre starts at
        [0, 0, {height}] m with the velocity [{velocity}, 0, 0] m/s. The ground is the plane z = 0,
        represented as the surface of a fixed sphere of radius 1000 m whose centre is at
        [0, 0, -1000] m (its top touches the plane z = 0 at the origin). The ground contact is a
        penalty contact: while the ball and the ground sphere overlap, a linear spring of stiffness
        k = {stiffness} N/m acts on the overlap along the line of centres, with no viscous damping,
        plus the hysteresis damping of Gonthier et al. / Carvalho-Martins that gives the coefficient
        of restitution e = {restitution}; no friction.
    """,
    params=(
        Param("mass", 0.1, 1.0, "kg"),
        Param("radius", 0.02, 0.1, "m"),
        Param("height", 0.3, 1.0, "m"),
        Param("velocity", 0.1, 1.0, "m/s"),
        Param("stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.5, 0.95, "", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SphereSphereContact"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBall = mbs.CreateMassPoint(referencePosition=[0, 0, height], initialVelocity=[velocity, 0, 0],
                                    mass=mass, gravity=[0, 0, -gravity])
        mbs.CreateSphereSphereContact(itemNumbers=[oGround, oBall], localPosition0=[0, 0, -1000],
                                      localPosition1=[0, 0, 0], spheresRadii=[1000, radius],
                                      contactStiffness=stiffness, contactDamping=0,
                                      impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=1.0,
        steps=10000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
