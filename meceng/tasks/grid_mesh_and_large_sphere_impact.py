"""Task 45 (level 2): grid mesh and large sphere impact — a large ball falls into a pre-tensioned net.

The net is an n x n grid of mass points (n = 3..5) connected by linear springs to each other and to
fixed points on a square frame (ground); its relaxed spring length is shorter than the grid spacing,
so the flat net is pre-tensioned. A large sphere (mass point) is thrown down onto the net centre and
touches the net nodes through sphere-sphere contacts (one per node). The grid is kept small so that
every instance solves in well under a second; the 0.4 s end time covers the impact, the deepest
deflection and the rebound. The moderate contact stiffness and fixed contact steps
(useRecommendedStepSize = False) keep a re-ordered but correct model within round-off of the ground
truth.

Physics checks: with e = 1 and no spring damping the total energy (kinetic, gravitational, spring and
contact energy) is conserved; the motion keeps the symmetry of the set-up (mirror x <-> y and the
sphere stays on the vertical through the centre); free flight before the first contact.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=45,
    name="grid mesh and large sphere impact",
    level="2",
    description="""
        A large sphere falls onto a horizontal net. The net consists of grid points
        P(i, j) = [i*a, j*a, 0] with spacing a = {spacing} m and i, j = 0, ..., n+1 for n = {n}:
        the points with i or j equal to 0 or n+1 form a fixed square frame (points on the ground),
        the n x n inner points (i, j = 1, ..., n) are mass points with mass m = {node_mass} kg each,
        created in the order j = 1, ..., n (outer loop), i = 1, ..., n (inner loop). Every pair of
        neighbouring grid points, P(i, j) - P(i+1, j) and P(i, j) - P(i, j+1), is connected by a
        linear spring-damper with stiffness k = {spring_stiffness} N/m, no damping and the relaxed
        length L0 = (1 - {prestrain})*a, so that the flat net is pre-tensioned; pairs of two frame
        points get no spring. A spring to a frame point connects the ground object (first item,
        created at [0, 0, 0], with the frame point as localPosition0) and the inner mass point.
        Create the springs in x-direction first (for j = 1, ..., n and i = 0, ..., n between P(i, j)
        and P(i+1, j)), then those in y-direction (for i = 1, ..., n and j = 0, ..., n between
        P(i, j) and P(i, j+1)). The sphere is a mass point with mass M = {sphere_mass} kg and
        radius R = {sphere_radius} m; its center starts at [c, c, R + 0.05] m with c = (n+1)*a/2,
        i.e. above the center of the net, with the initial velocity [0, 0, -{velocity}] m/s.
        Gravity g = 9.81 m/s^2 acts in the negative z-direction on the sphere and on all net mass
        points. The sphere touches the net nodes through one sphere-sphere contact per inner mass
        point (sphere first, node second, node radius 0.01 m, in the creation order of the mass
        points) with contact stiffness k_c = {contact_stiffness} N/m, no additional contact
        damping, the impact model 2 and a restitution coefficient e = {restitution}; friction is
        neglected. Create the ground, the net mass points, the springs, the sphere and then the
        contacts.
    """,
    open_description="""
        A large ball falls into a horizontal, pre-tensioned net. The net is a square grid of points
        P(i, j) = [i*a, j*a, 0] with spacing a = {spacing} m and i, j = 0, ..., n+1, n = {n}. The
        points with i or j equal to 0 or n+1 form a fixed square frame; the n x n inner points (i,
        j = 1, ..., n) are point masses m = {node_mass} kg. Every pair of neighbouring grid points,
        P(i, j) - P(i+1, j) and P(i, j) - P(i, j+1), is connected by a massless linear spring,
        stiffness k = {spring_stiffness} N/m, no damping, unstretched length
        L0 = (1 - {prestrain})*a, so the flat net is under tension; two frame points are not
        connected. The ball is a point mass M = {sphere_mass} kg (no rotation) with the contact
        radius R = {sphere_radius} m; its centre starts at [c, c, R + 0.05] m with c = (n+1)*a/2,
        i.e. above the centre of the net, with the velocity [0, 0, -{velocity}] m/s. The net nodes
        start at rest at their grid positions. Gravity g = 9.81 m/s^2 acts in the negative
        z-direction on the ball and on all net masses. The ball touches the net only at its inner
        nodes, each of which is a small sphere of radius 0.01 m for this purpose (the springs
        themselves have no contact); every ball-node contact is a penalty contact: while the two
        spheres overlap, a linear spring of stiffness k_c = {contact_stiffness} N/m acts on the
        overlap along the line of centres, with no viscous damping, plus the hysteresis damping of
        Gonthier et al. / Carvalho-Martins that gives the coefficient of restitution
        e = {restitution}; no friction.
    """,
    params=(
        Param("n", 3, 5, integer=True),
        Param("spacing", 0.1, 0.2, "m"),
        Param("node_mass", 0.01, 0.05, "kg"),
        Param("spring_stiffness", 1000.0, 3000.0, "N/m"),
        Param("prestrain", 0.02, 0.1, "", digits=2),
        Param("sphere_mass", 0.2, 1.0, "kg"),
        Param("sphere_radius", 0.2, 0.4, "m"),
        Param("velocity", 1.0, 2.0, "m/s"),
        Param("contact_stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.7, 0.95, "", digits=2),
    ),
    components=("Ground", "MassPoint", "SpringDamper", "SphereSphereContact"),
    model_code="""
        L0 = (1 - prestrain) * spacing
        c = (n + 1) * spacing / 2
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        nodes = {}
        for j in range(1, n + 1):
            for i in range(1, n + 1):
                nodes[(i, j)] = mbs.CreateMassPoint(referencePosition=[i * spacing, j * spacing, 0],
                                                    mass=node_mass, gravity=[0, 0, -9.81])

        def spring(pA, pB):
            if pA in nodes and pB in nodes:
                mbs.CreateSpringDamper(itemNumbers=[nodes[pA], nodes[pB]], stiffness=spring_stiffness,
                                       damping=0, referenceLength=L0)
            else:
                fixed, inner = (pA, pB) if pB in nodes else (pB, pA)
                mbs.CreateSpringDamper(itemNumbers=[oGround, nodes[inner]],
                                       localPosition0=[fixed[0] * spacing, fixed[1] * spacing, 0],
                                       stiffness=spring_stiffness, damping=0, referenceLength=L0)

        for j in range(1, n + 1):
            for i in range(0, n + 1):
                spring((i, j), (i + 1, j))
        for i in range(1, n + 1):
            for j in range(0, n + 1):
                spring((i, j), (i, j + 1))
        oSphere = mbs.CreateMassPoint(referencePosition=[c, c, sphere_radius + 0.05],
                                      initialVelocity=[0, 0, -velocity],
                                      mass=sphere_mass, gravity=[0, 0, -9.81])
        for j in range(1, n + 1):
            for i in range(1, n + 1):
                mbs.CreateSphereSphereContact(itemNumbers=[oSphere, nodes[(i, j)]],
                                              spheresRadii=[sphere_radius, 0.01],
                                              contactStiffness=contact_stiffness, contactDamping=0,
                                              impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=0.4,
        steps=4000,
        extra=("simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False",),
    ),
)
