"""Task 39 (level 2): sphere-sphere impact — two free spheres (mass points) collide once, obliquely.

Sphere 0 moves along x towards sphere 1, which is at rest and offset sideways by less than the sum
of the radii, so exactly one oblique impact happens; gravity is neglected. The contact is the
sphere-sphere penalty contact with impact model 2 (restitution coefficient e). The speed and
distance ranges put the impact at 0.02-0.3 s, well inside the 0.5 s end time. The contact stiffness
is moderate (1e4-5e4 N/m) and the contact's recommended step sizes are switched off
(discontinuous.useRecommendedStepSize = False): with them the adaptive step control takes discrete
decisions that turn a last-bit difference of an input into solution differences near the 1e-5
tolerance; without them a 1e-12 relative change of an input changes the solution by < 1e-9.

Physics checks: total momentum is conserved exactly; for a head-on impact the relative velocity
after the impact is -e times the one before, and the velocities of both spheres follow the
classical impact formulas.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=39,
    name="sphere-sphere impact",
    level="2",
    description="""
        Two spheres collide in free space; gravity is neglected and there is no ground object. Both spheres are modeled as mass
        points (no rotation, no friction). Sphere 0 has mass m0 = {mass0} kg and radius
        r0 = {radius0} m; it starts at [0, 0, 0] with the initial velocity [{velocity}, 0, 0] m/s.
        Sphere 1 has mass m1 = {mass1} kg and radius r1 = {radius1} m; it starts at rest at
        [{distance}, {offset}, 0] m. The impact is modeled with a sphere-sphere contact between
        sphere 0 and sphere 1 (in this order) with contact stiffness k = {stiffness} N/m, no
        additional contact damping, the impact model 2 and a restitution coefficient
        e = {restitution}. Create sphere 0, then sphere 1, then the contact.
    """,
    open_description="""
        Two balls collide once, obliquely, in free space; there is no gravity and no friction, and
        the balls do not rotate, so each ball is a point mass with a contact radius. Ball 0 has mass
        m0 = {mass0} kg and radius r0 = {radius0} m; its centre starts at [0, 0, 0] with the
        velocity [{velocity}, 0, 0] m/s. Ball 1 has mass m1 = {mass1} kg and radius r1 = {radius1}
        m; its centre starts at rest at [{distance}, {offset}, 0] m. The impact is a penalty
        contact: while the two spheres overlap, a linear spring of stiffness k = {stiffness} N/m
        acts on the overlap along the line of centres, with no viscous damping, plus the hysteresis
        damping of Gonthier et al. / Carvalho-Martins that gives the coefficient of restitution
        e = {restitution}; no friction.
    """,
    params=(
        Param("mass0", 0.1, 1.0, "kg"),
        Param("radius0", 0.03, 0.08, "m"),
        Param("mass1", 0.1, 1.0, "kg"),
        Param("radius1", 0.03, 0.08, "m"),
        Param("velocity", 1.5, 3.0, "m/s"),
        Param("distance", 0.3, 0.5, "m"),
        Param("offset", 0.005, 0.04, "m", digits=2),
        Param("stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.5, 0.95, "", digits=2),
    ),
    components=("MassPoint", "SphereSphereContact"),
    model_code="""
        oSphere0 = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[velocity, 0, 0],
                                       mass=mass0)
        oSphere1 = mbs.CreateMassPoint(referencePosition=[distance, offset, 0], mass=mass1)
        mbs.CreateSphereSphereContact(itemNumbers=[oSphere0, oSphere1], spheresRadii=[radius0, radius1],
                                      contactStiffness=stiffness, contactDamping=0,
                                      impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=0.5,
        steps=5000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
