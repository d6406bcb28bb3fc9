"""Physics checks of the level-2 mechanism ground truths against mechanics.

Tasks: four-bar mechanism / point masses (31), elastic chain (33), rigid rotor unbalanced (34),
four-bar mechanism / rigid bodies (36), parallel chord truss (37), Pratt truss bridge (38),
gyroscope nutation (48), 2R SCARA robot (49), RRR articulated robot (50).

Masses, inertias, geometry and loads are recomputed here from the parameters (never read from the
model), so a wrong parameter in a ground truth shows up as a violated equation of motion, energy
balance or equilibrium; the ``test_*_detects_*`` tests confirm this by perturbing one parameter of
the reference program by 5 %.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root
from simulate import SOLVE, perturb, reference, retime, simulate
from simulate import simulate_bodies as shared_simulate_bodies

SEEDS = (0, 1, 2, 3)
GRAVITY_ROBOTS = 9.81  # fixed in the robot descriptions


def simulate_qv(program: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(times, q_total, q_t) per step, including t = 0."""
    rows: list[tuple[float, np.ndarray, np.ndarray]] = []

    def state(mbs, t):
        rows.append((t, np.array(mbs.systemData.GetODE2CoordinatesTotal()),
                     np.array(mbs.systemData.GetODE2Coordinates_t())))
        return True

    def hook(mbs):
        state(mbs, 0.0)
        mbs.SetPostStepUserFunction(state)

    namespace: dict = {"__name__": "__meceng_test__", "_hook": hook}
    exec(compile(program.replace(SOLVE, f"_hook(mbs)\n{SOLVE}"), "<reference>", "exec"), namespace)
    times = np.array([r[0] for r in rows])
    _, first = np.unique(times, return_index=True)
    first.sort()
    return times[first], np.array([rows[i][1] for i in first]), np.array([rows[i][2] for i in first])


def simulate_bodies(program: str) -> tuple[np.ndarray, list[dict[str, np.ndarray]]]:
    """Body sensors on every rigid body, in creation order (the shared helper, without q)."""
    times, _, bodies = shared_simulate_bodies(program)
    return times, bodies

def cuboid(density: float, sides) -> tuple[float, np.ndarray]:
    """Mass and principal inertia (about the centre, local axes) of a homogeneous cuboid."""
    a, b, c = sides
    m = density * a * b * c
    return m, np.diag([m * (b * b + c * c), m * (a * a + c * c), m * (a * a + b * b)]) / 12


def _same_angle(a: float, b: float, tol: float = 1e-12) -> bool:
    return abs(np.remainder(a - b + np.pi, 2 * np.pi) - np.pi) < tol


def _z_angle(q: np.ndarray, i0: int) -> np.ndarray:
    """Unwrapped rotation angle about z of a rigid body whose Euler parameters start at i0 + 3."""
    return np.unwrap(2 * np.arctan2(q[:, i0 + 6], q[:, i0 + 3]))


# ---------------------------------------------------------------------------------------------
# 31, 36 four-bar mechanism: one degree of freedom, M(theta)*theta'' + M'/2*theta'^2 + V' = 0


def _fourbar_joints(p: dict, theta):
    a, b, c, d = p["crank_length"], p["coupler_length"], p["rocker_length"], p["ground_length"]
    pB = np.stack([a * np.cos(theta), a * np.sin(theta)], -1)
    e = np.array([d, 0.0]) - pB
    f = np.linalg.norm(e, axis=-1)[..., None]
    s = (b * b - c * c + f * f) / (2 * f)
    h = np.sqrt(b * b - s * s)
    return pB, pB + s / f * e + h / f * np.stack([-e[..., 1], e[..., 0]], -1)


def _fourbar_bodies(p: dict, theta) -> list:
    """(mass, inertia about z, centre of mass (.., 2), angle or None) of every moving body."""
    pB, pC = _fourbar_joints(p, theta)
    if "mass_b" in p:
        return [(p["mass_b"], 0.0, pB, None), (p["mass_c"], 0.0, pC, None)]
    pD = np.array([p["ground_length"], 0.0])
    out = []
    for length, com, vec in ((p["crank_length"], pB / 2, pB), (p["coupler_length"], (pB + pC) / 2, pC - pB),
                             (p["rocker_length"], (pD + pC) / 2, pC - pD)):
        m, j = cuboid(p["density"], (length, p["width"], p["width"]))
        out.append((m, j[2, 2], com, np.arctan2(vec[..., 1], vec[..., 0])))
    return out


def _fourbar_residual(p: dict, t: np.ndarray, theta: np.ndarray, eps: float = 1e-5) -> float:
    """Largest residual of the one-degree-of-freedom equation of motion along the simulated crank
    angle (central differences), relative to the largest gravity moment about the crank."""

    def potential(th):
        return sum(p["gravity"] * m * com[..., 1] for m, _, com, _ in _fourbar_bodies(p, th))

    def mass(th):
        total = 0.0
        for (m, j, c1, a1), (_, _, c0, a0) in zip(_fourbar_bodies(p, th + eps), _fourbar_bodies(p, th - eps),
                                                  strict=True):
            dc = (c1 - c0) / (2 * eps)
            total = total + m * np.sum(dc * dc, -1)
            if a1 is not None:
                total = total + j * (np.angle(np.exp(1j * (a1 - a0))) / (2 * eps)) ** 2
        return total

    h = t[1] - t[0]
    th = theta[1:-1]
    omega = (theta[2:] - theta[:-2]) / (2 * h)
    acc = (theta[2:] - 2 * th + theta[:-2]) / h**2
    d_mass = (mass(th + eps) - mass(th - eps)) / (2 * eps)
    d_pot = (potential(th + eps) - potential(th - eps)) / (2 * eps)
    residual = mass(th) * acc + 0.5 * d_mass * omega**2 + d_pot
    grid = np.linspace(0, 2 * np.pi, 721)
    scale = np.max(np.abs(potential(grid + eps) - potential(grid - eps))) / (2 * eps)
    return float(np.max(np.abs(residual)) / scale)


def _fourbar_point_errors(p: dict, program: str) -> tuple[float, float]:
    """(equation-of-motion residual, largest violation of the rod lengths and of z = 0)."""
    t, q, _ = simulate(retime(program, refine=4))
    pB, pC = q[:, 0:3], q[:, 3:6]
    pD = np.array([p["ground_length"], 0, 0])
    theta = np.unwrap(np.arctan2(pB[:, 1], pB[:, 0]))
    assert _same_angle(theta[0], np.radians(p["crank_angle_deg"]))
    lengths = np.abs(np.column_stack([np.linalg.norm(pB, axis=1) - p["crank_length"],
                                      np.linalg.norm(pC - pB, axis=1) - p["coupler_length"],
                                      np.linalg.norm(pC - pD, axis=1) - p["rocker_length"]]))
    constraint = max(float(np.max(lengths)), float(np.max(np.abs(q[:, [2, 5]]))))
    return _fourbar_residual(p, t, theta), constraint


@pytest.mark.parametrize("seed", SEEDS)
def test_four_bar_point_masses_equation_of_motion(seed):
    p, program = reference("four_bar_mechanism_point_masses", seed)
    residual, constraint = _fourbar_point_errors(p, program)
    assert residual < 1e-3
    assert constraint < 1e-8


def test_four_bar_point_masses_detects_wrong_parameters():
    p, program = reference("four_bar_mechanism_point_masses", 0)
    assert _fourbar_point_errors(p, perturb(program, "mass=mass_b,", "mass=1.05 * mass_b,"))[0] > 1e-2
    assert _fourbar_point_errors(p, perturb(program, "mass=mass_c,", "mass=1.05 * mass_c,"))[0] > 1e-2
    bad_gravity = perturb(program, "mass=mass_b, gravity=[0, -gravity, 0]",
                           "mass=mass_b, gravity=[0, -1.05 * gravity, 0]")
    assert _fourbar_point_errors(p, bad_gravity)[0] > 1e-2
    bad_length = perturb(program, "distance=coupler_length", "distance=1.05 * coupler_length")
    assert _fourbar_point_errors(p, bad_length)[1] > 1e-3


def _fourbar_rigid_errors(p: dict, program: str) -> tuple[float, float]:
    """(equation-of-motion residual, largest mismatch of the joint points / planarity)."""
    t, q, _ = simulate(retime(program, refine=4))
    theta = _z_angle(q, 0)
    assert _same_angle(theta[0], np.radians(p["crank_angle_deg"]))
    b, c = p["coupler_length"], p["rocker_length"]
    crank, coupler, rocker = q[:, 0:2], q[:, 7:9], q[:, 14:16]
    pD = np.array([p["ground_length"], 0])

    def direction(i0):
        angle = _z_angle(q, i0)
        return np.column_stack([np.cos(angle), np.sin(angle)])

    pB = 2 * crank
    pC = pD + c * direction(14)
    mismatch = [np.linalg.norm(crank, axis=1) - p["crank_length"] / 2,
                np.linalg.norm(coupler - b / 2 * direction(7) - pB, axis=1),
                np.linalg.norm(coupler + b / 2 * direction(7) - pC, axis=1),
                np.linalg.norm(rocker - (pD + pC) / 2, axis=1)]
    planar = q[:, [2, 4, 5, 9, 11, 12, 16, 18, 19]]  # z and the Euler parameters of x-/y-rotations
    kinematics = max(float(np.max(np.abs(mismatch))), float(np.max(np.abs(planar))))
    return _fourbar_residual(p, t, theta), kinematics


@pytest.mark.parametrize("seed", SEEDS)
def test_four_bar_rigid_bodies_equation_of_motion(seed):
    p, program = reference("four_bar_mechanism_rigid_bodies", seed)
    residual, kinematics = _fourbar_rigid_errors(p, program)
    assert residual < 1e-3
    assert kinematics < 1e-8


def test_four_bar_rigid_bodies_detects_wrong_parameters():
    p, program = reference("four_bar_mechanism_rigid_bodies", 0)
    heavy_coupler = perturb(program, "sideLengths=[coupler_length, width, width]",
                             "sideLengths=[coupler_length, width, 1.05 * width]")
    assert _fourbar_rigid_errors(p, heavy_coupler)[0] > 2.5e-3
    heavy_rocker = perturb(program, "sideLengths=[rocker_length, width, width]",
                            "sideLengths=[rocker_length, width, 1.05 * width]")
    assert _fourbar_rigid_errors(p, heavy_rocker)[0] > 2.5e-3
    bad_gravity = program.replace("gravity=[0, -gravity, 0]", "gravity=[0, -1.05 * gravity, 0]")
    assert _fourbar_rigid_errors(p, bad_gravity)[0] > 1e-2


# ---------------------------------------------------------------------------------------------
# 33, 37, 38 spring networks (chain, trusses): energy without damping, static equilibrium


def _network(slug: str, p: dict):
    """(free node positions (n, 2), fixed points {id: xy}, springs (i, j, k, l0), nodal loads (n, 2),
    node masses (n,), supports [(node, coordinate)]) in the creation order of the mass points;
    negative ids are ground points."""
    g = p["gravity"]
    if slug == "elastic_chain":
        n, span = p["n_masses"], p["span"]
        h = span / (n + 1)
        nodes = np.array([[i * h, 0.0] for i in range(1, n + 1)])
        fixed = {-1: np.array([0.0, 0.0]), -2: np.array([span, 0.0])}
        ids = [-1, *range(n), -2]
        springs = [(ids[i], ids[i + 1], p["stiffness"], p["length_ratio"] * h) for i in range(n + 1)]
        masses = np.full(n, p["mass"])
        return nodes, fixed, springs, np.outer(masses, [0, -g]), masses, []
    n, a, h = p["n_panels"], p["panel_length"], p["height"]
    if slug == "parallel_chord_truss_frame_with_springs":
        nodes = np.array([[i * a, 0.0] for i in range(1, n + 1)] + [[i * a, h] for i in range(1, n + 1)])
        fixed = {-1: np.array([0.0, 0.0]), -2: np.array([0.0, h])}

        def bottom(i):
            return i - 1 if i > 0 else -1

        def top(i):
            return n + i - 1 if i > 0 else -2

        pairs = [pair for i in range(n) for pair in ((bottom(i), bottom(i + 1)), (top(i), top(i + 1)),
                                                     (bottom(i), top(i + 1)))]
        pairs += [(bottom(i), top(i)) for i in range(1, n + 1)]
        loaded, supports = bottom(n), []
    else:  # Pratt truss
        nodes = np.array([[i * a, 0.0] for i in range(n + 1)] + [[i * a, h] for i in range(1, n)])
        fixed = {}

        def top(i):
            return n + i

        pairs = [(i, i + 1) for i in range(n)] + [(top(i), top(i + 1)) for i in range(1, n - 1)]
        pairs += [(0, top(1)), (top(n - 1), n)] + [(i, top(i)) for i in range(1, n)]
        pairs += [(top(i), i + 1) for i in range(1, n // 2)] + [(top(i), i - 1) for i in range(n // 2 + 1, n)]
        loaded, supports = 1, [(0, 0), (0, 1), (n, 1)]

    def position(j):
        return fixed[j] if j < 0 else nodes[j]

    springs = [(i, j, p["stiffness"], float(np.linalg.norm(position(i) - position(j)))) for i, j in pairs]
    masses = np.full(len(nodes), p["node_mass"])
    loads = np.outer(masses, [0, -g])
    loads[loaded, 1] -= p["force"]
    return nodes, fixed, springs, loads, masses, supports


def _spring_forces(x: np.ndarray, fixed: dict, springs: list) -> np.ndarray:
    forces = np.zeros_like(x)
    for i, j, k, l0 in springs:
        xi = fixed[i] if i < 0 else x[i]
        xj = fixed[j] if j < 0 else x[j]
        d = xj - xi
        length = np.linalg.norm(d)
        f = k * (length - l0) * d / length
        if i >= 0:
            forces[i] += f
        if j >= 0:
            forces[j] -= f
    return forces


def _spring_energy(x: np.ndarray, fixed: dict, springs: list) -> np.ndarray:
    energy = 0.0
    for i, j, k, l0 in springs:
        xi = fixed[i] if i < 0 else x[:, i]
        xj = fixed[j] if j < 0 else x[:, j]
        energy = energy + 0.5 * k * (np.linalg.norm(xj - xi, axis=-1) - l0) ** 2
    return energy


def _static_equilibrium(network) -> np.ndarray:
    """Newton (hybrid Powell) on the nonlinear in-plane equilibrium of the spring network."""
    nodes, fixed, springs, loads, _, supports = network
    free = np.ones(nodes.shape, bool)
    for node, coordinate in supports:
        free[node, coordinate] = False

    def residual(z):
        x = nodes.copy()
        x[free] = z
        return (_spring_forces(x, fixed, springs) + loads)[free]

    solution = root(residual, nodes[free], method="hybr", tol=1e-14)
    assert np.max(np.abs(residual(solution.x))) < 1e-8 * np.max(np.abs(loads))
    x = nodes.copy()
    x[free] = solution.x
    return x


#: Appended to the model (before mbs.Assemble) for the static check: the out-of-plane coordinates
#: have no stiffness, so they are locked; then the static solver replaces the dynamic one.
_STATIC = """
for _o in range(mbs.systemData.NumberOfObjects()):
    if mbs.GetObject(_o)['objectType'] == 'MassPoint':
        mbs.CreateCoordinateConstraint(itemNumbers=[None, _o], coordinates=[None, 2])
mbs.Assemble()
simulationSettings = exu.SimulationSettings()
simulationSettings.staticSolver.numberOfLoadSteps = 10
simulationSettings.staticSolver.verboseMode = 0
simulationSettings.solution.file.write = False
mbs.SolveStatic(simulationSettings)
_q = np.array(mbs.systemData.GetODE2CoordinatesTotal())
"""


def _static_error(slug: str, p: dict, program: str) -> float:
    """Static deflection of the ground-truth model vs the independent solution, relative to it."""
    network = _network(slug, p)
    expected = _static_equilibrium(network)
    namespace: dict = {"__name__": "__meceng_test__"}
    exec(compile(program[: program.index("mbs.Assemble()")] + _STATIC, "<static>", "exec"), namespace)
    q = namespace["_q"].reshape(-1, 3)
    deflection = np.max(np.abs(expected - network[0]))
    return float(np.max(np.abs(q[:, :2] - expected)) / deflection)


def _energy_error(slug: str, p: dict, program: str) -> tuple[float, np.ndarray]:
    """Relative drift of kinetic + spring energy - work of the constant loads, undamped and without
    numerical damping (spectral radius 1); also returns the positions (steps, nodes, 3)."""
    nodes, fixed, springs, loads, masses, _ = _network(slug, p)
    t, q, v = simulate_qv(retime(program, spectral_radius=1.0))
    x = q.reshape(len(t), -1, 3)
    assert np.max(np.abs(x[:, :, 2])) == 0.0  # planar
    xy, vel = x[:, :, :2], v.reshape(len(t), -1, 3)
    assert np.max(np.abs(xy[0] - nodes)) < 1e-12 and np.max(np.abs(vel[0])) == 0.0
    work = np.sum(loads[None] * (xy - xy[0]), axis=(1, 2))
    energy = 0.5 * np.sum(masses[None, :, None] * vel**2, axis=(1, 2)) + _spring_energy(xy, fixed, springs) - work
    return float(np.max(np.abs(energy - energy[0])) / np.max(np.abs(work))), x


SPRING_NETWORKS = ("elastic_chain", "parallel_chord_truss_frame_with_springs", "pratt_truss_bridge_frame_with_springs")


@pytest.mark.parametrize("slug", SPRING_NETWORKS)
@pytest.mark.parametrize("seed", SEEDS)
def test_spring_network_energy_and_statics(slug, seed):
    p, program = reference(slug, seed)
    assert _static_error(slug, p, program) < 1e-7
    p, program = reference(slug, seed, damping=0.0)
    error, x = _energy_error(slug, p, program)
    assert error < 3e-4
    if slug == "elastic_chain":  # symmetric about the middle of the span
        assert np.max(np.abs(x[:, ::-1, 0] + x[:, :, 0] - p["span"])) < 1e-9
        assert np.max(np.abs(x[:, ::-1, 1] - x[:, :, 1])) < 1e-9
    if slug.startswith("pratt"):  # pinned and roller supports hold
        n = p["n_panels"]
        assert np.max(np.abs(x[:, 0, :2])) < 1e-10 and np.max(np.abs(x[:, n, 1])) < 1e-10


@pytest.mark.parametrize("slug", SPRING_NETWORKS)
def test_spring_network_detects_wrong_parameters(slug):
    p, program = reference(slug, 1, damping=0.0)
    bad_stiffness = program.replace("stiffness=stiffness", "stiffness=1.05 * stiffness")
    assert _static_error(slug, p, bad_stiffness) > 1e-2
    assert _energy_error(slug, p, bad_stiffness)[0] > 1e-3
    bad_gravity = program.replace("gravity=[0, -gravity, 0]", "gravity=[0, -1.05 * gravity, 0]")
    assert _static_error(slug, p, bad_gravity) > 1e-3
    assert _energy_error(slug, p, bad_gravity)[0] > 1e-3


# ---------------------------------------------------------------------------------------------
# 34 rigid rotor unbalanced: J*theta'' = T + m_u*g*r*sin(theta), J = m*r^2/2 + m_u*r^2


def _rotor_error(p: dict, program: str) -> float:
    """Largest deviation of the rotation angle from the independent solution, relative to the final
    angle; asserts that the rotor axis stays fixed."""
    # the Euler-parameter integration has a relative error ~ (omega*h)^2; refine the step 4x
    t, q, _ = simulate(retime(program, refine=4))
    assert np.max(np.abs(q[:, :3])) < 1e-10 and np.max(np.abs(q[:, 5:7])) < 1e-10
    theta = np.unwrap(2 * np.arctan2(q[:, 4], q[:, 3]))
    r, mu = p["radius"], p["unbalance_mass"]
    j = 0.5 * p["density"] * np.pi * r**4 * p["length"] + mu * r * r
    solution = solve_ivp(lambda _, y: [y[1], (p["torque"] + mu * p["gravity"] * r * np.sin(y[0])) / j],
                         (0.0, t[-1]), [0.0, p["omega0"]], t_eval=t, rtol=1e-12, atol=1e-12, method="DOP853")
    return float(np.max(np.abs(theta - solution.y[0])) / theta[-1])


@pytest.mark.parametrize("seed", SEEDS)
def test_unbalanced_rotor_rotation(seed):
    p, program = reference("rigid_rotor_unbalanced", seed)
    assert _rotor_error(p, program) < 1e-5


def test_unbalanced_rotor_detects_wrong_parameters():
    p, program = reference("rigid_rotor_unbalanced", 2)
    bad_unbalance = perturb(program, "InertiaMassPoint(mass=unbalance_mass)",
                             "InertiaMassPoint(mass=1.05 * unbalance_mass)")
    assert _rotor_error(p, bad_unbalance) > 1e-4
    bad_radius = perturb(program, "Translated([0, 0, radius])", "Translated([0, 0, 1.05 * radius])")
    assert _rotor_error(p, bad_radius) > 1e-4
    bad_inertia = perturb(program, "length=length,", "length=1.05 * length,")
    assert _rotor_error(p, bad_inertia) > 1e-3


# ---------------------------------------------------------------------------------------------
# 48 gyroscope nutation: heavy symmetric top, reduced equation for the inclination of the axis


def _gyroscope_errors(p: dict, program: str) -> tuple[float, float]:
    """(largest deviation of the axis inclination from the reduced equation, and of its largest
    value from the closed-form lower turning point), both relative to the nutation amplitude."""
    t, q, _ = simulate(retime(program, refine=2))
    radius, thickness, arm, g = p["disc_radius"], p["thickness"], p["axle_length"], p["gravity"]
    m = p["density"] * np.pi * radius**2 * thickness
    j3 = 0.5 * m * radius**2
    j1 = m * (3 * radius**2 + thickness**2) / 12 + m * arm**2  # about the pivot
    theta = np.arccos(q[:, 2] / arm)  # polar angle of the axis from the vertical
    assert np.max(np.abs(np.linalg.norm(q[:, :3], axis=1) - arm)) < 1e-8
    l3 = j3 * p["spin"]  # conserved spin angular momentum
    theta0 = np.pi / 2 - np.radians(p["elevation_deg"])
    lz = l3 * np.cos(theta0)  # conserved vertical angular momentum (no initial precession)

    def rhs(_, y):
        th, om = y
        phi_dot = (lz - l3 * np.cos(th)) / (j1 * np.sin(th) ** 2)
        return [om, phi_dot**2 * np.sin(th) * np.cos(th) - l3 / j1 * phi_dot * np.sin(th)
                + m * g * arm / j1 * np.sin(th)]

    solution = solve_ivp(rhs, (0.0, t[-1]), [theta0, 0.0], t_eval=t, rtol=1e-12, atol=1e-12, method="DOP853")
    # lower turning point u1 = cos(theta1): 2*j1*m*g*l*(1 - u^2) = l3^2*(u0 - u), the root below u0
    a = 2 * j1 * m * g * arm
    u0 = np.cos(theta0)
    u1 = (l3**2 - np.sqrt(l3**4 - 4 * a * (l3**2 * u0 - a))) / (2 * a)
    amplitude = np.arccos(u1) - theta0
    assert solution.y[0].max() - theta0 == pytest.approx(amplitude, rel=1e-6)
    return (float(np.max(np.abs(theta - solution.y[0])) / amplitude),
            float(abs(theta.max() - theta0 - amplitude) / amplitude))


@pytest.mark.parametrize("seed", SEEDS[:3])
def test_gyroscope_nutation(seed):
    p, program = reference("gyroscope_nutation", seed)
    trajectory, turning = _gyroscope_errors(p, program)
    assert trajectory < 3e-4
    assert turning < 1e-4


def test_gyroscope_detects_wrong_parameters():
    p, program = reference("gyroscope_nutation", 1)
    bad_disc = perturb(program, "outerRadius=disc_radius", "outerRadius=1.05 * disc_radius")
    assert max(_gyroscope_errors(p, bad_disc)) > 1e-2
    bad_thickness = perturb(program, "length=thickness", "length=1.05 * thickness")
    assert _gyroscope_errors(p, bad_thickness)[0] > 1e-3
    bad_gravity = perturb(program, "gravity=[0, 0, -gravity]", "gravity=[0, 0, -1.05 * gravity]")
    assert max(_gyroscope_errors(p, bad_gravity)) > 1e-2


# ---------------------------------------------------------------------------------------------
# 49 2R SCARA robot: Lagrange equations of the planar two-link arm with the PD torques


def _cosine_trajectory(t, qs, qe, duration):
    s = np.minimum(t, duration)
    return (qs + (qe - qs) * (1 - np.cos(np.pi * s / duration)) / 2,
            np.where(t < duration, (qe - qs) * np.pi / (2 * duration) * np.sin(np.pi * s / duration), 0.0))


def _scara_errors(p: dict, program: str, end_time: float | None = None) -> tuple[float, np.ndarray, float]:
    """(equation-of-motion residual relative to the largest joint torque, final joint angles,
    largest absolute link angle)."""
    t, q, v = simulate_qv(retime(program, end_time=end_time))

    def angle_rate(i0):
        e0, e3, de0, de3 = q[:, i0 + 3], q[:, i0 + 6], v[:, i0 + 3], v[:, i0 + 6]
        return np.unwrap(2 * np.arctan2(e3, e0)), 2 * (e0 * de3 - e3 * de0) / (e0**2 + e3**2)

    phi1, omega1 = angle_rate(0)
    phi2, omega2 = angle_rate(7)
    joints = [(phi1, omega1), (phi2 - phi1, omega2 - omega1)]
    taus = []
    for (angle, rate), name in zip(joints, ("q1", "q2"), strict=True):
        qd, vd = _cosine_trajectory(t, np.radians(p[f"{name}_start_deg"]), np.radians(p[f"{name}_end_deg"]),
                                    p["duration"])
        taus.append(p["kp"] * (qd - angle) + p["kd"] * (vd - rate))
    l1, l2 = p["length1"], p["length2"]
    m1, j1 = cuboid(p["density"], (l1, 0.04, 0.04))
    m2, j2 = cuboid(p["density"], (l2, 0.04, 0.04))
    i1, i2, c1, c2 = j1[2, 2], j2[2, 2], l1 / 2, l2 / 2
    h = t[1] - t[0]
    q2, dq1, dq2 = joints[1][0][1:-1], joints[0][1][1:-1], joints[1][1][1:-1]
    a1, a2 = ((x[2:] - 2 * x[1:-1] + x[:-2]) / h**2 for x, _ in joints)
    m11 = i1 + i2 + m1 * c1**2 + m2 * (l1**2 + c2**2 + 2 * l1 * c2 * np.cos(q2))
    m12 = i2 + m2 * (c2**2 + l1 * c2 * np.cos(q2))
    m22 = i2 + m2 * c2**2
    coriolis = m2 * l1 * c2 * np.sin(q2)
    r1 = m11 * a1 + m12 * a2 - coriolis * (2 * dq1 * dq2 + dq2**2) - taus[0][1:-1]
    r2 = m12 * a1 + m22 * a2 + coriolis * dq1**2 - taus[1][1:-1]
    # the first steps (start-up of the generalized-alpha accelerations) and the steps around the end
    # of the motion (jump of the desired acceleration) are not smooth enough for central differences
    tc = t[1:-1]
    smooth = (tc > 5.5 * h) & (np.abs(tc - p["duration"]) > 5.5 * h)
    scale = max(np.max(np.abs(taus[0])), np.max(np.abs(taus[1])))
    residual = max(np.max(np.abs(r1[smooth])), np.max(np.abs(r2[smooth]))) / scale
    final = np.array([joints[0][0][-1], joints[1][0][-1]])
    return float(residual), final, float(max(np.max(np.abs(phi1)), np.max(np.abs(phi2))))


@pytest.mark.parametrize("seed", SEEDS)
def test_scara_equations_of_motion(seed):
    p, program = reference("2r_scara_robot", seed)
    residual, _, largest_angle = _scara_errors(p, program)
    assert residual < 5e-3
    assert largest_angle < np.radians(170)  # the Tait-Bryan z-angle in the controller never wraps


def test_scara_settles_at_end_angles():
    p, program = reference("2r_scara_robot", 3)
    _, final, _ = _scara_errors(p, program, end_time=4.0)
    assert np.max(np.abs(final - np.radians([p["q1_end_deg"], p["q2_end_deg"]]))) < 1e-8


def test_scara_detects_wrong_parameters():
    p, program = reference("2r_scara_robot", 0)
    heavy_link2 = perturb(program, "sideLengths=[length2, 0.04, 0.04]", "sideLengths=[length2, 0.04, 1.05 * 0.04]")
    assert _scara_errors(p, heavy_link2)[0] > 2e-2
    bad_gain = perturb(program, "tau1 = kp * (q1d - phi1)", "tau1 = 1.05 * kp * (q1d - phi1)")
    assert _scara_errors(p, bad_gain)[0] > 2e-2


# ---------------------------------------------------------------------------------------------
# 50 RRR articulated robot: work of the joint torques, static sag at the end pose


def _rrr_inertias(p: dict) -> list[tuple[float, np.ndarray]]:
    w = 0.05
    return [cuboid(p["density"], sides) for sides in ((w, w, p["length1"]), (p["length2"], w, w), (p["length3"], w, w))]


def _rrr_centres(p: dict, q) -> list[np.ndarray]:
    """Centres of mass (3, ...) of the three links for the joint angles q (forward kinematics)."""
    q1, q2, q3 = q
    shape = np.shape(q1)
    shoulder = np.array([0, 0, p["length1"]]).reshape((3,) + (1,) * len(shape))
    d2 = np.array([np.cos(q1) * np.cos(q2), np.sin(q1) * np.cos(q2), np.sin(q2)])
    d3 = np.array([np.cos(q1) * np.cos(q2 + q3), np.sin(q1) * np.cos(q2 + q3), np.sin(q2 + q3)])
    elbow = shoulder + p["length2"] * d2
    return [shoulder / 2 + 0 * d2, shoulder + p["length2"] / 2 * d2, elbow + p["length3"] / 2 * d3]


def _rrr_errors(p: dict, program: str, end_time: float | None = None) -> tuple[float, float, np.ndarray]:
    """(work-energy balance error, kinematics error, final joint angles)."""
    t, bodies = simulate_bodies(retime(program, end_time=end_time))
    r1, r2, r3 = (b["RotationMatrix"] for b in bodies)
    w1, w2, w3 = (b["AngularVelocity"] for b in bodies)
    r12 = np.einsum("nji,njk->nik", r1, r2)
    r23 = np.einsum("nji,njk->nik", r2, r3)
    # joint 2 and 3 rotate about the local -y axis of the preceding link
    angles = np.array([np.unwrap(np.arctan2(r1[:, 1, 0], r1[:, 0, 0])),
                       np.arctan2(r12[:, 2, 0], r12[:, 0, 0]), np.arctan2(r23[:, 2, 0], r23[:, 0, 0])])
    rates = np.array([w1[:, 2], -np.einsum("nji,nj->ni", r1, w2 - w1)[:, 1],
                      -np.einsum("nji,nj->ni", r2, w3 - w2)[:, 1]])
    ends = np.radians([p["q1_end_deg"], p["q2_end_deg"], p["q3_end_deg"]])
    s = np.minimum(t / p["duration"], 1)
    torques = []
    for angle, rate, end in zip(angles, rates, ends, strict=True):
        qd = end * (3 * s**2 - 2 * s**3)
        vd = np.where(t < p["duration"], end * 6 * (s - s**2) / p["duration"], 0.0)
        torques.append(p["kp"] * (qd - angle) + p["kd"] * (vd - rate))
    power = np.sum(np.array(torques) * rates, axis=0)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))])
    energy = 0.0
    for body, (m, j) in zip(bodies, _rrr_inertias(p), strict=True):
        vel, omega, rot = body["Velocity"], body["AngularVelocity"], body["RotationMatrix"]
        j_global = rot @ j @ np.transpose(rot, (0, 2, 1))
        energy = energy + 0.5 * m * np.sum(vel * vel, 1) + 0.5 * np.einsum("ni,nij,nj->n", omega, j_global, omega)
        energy = energy + m * GRAVITY_ROBOTS * body["Position"][:, 2]
    balance = energy - energy[0] - work
    balance_error = np.max(np.abs(balance)) / (np.max(np.abs(work)) + np.max(np.abs(energy - energy[0])))
    centres = _rrr_centres(p, angles)
    kinematics = max(np.max(np.abs(b["Position"] - c.T)) for b, c in zip(bodies, centres, strict=True))
    return float(balance_error), float(kinematics), angles[:, -1]


def _rrr_static_pose(p: dict) -> np.ndarray:
    """Joint angles where the PD torques kP*(q_e - q) balance the gravity moments dV/dq."""
    ends = np.radians([p["q1_end_deg"], p["q2_end_deg"], p["q3_end_deg"]])
    masses = [m for m, _ in _rrr_inertias(p)]

    def potential(q):
        return GRAVITY_ROBOTS * sum(m * c[2] for m, c in zip(masses, _rrr_centres(p, q), strict=True))

    def residual(q, eps=1e-6):
        gradient = [(potential(q + eps * e) - potential(q - eps * e)) / (2 * eps) for e in np.eye(3)]
        return p["kp"] * (ends - q) - np.array(gradient)

    solution = root(residual, ends, method="hybr", tol=1e-14)
    assert np.max(np.abs(residual(solution.x))) < 1e-8 * p["kp"]
    return solution.x


@pytest.mark.parametrize("seed", SEEDS)
def test_rrr_robot_work_energy_balance(seed):
    p, program = reference("rrr_articulated_robot_with_3d_cubic_trajectory", seed)
    balance, kinematics, _ = _rrr_errors(p, program)
    assert balance < 1e-4
    assert kinematics < 1e-9


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_rrr_robot_static_sag_at_end_pose(seed):
    p, program = reference("rrr_articulated_robot_with_3d_cubic_trajectory", seed)
    _, _, final = _rrr_errors(p, program, end_time=5.0)
    expected = _rrr_static_pose(p)
    assert np.max(np.abs(final - expected)) < 1e-8
    assert final[0] == pytest.approx(np.radians(p["q1_end_deg"]), abs=1e-10)  # no gravity moment about z


def test_rrr_robot_detects_wrong_parameters():
    slug = "rrr_articulated_robot_with_3d_cubic_trajectory"
    p, program = reference(slug, 0)
    heavy_forearm = perturb(program, "sideLengths=[length3, w, w]", "sideLengths=[length3, w, 1.05 * w]")
    assert _rrr_errors(p, heavy_forearm)[0] > 1e-3
    _, _, final = _rrr_errors(p, heavy_forearm, end_time=5.0)
    assert np.max(np.abs(final - _rrr_static_pose(p))) > 1e-4
    bad_gain = perturb(program, "stiffness=kp,", "stiffness=1.05 * kp,")
    assert _rrr_errors(p, bad_gain)[0] > 1e-3
