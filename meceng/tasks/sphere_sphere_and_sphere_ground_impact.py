"""Task 41 (level 2): sphere-sphere and sphere-ground impact — two stacked balls dropped on the floor.

Two rigid spheres are dropped from rest, the upper (light) one a small gap above the lower (heavy)
one and slightly offset sideways. The lower sphere hits the floor (a triangle fixed to ground,
sphere-triangle contact, which needs rigid bodies), rebounds and hits the falling upper sphere
(sphere-sphere contact), which is thrown up and sideways. The gap (at least 0.1 m) separates the floor impact from
the sphere-sphere impact; the 0.6 s end time covers the first floor impact (at most 0.4 s), the
sphere-sphere impact and one or two more floor impacts of the lower sphere. Moderate contact stiffness (2e4-5e4 N/m) and fixed
contact steps (discontinuous.useRecommendedStepSize = False, see sphere_sphere_impact) keep a
re-ordered but correct model within round-off of the ground truth.

Physics checks: free fall until the first floor impact; rebound velocity ratio e at the floor; while
no sphere touches the floor the total momentum changes only by the weight, (m0 + m1)*g*t, and the
relative normal velocity of the sphere-sphere impact is reversed with factor e.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=41,
    name="sphere-sphere and sphere-ground impact",
    level="2",
    description="""
        Two balls, one above the other, are dropped onto the floor. Both are homogeneous spheres
        modeled as rigid bodies with inertia InertiaSphere(mass=m, radius=r) (identity reference
        rotation). The lower sphere 0 has mass m0 = {mass0} kg and radius r0 = {radius0} m; its
        center starts at [0, 0, {height}] m. The upper sphere 1 has mass m1 = {mass1} kg and radius
        r1 = {radius1} m; its center starts at [{offset}, 0, {height} + r0 + r1 + {gap}] m, i.e. a gap
        of {gap} m above sphere 0 and offset sideways by {offset} m. Both start from rest. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. The floor is the plane z = 0,
        represented by one triangle fixed to the ground with the points [-1, -1, 0], [2, -1, 0] and
        [-1, 2, 0] (in this order). All contacts use the contact stiffness k = {stiffness} N/m, no
        additional contact damping, the impact model 2 and the restitution coefficient
        e = {restitution}; friction is neglected. Create the ground, sphere 0 and sphere 1, then a
        sphere-triangle contact between sphere 0 and the ground, a sphere-triangle contact between
        sphere 1 and the ground, and a sphere-sphere contact between sphere 0 and sphere 1 (in this
        order).
    """,
    open_description="""
        Two balls, one above the other, are dropped onto a floor. Both are homogeneous solid spheres
        (rigid bodies with mass and rotational inertia). The lower ball 0 has mass m0 = {mass0} kg
        and radius r0 = {radius0} m; its centre starts at [0, 0, {height}] m. The upper ball 1 has
        mass m1 = {mass1} kg and radius r1 = {radius1} m; its centre starts at
        [{offset}, 0, {height} + r0 + r1 + {gap}] m, i.e. with a gap of {gap} m between the balls
        and offset sideways by {offset} m along x. Both start at rest, without rotation. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. The floor is the fixed plane z = 0 (a
        flat triangle with the corners [-1, -1, 0], [2, -1, 0] and [-1, 2, 0], which covers
        everywhere the balls touch it). Each ball can hit the floor, and the balls can hit each
        other; every one of these contacts is a penalty contact: while the two surfaces overlap, a
        linear spring of stiffness k = {stiffness} N/m acts on the overlap normal to the contact
        surface, with no viscous damping, plus the hysteresis damping of Gonthier et al. /
        Carvalho-Martins that gives the coefficient of restitution e = {restitution}; no friction.
    """,
    params=(
        Param("mass0", 0.2, 0.6, "kg"),
        Param("radius0", 0.05, 0.08, "m"),
        Param("mass1", 0.02, 0.1, "kg"),
        Param("radius1", 0.02, 0.04, "m"),
        Param("height", 0.3, 0.8, "m"),
        Param("gap", 0.1, 0.2, "m"),
        Param("offset", 0.002, 0.02, "m", digits=2),
        Param("stiffness", 2e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.6, 0.95, "", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaSphere", "SphereTriangleContact", "SphereSphereContact"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oSphere0 = mbs.CreateRigidBody(referencePosition=[0, 0, height],
                                       referenceRotationMatrix=np.eye(3),
                                       inertia=InertiaSphere(mass=mass0, radius=radius0),
                                       gravity=[0, 0, -gravity])
        oSphere1 = mbs.CreateRigidBody(referencePosition=[offset, 0, height + radius0 + radius1 + gap],
                                       referenceRotationMatrix=np.eye(3),
                                       inertia=InertiaSphere(mass=mass1, radius=radius1),
                                       gravity=[0, 0, -gravity])
        floor = exu.Vector3DList([[-1, -1, 0], [2, -1, 0], [-1, 2, 0]])
        mbs.CreateSphereTriangleContact(itemNumbers=[oSphere0, oGround], sphereRadius=radius0,
                                        trianglePoints=floor, contactStiffness=stiffness, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=restitution)
        mbs.CreateSphereTriangleContact(itemNumbers=[oSphere1, oGround], sphereRadius=radius1,
                                        trianglePoints=floor, contactStiffness=stiffness, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=restitution)
        mbs.CreateSphereSphereContact(itemNumbers=[oSphere0, oSphere1], spheresRadii=[radius0, radius1],
                                      contactStiffness=stiffness, contactDamping=0,
                                      impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=0.6,
        steps=6000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
