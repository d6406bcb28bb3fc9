"""Task 42 (level 2): pendulum wall impacting — a ball on a massless rod swings against a vertical wall.

The bob is a rigid sphere (sphere-triangle contact needs a rigid body) held by a distance
constraint; the wall is a vertical triangle fixed to ground in the plane x = r, so the hanging bob
just touches it and every impact happens at the lowest point with a purely horizontal velocity. The
1.5 s end time covers one to four impacts (pendulum periods 1.1-2 s). Moderate contact stiffness
(1e4-5e4 N/m) and fixed contact steps (discontinuous.useRecommendedStepSize = False, see
sphere_sphere_impact) keep a re-ordered but correct model within round-off of the ground truth.
The sphere radius enters only the graph: wall and sphere surface shift together, and the free spin
of the bob is not excited.

Physics checks: the rod length is kept; the speed just before the first impact follows from energy
conservation, sqrt(2*g*L*(1 - cos(phi0))); the rebound speed is e times the impact speed.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=42,
    name="pendulum wall impacting",
    level="2",
    description="""
        A pendulum swinging in the x-z plane impacts a vertical wall. The bob is a homogeneous
        sphere with mass m = {mass} kg and radius r = {radius} m, modeled as a rigid body with
        inertia InertiaSphere(mass=m, radius=r). It hangs from the fixed support point [0, 0, 0]
        (ground) on a massless rigid rod of length L = {length} m, modeled as a distance
        constraint between ground and the sphere's center. Initially the rod is deflected by
        phi0 = {angle_deg} degrees from the downward vertical towards negative x, i.e. the sphere's
        center is at p0 = [-L*sin(phi0), 0, -L*cos(phi0)]; use p0 as the sphere's reference
        position (identity reference rotation); the sphere starts from rest. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. The wall is the vertical plane x = r,
        which the sphere just touches when hanging at rest; it is represented by one triangle fixed
        to the ground with the points [r, -L, -2*L], [r, L, -2*L] and [r, 0, 0] (in this order). The
        impact is modeled with a sphere-triangle contact between the sphere and the ground object
        with contact stiffness k = {stiffness} N/m, no additional contact damping, the impact model
        2 and a restitution coefficient e = {restitution}; friction is neglected. Create the ground,
        the sphere, the distance constraint and then the contact.
    """,
    open_description="""
        A pendulum swinging in the x-z plane strikes a vertical wall. The bob is a homogeneous solid
        sphere (a rigid body with mass and rotational inertia) of mass m = {mass} kg and radius
        r = {radius} m. Its centre is held at the distance L = {length} m from the fixed pivot
        [0, 0, 0] by a massless rigid rod, frictionless at both ends (the bob is free to turn about
        its centre). Gravity g = {gravity} m/s^2 acts in the negative z-direction. At the start the
        rod is turned {angle_deg} degrees from hanging straight down, towards negative x, in the x-z
        plane (the bob's centre at x < 0, z < 0), and the bob is at rest, without rotation. The wall
        is the fixed vertical plane x = r, which the bob just touches when it hangs straight down (a
        flat triangle with the corners [r, -L, -2*L], [r, L, -2*L] and [r, 0, 0], which covers where
        the bob touches it). The impact of bob and wall is a penalty contact: while the bob and the
        wall overlap, a linear spring of stiffness k = {stiffness} N/m acts on the overlap normal to
        the contact surface, with no viscous damping, plus the hysteresis damping of Gonthier et al.
        / Carvalho-Martins that gives the coefficient of restitution e = {restitution}; no friction.
    """,
    params=(
        Param("mass", 0.1, 1.0, "kg"),
        Param("radius", 0.02, 0.05, "m"),
        Param("length", 0.3, 1.0, "m"),
        Param("angle_deg", 10.0, 60.0, "deg", digits=2),
        Param("stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.5, 0.95, "", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaSphere", "DistanceConstraint", "SphereTriangleContact"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oSphere = mbs.CreateRigidBody(referencePosition=[-length * np.sin(phi0), 0, -length * np.cos(phi0)],
                                      referenceRotationMatrix=np.eye(3),
                                      inertia=InertiaSphere(mass=mass, radius=radius),
                                      gravity=[0, 0, -gravity])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oSphere], distance=length)
        mbs.CreateSphereTriangleContact(itemNumbers=[oSphere, oGround], sphereRadius=radius,
                                        trianglePoints=exu.Vector3DList([[radius, -length, -2 * length],
                                                                         [radius, length, -2 * length],
                                                                         [radius, 0, 0]]),
                                        contactStiffness=stiffness, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=1.5,
        steps=15000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
