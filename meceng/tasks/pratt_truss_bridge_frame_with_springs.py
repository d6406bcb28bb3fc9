"""Task 38 (level 2): Pratt truss bridge frame with springs — a planar, simply supported Pratt truss
with inclined end posts; nodes are mass points, members are spring-dampers; a pinned support and a
roller support by coordinate constraints; loaded suddenly by gravity and a force at the first panel
point.

The number of panels n = 2*half_panels is drawn (4, 6 or 8). With 2n nodes, 4n - 3 members and 3
support constraints the truss is statically determinate in its plane; all forces lie in the x-y
plane, so the out-of-plane coordinates stay exactly zero (they have no stiffness, but no force
either). The member stiffness is high against node masses and loads (largest displacement below
about 1.5 % of the span), the response is close to linear and not sensitive to the order of adding
items; 1 s with 2000 steps resolves the lowest modes, the numerical damping of the solver removes
the unresolved highest ones. With the stiff members the default Newton tolerances sometimes hit
round-off, the solver then halves single steps, and whether it does depends on the order of adding
items; newton.absoluteTolerance = 1e-8 avoids that. The force acts at B_1, not at mid-span: with
the only unique item (the force) on the symmetry axis, the type-only graph isomorphism (VF2++) of
the mirror-symmetric truss backtracks for 10-50 s at n = 6, 8; off the axis it takes < 0.5 s.

Physics checks: with d = 0 the total energy (kinetic + spring - work of gravity and force) is
conserved; the static equilibrium of the model (static solver, out-of-plane coordinates locked)
agrees with the one computed independently (Newton's method on the spring network); the supports
hold.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel


def _derive(values: dict) -> dict:
    return {"n_panels": 2 * values["half_panels"]}


TASK = TaskModel(
    id=38,
    name="Pratt truss bridge frame with springs",
    level="2",
    description="""
        A planar Pratt truss bridge in the x-y plane with n = {n_panels} panels of length
        a = {panel_length} m and height h = {height} m. The bottom chord nodes are
        B_i = [i*a, 0, 0] for i = 0 to n, the top chord nodes T_i = [i*a, h, 0] for i = 1 to n - 1
        (the end posts are inclined, there are no top nodes above B_0 and B_n). Every node is a mass
        point with mass m = {node_mass} kg at its node position (reference position), starting from
        rest. The members are linear spring-dampers with stiffness k = {stiffness} N/m and damping
        coefficient d = {damping} N*s/m, relaxed in the reference configuration (default reference
        length): the bottom chord members B_i-B_(i+1) for i = 0 to n - 1; the top chord members
        T_i-T_(i+1) for i = 1 to n - 2; the two end posts B_0-T_1 and T_(n-1)-B_n; the verticals
        B_i-T_i for i = 1 to n - 1; and the diagonals, which slope down towards mid-span:
        T_i-B_(i+1) for i = 1 to n/2 - 1 and T_i-B_(i-1) for i = n/2 + 1 to n - 1. Supports: B_0
        is pinned, i.e. its x- and y-coordinates are fixed to their reference values by two
        coordinate constraints to ground (coordinate indices 0 and 1), and B_n rests on a roller,
        i.e. only its y-coordinate is fixed by a coordinate constraint (coordinate index 1); each is
        made with mbs.CreateCoordinateConstraint with itemNumbers=[None, mass point], so no ground
        object is created. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on all mass points, and a constant force
        [0, -{force}, 0] N is applied to the bottom node B_1. Create the mass points B_0 to
        B_n, then T_1 to T_(n-1), then the members in the order given, then the support constraints
        (B_0 x, B_0 y, B_n y), then the force.
    """,
    open_description="""
        A planar Pratt truss bridge in the x-y plane, simply supported, with
        n = 2*{half_panels} = {n_panels} panels of length a = {panel_length} m and height
        h = {height} m. The bottom chord nodes are B_i = [i*a, 0, 0] for i = 0 to n, the top chord
        nodes T_i = [i*a, h, 0] for i = 1 to n - 1 (the end posts are inclined: there are no top
        nodes above B_0 and B_n). Every node, the two support nodes included, is a point mass
        m = {node_mass} kg. The members are massless linear spring-dampers, axial stiffness
        k = {stiffness} N/m and axial damping d = {damping} N*s/m, each unstretched at the node
        positions given above: the bottom chord B_i-B_(i+1) for i = 0 to n - 1; the top chord
        T_i-T_(i+1) for i = 1 to n - 2; the end posts B_0-T_1 and T_(n-1)-B_n; the verticals B_i-T_i
        for i = 1 to n - 1; and the diagonals, which slope down towards mid-span: T_i-B_(i+1) for
        i = 1 to n/2 - 1 and T_i-B_(i-1) for i = n/2 + 1 to n - 1. Supports: B_0 is a pin, its x-
        and y-coordinates are held at their initial values; B_n is a roller, only its y-coordinate
        is held. Nothing else restrains the nodes (no force acts out of the plane). All nodes start
        at rest at these positions. At t = 0 the loads are applied suddenly and stay constant:
        gravity g = {gravity} m/s^2 in the negative y-direction on every node mass, and a force of
        {force} N in the negative y-direction at the bottom node B_1.
    """,
    params=(
        Param("half_panels", 2, 4, integer=True),
        Param("panel_length", 0.5, 1.0, "m"),
        Param("height", 0.6, 1.2, "m"),
        Param("node_mass", 1.0, 5.0, "kg"),
        Param("stiffness", 2e6, 1e7, "N/m"),
        Param("damping", 50.0, 500.0, "N*s/m"),
        Param("force", 500.0, 5000.0, "N"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    derive=_derive,
    components=("MassPoint", "SpringDamper", "CoordinateConstraint", "Force"),
    model_code="""
        bottom = []
        for i in range(n_panels + 1):
            bottom.append(mbs.CreateMassPoint(referencePosition=[i * panel_length, 0, 0], mass=node_mass,
                                              gravity=[0, -gravity, 0]))
        top = {}
        for i in range(1, n_panels):
            top[i] = mbs.CreateMassPoint(referencePosition=[i * panel_length, height, 0], mass=node_mass,
                                         gravity=[0, -gravity, 0])

        members = []
        for i in range(n_panels):
            members.append((bottom[i], bottom[i + 1]))
        for i in range(1, n_panels - 1):
            members.append((top[i], top[i + 1]))
        members += [(bottom[0], top[1]), (top[n_panels - 1], bottom[n_panels])]
        for i in range(1, n_panels):
            members.append((bottom[i], top[i]))
        for i in range(1, n_panels // 2):
            members.append((top[i], bottom[i + 1]))
        for i in range(n_panels // 2 + 1, n_panels):
            members.append((top[i], bottom[i - 1]))
        for item0, item1 in members:
            mbs.CreateSpringDamper(itemNumbers=[item0, item1], stiffness=stiffness, damping=damping)

        mbs.CreateCoordinateConstraint(itemNumbers=[None, bottom[0]], coordinates=[None, 0])
        mbs.CreateCoordinateConstraint(itemNumbers=[None, bottom[0]], coordinates=[None, 1])
        mbs.CreateCoordinateConstraint(itemNumbers=[None, bottom[n_panels]], coordinates=[None, 1])
        mbs.CreateForce(itemNumber=bottom[1], loadVector=[0, -force, 0])
    """,
    sim=SimSettings(
        end_time=1.0,
        steps=2000,
        extra=("simulationSettings.timeIntegration.newton.absoluteTolerance = 1e-8",),
    ),
)
