"""Task 37 (level 2): parallel chord truss frame with springs — a planar cantilever truss with
parallel top and bottom chords; nodes are mass points, members are spring-dampers, the two wall
nodes are ground points; loaded suddenly by gravity and a tip force.

The number of panels n is drawn (2 to 6). Every panel adds two nodes and four members (two chord
members, one vertical, one diagonal), so the truss is statically determinate and stiff in its plane;
all forces lie in the x-y plane, so the out-of-plane coordinates stay exactly zero (they have no
stiffness, but no force either). The member stiffness is high against node masses and loads (largest
displacement below about 1.5 % of the length of the truss), the response is close to linear and not
sensitive to the order of adding items; 1 s with 2000 steps resolves the lowest modes, the numerical
damping of the solver removes the unresolved highest ones. With the stiff members the default Newton
tolerances sometimes hit round-off, the solver then halves single steps, and whether it does depends
on the order of adding items; newton.absoluteTolerance = 1e-8 avoids that.

Physics checks: with d = 0 the total energy (kinetic + spring - work of gravity and tip force) is
conserved; the static equilibrium of the model (static solver, out-of-plane coordinates locked)
agrees with the one computed independently (Newton's method on the spring network).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=37,
    name="parallel chord truss frame with springs",
    level="2",
    description="""
        A planar parallel chord truss in the x-y plane, clamped to a wall at its left end as a
        cantilever, with n = {n_panels} panels of length a = {panel_length} m and height
        h = {height} m. The truss nodes are the bottom chord nodes B_i = [i*a, 0, 0] and the top
        chord nodes T_i = [i*a, h, 0] for i = 0 to n. The wall nodes B_0 and T_0 are fixed points on
        ground; every other node is a mass point with mass m = {node_mass} kg at its node position
        (reference position), starting from rest. The members are linear spring-dampers with
        stiffness k = {stiffness} N/m and damping coefficient d = {damping} N*s/m, relaxed in the
        reference configuration (default reference length): for every panel i = 0 to n - 1 the
        bottom chord member B_i-B_(i+1), the top chord member T_i-T_(i+1) and the diagonal
        B_i-T_(i+1), and the verticals B_i-T_i for i = 1 to n. A member ending at B_0 or T_0 is
        attached to the ground at that point. The truss carries its weight, gravity
        g = {gravity} m/s^2 acting in the negative y-direction on all mass points, and a constant
        force [0, -{force}, 0] N applied to the tip node B_n. Create the ground, the mass points
        B_1 to B_n, then T_1 to T_n, then the members (for each panel its bottom chord, top chord
        and diagonal, then the verticals), then the force.
    """,
    open_description="""
        A planar cantilever truss with parallel chords in the x-y plane, built into a wall at its
        left end. It has n = {n_panels} panels of length a = {panel_length} m and height
        h = {height} m. Its nodes are the bottom chord nodes B_i = [i*a, 0, 0] and the top chord
        nodes T_i = [i*a, h, 0], i = 0 to n. The two wall nodes B_0 and T_0 are fixed points of the
        wall (no mass, they do not move); every other node is a point mass m = {node_mass} kg. The
        members are massless linear spring-dampers, axial stiffness k = {stiffness} N/m and axial
        damping d = {damping} N*s/m, each unstretched at the node positions given above: in every
        panel i = 0 to n - 1 the bottom chord B_i-B_(i+1), the top chord T_i-T_(i+1) and the
        diagonal B_i-T_(i+1), and the verticals B_i-T_i for i = 1 to n (no vertical at the wall).
        All nodes start at rest at these positions. At t = 0 the loads are applied suddenly and stay
        constant: gravity g = {gravity} m/s^2 in the negative y-direction on every point mass, and a
        force of {force} N in the negative y-direction at the tip node B_n.
    """,
    params=(
        Param("n_panels", 2, 6, integer=True),
        Param("panel_length", 0.4, 0.8, "m"),
        Param("height", 0.5, 1.0, "m"),
        Param("node_mass", 1.0, 5.0, "kg"),
        Param("stiffness", 2e6, 1e7, "N/m"),
        Param("damping", 50.0, 500.0, "N*s/m"),
        Param("force", 200.0, 2000.0, "N"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper", "Force"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        # truss nodes as (item, local position): the wall nodes are points on the ground
        bottom = [(oGround, [0, 0, 0])]
        top = [(oGround, [0, height, 0])]
        for i in range(1, n_panels + 1):
            oNode = mbs.CreateMassPoint(referencePosition=[i * panel_length, 0, 0], mass=node_mass,
                                        gravity=[0, -gravity, 0])
            bottom.append((oNode, [0, 0, 0]))
        for i in range(1, n_panels + 1):
            oNode = mbs.CreateMassPoint(referencePosition=[i * panel_length, height, 0], mass=node_mass,
                                        gravity=[0, -gravity, 0])
            top.append((oNode, [0, 0, 0]))

        members = []
        for i in range(n_panels):
            members += [(bottom[i], bottom[i + 1]), (top[i], top[i + 1]), (bottom[i], top[i + 1])]
        for i in range(1, n_panels + 1):
            members.append((bottom[i], top[i]))
        for (item0, local0), (item1, local1) in members:
            mbs.CreateSpringDamper(itemNumbers=[item0, item1], localPosition0=local0, localPosition1=local1,
                                   stiffness=stiffness, damping=damping)
        mbs.CreateForce(itemNumber=bottom[n_panels][0], loadVector=[0, -force, 0])
    """,
    sim=SimSettings(
        end_time=1.0,
        steps=2000,
        extra=("simulationSettings.timeIntegration.newton.absoluteTolerance = 1e-8",),
    ),
)
