"""Task 43 (level 2): Newton's cradle — the paper's own template (section 2.1).

Four mass points on distance constraints with sphere-sphere contact between neighbours. Contact
makes the solution sensitive; the end time is kept at one swing and a half so that a re-ordered but
correct model stays within the 1e-5 solution tolerance.

Where the text departs from the paper's quote, and why (docs/prompts.md):

- the contact: the paper's "Contact between spheres is modeled with a stiffness k and a
  restitution coefficient e" names neither the pairs nor the damping nor the impact model; the graph
  check compares all three (contactDamping, impactModel, one contact object per pair), and e acts
  only with impact model 2. Ours: "between neighbouring spheres (0-1, 1-2, 2-3) ... no additional
  damping, the impact model 2";
- the creation order: the paper's "Add the spheres in the order of their index" goes on with the
  distance constraints in the same order and then the contacts, as every task text states its order;
- the simulated time: every task text ends with "Simulate the system for T s using N time steps"
  (``TaskModel.instance``), because the code templates ask the model to use them.

Physics check: with e close to 1, the momentum of sphere 0 is passed on to sphere 3.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=43,
    name="Newton's cradle",
    level="2",
    description="""
        A Newton's cradle consisting of 4 identical spheres (index 0 to 3) modeled as mass points.
        Each sphere has a mass m = {mass} kg, a radius r = {radius} m, and is suspended from a fixed
        ceiling (ground) at z = {length} m. Each sphere with index i is connected to the ceiling at
        p_fix,i = [i*(2*{radius}+0.002), 0, {length}] via a distance constraint of length
        L = {length} m. The spheres are aligned along the x-axis. Spheres 1, 2, and 3 are initially
        at rest at their equilibrium positions p_i = [i*(2*{radius}+0.002), 0, 0]. Sphere 0 is
        initially positioned at p_0 = [-{length}, 0, {length}], representing a horizontal
        configuration with the cable taut, and starts from rest. Gravity g = {gravity} m/s^2 acts
        in the negative z-direction. Contact between neighbouring spheres (0-1, 1-2, 2-3) is
        modeled with a sphere-sphere contact with stiffness k = {stiffness} N/m, no additional
        damping, the impact model 2 and a restitution coefficient e = {restitution}. Friction is
        neglected. Add the spheres in the order of their index, then the distance constraints in
        the same order, then the contacts.
    """,
    open_description="""
        A Newton's cradle of 4 identical balls (index 0 to 3), each of mass m = {mass} kg and radius
        r = {radius} m, treated as point masses (no rotation) at their centres. Ball i hangs from
        the fixed suspension point [i*(2*{radius}+0.002), 0, {length}] m on a massless rigid rod of
        length L = {length} m, pinned without friction at both ends, so that the balls hang in a row
        along the x-axis with a gap of 0.002 m between neighbours. Gravity g = {gravity} m/s^2 acts
        in the negative z-direction. Balls 1, 2 and 3 start at rest hanging straight down, their
        centres at [i*(2*{radius}+0.002), 0, 0]. Ball 0 starts at rest lifted sideways until its rod
        is horizontal, its centre at [-{length}, 0, {length}] m. Each pair of neighbouring balls
        (0-1, 1-2, 2-3) can collide; each such contact is a penalty contact: while the two balls
        overlap, a linear spring of stiffness k = {stiffness} N/m acts on the overlap along the line
        of centres, with no viscous damping, plus the hysteresis damping of Gonthier et al. /
        Carvalho-Martins that gives the coefficient of restitution e = {restitution}; no friction.
    """,
    params=(
        Param("mass", 0.05, 0.5, "kg"),
        Param("radius", 0.02, 0.05, "m"),
        Param("length", 0.2, 0.6, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
        Param("stiffness", 1e4, 5e4, "N/m", digits=2),
        Param("restitution", 0.7, 0.99, "", digits=2),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint", "SphereSphereContact"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        spheres = []
        for i in range(4):
            p = [i * (2 * radius + 0.002), 0, 0]
            if i == 0:
                p = [-length, 0, length]
            spheres.append(mbs.CreateMassPoint(referencePosition=p, mass=mass,
                                               gravity=[0, 0, -gravity]))
        for i in range(4):
            mbs.CreateDistanceConstraint(itemNumbers=[oGround, spheres[i]],
                                         localPosition0=[i * (2 * radius + 0.002), 0, length],
                                         distance=length)
        for i in range(3):
            mbs.CreateSphereSphereContact(itemNumbers=[spheres[i], spheres[i + 1]],
                                          spheresRadii=[radius, radius],
                                          contactStiffness=stiffness, contactDamping=0,
                                          impactModel=2, restitutionCoefficient=restitution)
    """,
    sim=SimSettings(
        end_time=0.6,
        steps=6000,
        extra=("simulationSettings.timeIntegration.discontinuous.iterationTolerance = 1e-3",
               # contact would otherwise cut the step in discrete jumps that depend on round-off
               "simulationSettings.timeIntegration.discontinuous.useRecommendedStepSize = False"),
    ),
)
