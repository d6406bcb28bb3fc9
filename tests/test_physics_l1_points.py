"""Physics checks of the level-1 mass-point ground truths against mechanics.

Tasks: slider crank / point masses (5), pendulum with elastic string (6), mass oscillator with user
function (7), n-mass oscillator (10), n-pendulum (13), double pendulum elastic spring (17),
n-pendulum elastic spring (18), mass point on rigid string (20), mass point on elastic string (21),
two mass points with springs (27), two mass points with distances (28).

Every check computes an error measure from the simulated trajectory and from quantities recomputed
here from the task parameters (masses, stiffnesses, lengths are never read back from the model), so
a wrong parameter in a ground truth shows up as a violated balance law or a wrong trajectory; the
``test_*_detects_*`` tests confirm that by perturbing the reference program by 5 % or less.
Velocities come from node sensors (written every step), accelerations from second differences.
"""

from __future__ import annotations

import numpy as np
import pytest
from simulate import SOLVE, perturb, reference, retime, simulate, stored_sensor

SEEDS = (0, 1, 2)

#: Added before ``mbs.Assemble()``: a velocity sensor on every point node (in node order, which is
#: the order of the coordinates) and a force sensor on every spring-damper / distance constraint.
_SENSORS = """
_vel, _force = [], []
for _n in range(mbs.systemData.NumberOfNodes()):
    if mbs.GetNode(_n)['nodeType'] == 'Point':
        _vel.append(mbs.AddSensor(SensorNode(nodeNumber=_n, storeInternal=True, writeToFile=False,
                                             outputVariableType=exu.OutputVariableType.Velocity)))
for _o in range(mbs.systemData.NumberOfObjects()):
    if mbs.GetObject(_o)['objectType'] in ('ConnectorSpringDamper', 'ConnectorDistance'):
        _force.append(mbs.AddSensor(SensorObject(objectNumber=_o, storeInternal=True, writeToFile=False,
                                                 outputVariableType=exu.OutputVariableType.Force)))
mbs.variables['_vel'] = _vel
mbs.variables['_force'] = _force
"""


def _run(program: str, *, refine: int = 1, conservative: bool = False):
    """Simulate with more steps and/or without numerical damping; returns
    (t, positions (n, 3N), velocities (n, 3N), connector forces (n, k), mbs)."""
    program = retime(program, refine=refine)
    extra = ["simulationSettings.solution.sensors.writePeriod = 0"]
    if conservative:
        extra.append("simulationSettings.timeIntegration.generalizedAlpha.spectralRadius = 1")
    assert program.count("mbs.Assemble()") == 1
    program = program.replace("mbs.Assemble()", _SENSORS + "mbs.Assemble()")
    program = program.replace(SOLVE, "\n".join([*extra, SOLVE]))
    t, q, mbs = simulate(program)

    def stored(sensor):
        return stored_sensor(mbs, sensor, t)

    vel = np.hstack([stored(s) for s in mbs.variables["_vel"]])
    forces = [stored(s)[:, 0] for s in mbs.variables["_force"]]
    force = np.column_stack(forces) if forces else np.zeros((len(t), 0))
    assert vel.shape == q.shape
    return t, q, vel, force, mbs


def _integral(t: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Cumulative trapezoidal integral of f over t, starting at 0."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))])


def _spring_chain_energy_error(q, vel, t, masses, gravity_vec, springs) -> float:
    """max |E(t) + W_damper(t) - E(0)| / E_scale for mass points and spring-dampers.

    ``springs``: (i, j, k, d, L0) with i = -1 for the ground point [0, 0, 0]. E is kinetic energy +
    gravity potential + spring energy; W_damper = integral of d*(dL/dt)^2. E_scale is the largest
    kinetic energy reached (plus the spring energy range), so the measure is relative.
    """
    n = len(masses)
    pos = q.reshape(len(t), n, 3)
    v = vel.reshape(len(t), n, 3)
    kinetic = 0.5 * np.einsum("i,tij,tij->t", np.asarray(masses), v, v)
    potential = -np.einsum("i,tij,j->t", np.asarray(masses), pos, np.asarray(gravity_vec))
    spring = np.zeros(len(t))
    power = np.zeros(len(t))
    for i, j, k, d, length0 in springs:
        pi = np.zeros((len(t), 3)) if i < 0 else pos[:, i]
        vi = np.zeros((len(t), 3)) if i < 0 else v[:, i]
        r, w = pos[:, j] - pi, v[:, j] - vi
        ell = np.linalg.norm(r, axis=1)
        ell_t = np.einsum("ti,ti->t", r, w) / ell
        spring += 0.5 * k * (ell - length0) ** 2
        power += d * ell_t**2
    energy = kinetic + potential + spring + _integral(t, power)
    scale = np.max(kinetic) + np.ptp(spring)
    return float(np.max(np.abs(energy - energy[0])) / scale)


# ---------------------------------------------------------------------------------------------
# 5 slider crank / point masses


def _slider_crank_reduced(v: dict, t: np.ndarray) -> np.ndarray:
    """Crank angle from the one-DOF equation M(theta)*theta'' + m2*x'*x''*theta'^2 = F*x' (RK4)."""
    m1, m2, r, ell, force = v["mass_crank"], v["mass_slider"], v["crank_length"], v["rod_length"], v["force"]

    def rhs(y):
        th, om = y
        s, c = np.sin(th), np.cos(th)
        w = np.sqrt(ell**2 - (r * s) ** 2)
        x1 = -r * s - r * r * s * c / w
        x2 = -r * c - r * r * ((c * c - s * s) / w + r * r * s * s * c * c / w**3)
        return np.array([om, (force * x1 - m2 * x1 * x2 * om**2) / (m1 * r * r + m2 * x1 * x1)])

    y = np.array([np.radians(v["crank_angle_deg"]), 0.0])
    out = [y[0]]
    sub = 4
    for k in range(len(t) - 1):
        h = (t[k + 1] - t[k]) / sub
        for _ in range(sub):
            k1 = rhs(y)
            k2 = rhs(y + 0.5 * h * k1)
            k3 = rhs(y + 0.5 * h * k2)
            k4 = rhs(y + h * k3)
            y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out.append(y[0])
    return np.array(out)


def _slider_crank_errors(v: dict, program: str) -> tuple[float, float, float]:
    """(constraint error, crank angle error vs the reduced ODE [rad], relative energy error)."""
    t, q, vel, _, _ = _run(program, refine=5)
    r, ell = v["crank_length"], v["rod_length"]
    p1, p2 = q[:, :3], q[:, 3:]
    constraint = max(
        np.max(np.abs(np.linalg.norm(p1, axis=1) - r)),
        np.max(np.abs(np.linalg.norm(p2 - p1, axis=1) - ell)),
        np.max(np.abs(p1[:, 2])),
        np.max(np.abs(p2[:, 1:])),
    )
    theta = np.unwrap(np.arctan2(p1[:, 1], p1[:, 0]))
    t_coarse = t[::10]
    angle_err = float(np.max(np.abs(theta[::10] - _slider_crank_reduced(v, t_coarse))))
    speed2 = np.sum(vel.reshape(len(t), 2, 3) ** 2, axis=2)
    kinetic = 0.5 * (v["mass_crank"] * speed2[:, 0] + v["mass_slider"] * speed2[:, 1])
    work = v["force"] * (p2[:, 0] - p2[0, 0])
    energy_err = float(np.max(np.abs(kinetic - work)) / np.max(kinetic))
    return float(constraint), angle_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_slider_crank_point_masses(seed):
    v, program = reference("slider_crank_point_masses", seed)
    constraint, angle_err, energy_err = _slider_crank_errors(v, program)
    assert constraint < 1e-9
    assert angle_err < 2e-5
    assert energy_err < 2e-5


def test_slider_crank_point_masses_swings_to_minus_theta0():
    """The force drives the crank through theta = 0 to -theta0 (energy conservation)."""
    v, program = reference("slider_crank_point_masses", 4)
    _, q, _, _, _ = _run(program)
    theta = np.arctan2(q[:, 1], q[:, 0])
    assert theta.min() == pytest.approx(-np.radians(v["crank_angle_deg"]), abs=2e-3)


def test_slider_crank_point_masses_detects_wrong_parameters():
    v, program = reference("slider_crank_point_masses", 1)
    for old, new in [
        ("mass=mass_crank", "mass=1.05 * mass_crank"),
        ("mass=mass_slider", "mass=1.05 * mass_slider"),
        ("loadVector=[force, 0, 0]", "loadVector=[1.05 * force, 0, 0]"),
    ]:
        _, angle_err, energy_err = _slider_crank_errors(v, perturb(program, old, new))
        assert angle_err > 1e-2, old
        assert energy_err > 1e-2, old
    bad = perturb(program, "distance=rod_length", "distance=1.01 * rod_length")
    assert _slider_crank_errors(v, bad)[0] > 1e-3


# ---------------------------------------------------------------------------------------------
# 6 pendulum with elastic string, 17 double pendulum elastic spring, 18 n-pendulum elastic spring


def _elastic_pendulum_errors(v: dict, program: str) -> tuple[float, float]:
    """(start state error, relative energy balance error)."""
    t, q, vel, _, _ = _run(program, refine=5, conservative=True)
    phi = np.radians(v["angle_deg"])
    length = v["length"]
    start = np.array([length * np.sin(phi), -length * np.cos(phi), 0, v["vx"], v["vy"], 0])
    start_err = float(np.max(np.abs(np.concatenate([q[0], vel[0]]) - start)))
    assert np.max(np.abs(q[:, 2])) == 0.0  # planar
    energy_err = _spring_chain_energy_error(
        q, vel, t, [v["mass"]], [0, -v["gravity"], 0], [(-1, 0, v["stiffness"], v["damping"], length)]
    )
    return start_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_pendulum_with_elastic_string_energy(seed):
    v, program = reference("pendulum_with_elastic_string", seed)
    start_err, energy_err = _elastic_pendulum_errors(v, program)
    assert start_err < 1e-12
    assert energy_err < 2e-5


def test_pendulum_with_elastic_string_detects_wrong_parameters():
    v, program = reference("pendulum_with_elastic_string", 0, damping=2.0)
    for old, new in [
        ("mass=mass,", "mass=1.05 * mass,"),
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
        ("gravity=[0, -gravity, 0]", "gravity=[0, -1.05 * gravity, 0]"),
    ]:
        assert _elastic_pendulum_errors(v, perturb(program, old, new))[1] > 1e-4, old
    bad = perturb(program, "initialVelocity=[vx, vy, 0]", "initialVelocity=[vx, 1.05 * vy, 0]")
    assert _elastic_pendulum_errors(v, bad)[0] > 1e-3


def _double_elastic_errors(v: dict, program: str) -> tuple[float, float]:
    t, q, vel, _, _ = _run(program, refine=5, conservative=True)
    phi1, phi2 = np.radians(v["angle1_deg"]), np.radians(v["angle2_deg"])
    p1 = np.array([v["length1"] * np.sin(phi1), -v["length1"] * np.cos(phi1), 0])
    p2 = p1 + np.array([v["length2"] * np.sin(phi2), -v["length2"] * np.cos(phi2), 0])
    start_err = float(max(np.max(np.abs(q[0] - np.concatenate([p1, p2]))), np.max(np.abs(vel[0]))))
    assert np.max(np.abs(q[:, [2, 5]])) == 0.0  # planar
    d = v["damping"]
    springs = [(-1, 0, v["stiffness1"], d, v["length1"]), (0, 1, v["stiffness2"], d, v["length2"])]
    energy_err = _spring_chain_energy_error(q, vel, t, [v["mass1"], v["mass2"]], [0, -v["gravity"], 0], springs)
    return start_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_double_pendulum_elastic_spring_energy(seed):
    v, program = reference("double_pendulum_elastic_spring", seed)
    start_err, energy_err = _double_elastic_errors(v, program)
    assert start_err < 1e-12
    assert energy_err < 2e-5


def test_double_pendulum_elastic_spring_detects_wrong_parameters():
    v, program = reference("double_pendulum_elastic_spring", 2, damping=2.0)
    for old, new in [
        ("mass=mass1", "mass=1.05 * mass1"),
        ("mass=mass2", "mass=1.05 * mass2"),
        ("stiffness=stiffness1", "stiffness=1.05 * stiffness1"),
        ("stiffness=stiffness2", "stiffness=1.05 * stiffness2"),
        ("stiffness=stiffness2, damping=damping", "stiffness=stiffness2, damping=1.05 * damping"),
        ("mass=mass1, gravity=[0, -gravity, 0]", "mass=mass1, gravity=[0, -1.05 * gravity, 0]"),
    ]:
        assert _double_elastic_errors(v, perturb(program, old, new))[1] > 1e-4, old
    bad = perturb(program, "phi2 = angle2_deg", "phi2 = 1.01 * angle2_deg")
    assert _double_elastic_errors(v, bad)[0] > 1e-4


def _n_elastic_errors(v: dict, program: str) -> tuple[float, float]:
    t, q, vel, _, _ = _run(program, refine=5, conservative=True)
    n, length = v["n_masses"], v["length"]
    phi = np.radians(v["angle_deg"])
    start = np.concatenate([[i * length * np.sin(phi), -i * length * np.cos(phi), 0] for i in range(1, n + 1)])
    start_err = float(max(np.max(np.abs(q[0] - start)), np.max(np.abs(vel[0]))))
    assert np.max(np.abs(q[:, 2::3])) == 0.0  # planar
    k, d = v["stiffness"], v["damping"]
    springs = [(i - 1, i, k, d, length) for i in range(n)]
    energy_err = _spring_chain_energy_error(q, vel, t, [v["mass"]] * n, [0, -v["gravity"], 0], springs)
    return start_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_n_pendulum_elastic_spring_energy(seed):
    v, program = reference("n_pendulum_elastic_spring", seed)
    start_err, energy_err = _n_elastic_errors(v, program)
    assert start_err < 1e-12
    assert energy_err < 2e-5


def test_n_pendulum_elastic_spring_detects_wrong_parameters():
    v, program = reference("n_pendulum_elastic_spring", 0, damping=5.0)
    for old, new in [
        ("mass=mass,", "mass=1.05 * mass,"),
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
        ("gravity=[0, -gravity, 0]", "gravity=[0, -1.05 * gravity, 0]"),
    ]:
        assert _n_elastic_errors(v, perturb(program, old, new))[1] > 1e-4, old


# ---------------------------------------------------------------------------------------------
# 7 mass oscillator with user function


def _forced_oscillator_error(v: dict, program: str) -> float:
    """max |x - x_exact| / max |x_exact| for m*x'' + d*x' + k*x = F0*sin(omega*t) from rest."""
    t, q, _, _, _ = _run(program, refine=10, conservative=True)
    m, k, d = v["mass"], v["stiffness"], v["damping"]
    f0, w = v["force_amplitude"], v["omega"]
    assert np.max(np.abs(q[:, 1:])) == 0.0  # stays on the x-axis
    amp = f0 / (k - m * w * w + 1j * d * w)  # x_p = Im(amp * exp(i*w*t))
    x_p = np.imag(amp * np.exp(1j * w * t))
    x0, v0 = -np.imag(amp), -np.real(amp) * w  # homogeneous part cancels x_p(0), x_p'(0)
    delta = d / (2 * m)
    w_d = np.sqrt(k / m - delta**2)
    x_h = np.exp(-delta * t) * (x0 * np.cos(w_d * t) + (v0 + delta * x0) / w_d * np.sin(w_d * t))
    exact = x_p + x_h
    return float(np.max(np.abs(q[:, 0] - v["length"] - exact)) / np.max(np.abs(exact)))


@pytest.mark.parametrize("seed", SEEDS)
def test_mass_oscillator_with_user_function(seed):
    v, program = reference("mass_oscillator_with_user_function", seed)
    assert _forced_oscillator_error(v, program) < 1e-4


def test_mass_oscillator_with_user_function_detects_wrong_parameters():
    v, program = reference("mass_oscillator_with_user_function", 0)
    for old, new in [
        ("mass=mass)", "mass=1.05 * mass)"),
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
        ("return [force_amplitude * np.sin(omega * t)", "return [1.05 * force_amplitude * np.sin(omega * t)"),
        ("np.sin(omega * t)", "np.sin(1.05 * omega * t)"),
        ("np.sin(omega * t)", "np.cos(omega * t)"),
    ]:
        assert _forced_oscillator_error(v, perturb(program, old, new)) > 1e-2, new


# ---------------------------------------------------------------------------------------------
# 10 n-mass oscillator


def _n_oscillator_errors(v: dict, program: str) -> tuple[float, float]:
    """(trajectory error / static tip displacement, relative energy error if undamped)."""
    t, q, vel, _, _ = _run(program, refine=10, conservative=True)
    n, m, k, d, f = v["n_masses"], v["mass"], v["stiffness"], v["damping"], v["force"]
    assert np.max(np.abs(np.delete(q, np.s_[::3], axis=1))) == 0.0  # motion stays on the x-axis
    x = q[:, ::3] - v["length"] * np.arange(1, n + 1)
    stiff = 2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    stiff[-1, -1] = 1
    K, D, M = k * stiff, d * stiff, m * np.eye(n)
    load = np.zeros(n)
    load[-1] = f
    x_static = np.linalg.solve(K, load)
    assert np.allclose(x_static, np.arange(1, n + 1) * f / k)
    # z' = A z about the static equilibrium, through the eigen-decomposition of A
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ D]])
    lam, V = np.linalg.eig(A)
    c = np.linalg.solve(V, np.concatenate([-x_static, np.zeros(n)]))
    exact = x_static + (V[:n] @ (c[:, None] * np.exp(lam[:, None] * t[None, :]))).real.T
    traj_err = float(np.max(np.abs(x - exact)) / x_static[-1])
    energy_err = 0.0
    if d == 0:
        xd = vel[:, ::3]
        energy = 0.5 * m * np.sum(xd**2, axis=1) + 0.5 * np.einsum("ti,ij,tj->t", x, K, x) - f * x[:, -1]
        energy_err = float(np.max(np.abs(energy)) / (f * x_static[-1]))
    return traj_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_n_mass_oscillator_damped(seed):
    v, program = reference("n_mass_oscillator", seed)
    assert _n_oscillator_errors(v, program)[0] < 2e-4


@pytest.mark.parametrize("seed", SEEDS)
def test_n_mass_oscillator_undamped_energy(seed):
    v, program = reference("n_mass_oscillator", seed, damping=0.0)
    traj_err, energy_err = _n_oscillator_errors(v, program)
    assert traj_err < 2e-4
    assert energy_err < 1e-10


def test_n_mass_oscillator_detects_wrong_parameters():
    v, program = reference("n_mass_oscillator", 0, damping=5.0)
    for old, new in [
        ("mass=mass)", "mass=1.05 * mass)"),
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
        ("loadVector=[force, 0, 0]", "loadVector=[1.05 * force, 0, 0]"),
    ]:
        assert _n_oscillator_errors(v, perturb(program, old, new))[0] > 2e-3, old


# ---------------------------------------------------------------------------------------------
# 13 n-pendulum


def _n_pendulum_errors(v: dict, program: str) -> tuple[float, float, float, float]:
    """(start error, constraint error, relative energy error, support force balance error)."""
    t, q, vel, force, _ = _run(program, refine=5)
    n, m, length, g = v["n_masses"], v["mass"], v["length"], v["gravity"]
    phi = np.radians(v["angle_deg"])
    start = np.concatenate([[i * length * np.sin(phi), -i * length * np.cos(phi), 0] for i in range(1, n + 1)])
    start_err = float(max(np.max(np.abs(q[0] - start)), np.max(np.abs(vel[0]))))
    pos = q.reshape(len(t), n, 3)
    links = np.diff(np.concatenate([np.zeros((len(t), 1, 3)), pos], axis=1), axis=1)
    constraint_err = float(np.max(np.abs(np.linalg.norm(links, axis=2) - length)))
    assert np.max(np.abs(pos[:, :, 2])) == 0.0  # planar
    energy = 0.5 * m * np.sum(vel**2, axis=1) + m * g * np.sum(pos[:, :, 1], axis=1)
    swing = m * g * length * (1 - np.cos(phi)) * n * (n + 1) / 2
    energy_err = float(np.max(np.abs(energy - energy[0])) / swing)
    # rod 1 pulls mass 1 towards the support: sum m*(a - g) = -T1 * p1 / L
    h = t[1] - t[0]
    acc = (pos[2:] - 2 * pos[1:-1] + pos[:-2]) / h**2
    inertia = m * np.sum(acc - np.array([0, -g, 0]), axis=1)
    support = -force[1:-1, :1] * pos[1:-1, 0] / length
    balance_err = float(np.max(np.linalg.norm(inertia - support, axis=1)) / (n * m * g))
    return start_err, constraint_err, energy_err, balance_err


def _linear_modes(v: dict, t: np.ndarray) -> np.ndarray:
    """Absolute link angles of the linearised chain: M theta'' + K theta = 0 from a straight start."""
    n, length, g = v["n_masses"], v["length"], v["gravity"]
    idx = np.arange(n)
    M = length * (n - np.maximum.outer(idx, idx))
    K = np.diag(g * (n - idx)).astype(float)
    lam, phi = np.linalg.eig(np.linalg.solve(M, K))
    coeff = np.linalg.solve(phi, np.full(n, np.radians(v["angle_deg"])))
    return (phi.real @ (coeff.real[:, None] * np.cos(np.sqrt(lam.real)[:, None] * t[None, :]))).T


@pytest.mark.parametrize("seed", SEEDS)
def test_n_pendulum_energy_constraints_support_force(seed):
    v, program = reference("n_pendulum", seed)
    start_err, constraint_err, energy_err, balance_err = _n_pendulum_errors(v, program)
    assert start_err < 1e-12
    assert constraint_err < 1e-9
    assert energy_err < 1e-6
    assert balance_err < 2e-3


@pytest.mark.parametrize("seed", SEEDS)
def test_n_pendulum_small_angle_normal_modes(seed):
    v, program = reference("n_pendulum", seed, angle_deg=0.5)
    t, q, _, _, _ = _run(program, refine=5)
    n = v["n_masses"]
    pos = np.concatenate([np.zeros((len(t), 1, 3)), q.reshape(len(t), n, 3)], axis=1)
    links = np.diff(pos, axis=1)
    theta = np.arctan2(links[:, :, 0], -links[:, :, 1])
    exact = _linear_modes(v, t)
    assert np.max(np.abs(theta - exact)) < 2e-3 * np.radians(v["angle_deg"])


def test_n_pendulum_detects_wrong_parameters():
    v, program = reference("n_pendulum", 1)
    bad_mass = perturb(program, "mass=mass,", "mass=1.05 * mass,")
    assert _n_pendulum_errors(v, bad_mass)[3] > 2e-2
    bad_gravity = perturb(program, "gravity=[0, -gravity, 0]", "gravity=[0, -1.05 * gravity, 0]")
    assert _n_pendulum_errors(v, bad_gravity)[2] > 1e-2
    bad_length = perturb(program, "phi0 = angle_deg", "length = 1.01 * length\nphi0 = angle_deg")
    start_err, constraint_err, _, _ = _n_pendulum_errors(v, bad_length)
    assert start_err > 1e-3
    assert constraint_err > 1e-3
    bad_angle = perturb(program, "phi0 = angle_deg", "phi0 = 1.05 * angle_deg")
    assert _n_pendulum_errors(v, bad_angle)[0] > 1e-4


# ---------------------------------------------------------------------------------------------
# 20 mass point on rigid string, 21 mass point on elastic string


def _string_errors(v: dict, program: str, elastic: bool) -> tuple[float, float, float, float]:
    """(start error, angular momentum error, energy error, string error), all relative.

    Rigid string: the string force is T = m*(v^2 - g*z)/L (radial balance) and |p| = L.
    Elastic string: the string error is 0; the energy includes spring and damper.
    """
    t, q, vel, force, _ = _run(program, refine=5, conservative=elastic)
    m, length, g = v["mass"], v["length"], v["gravity"]
    start = np.array([length, 0, 0, 0, v["vy"], v["vz"]])
    start_err = float(np.max(np.abs(np.concatenate([q[0], vel[0]]) - start)))
    h_z = m * (q[:, 0] * vel[:, 1] - q[:, 1] * vel[:, 0])
    momentum_err = float(np.max(np.abs(h_z - m * length * v["vy"])) / (m * length * v["vy"]))
    if elastic:
        spring = [(-1, 0, v["stiffness"], v["damping"], length)]
        energy_err = _spring_chain_energy_error(q, vel, t, [m], [0, 0, -g], spring)
        return start_err, momentum_err, energy_err, 0.0
    speed2 = np.sum(vel**2, axis=1)
    energy = 0.5 * m * speed2 + m * g * q[:, 2]
    scale = 0.5 * m * np.max(speed2)
    energy_err = float(np.max(np.abs(energy - energy[0])) / scale)
    tension = m * (speed2 - g * q[:, 2]) / length
    string_err = float(max(np.max(np.abs(force[:, 0] - tension)) / np.max(tension),
                           np.max(np.abs(np.linalg.norm(q, axis=1) - length)) / length))
    return start_err, momentum_err, energy_err, string_err


@pytest.mark.parametrize("seed", SEEDS)
def test_mass_point_on_rigid_string(seed):
    v, program = reference("mass_point_on_rigid_string", seed)
    start_err, momentum_err, energy_err, string_err = _string_errors(v, program, elastic=False)
    assert start_err < 1e-12
    assert momentum_err < 2e-5
    assert energy_err < 2e-5
    assert string_err < 3e-3


def test_mass_point_on_rigid_string_detects_wrong_parameters():
    v, program = reference("mass_point_on_rigid_string", 0)
    bad_mass = perturb(program, "mass=mass,", "mass=1.05 * mass,")
    assert _string_errors(v, bad_mass, elastic=False)[3] > 2e-2
    bad_gravity = perturb(program, "gravity=[0, 0, -gravity]", "gravity=[0, 0, -1.05 * gravity]")
    assert _string_errors(v, bad_gravity, elastic=False)[2] > 1e-2
    bad_length = perturb(program, "distance=length", "distance=1.01 * length")
    assert _string_errors(v, bad_length, elastic=False)[3] > 5e-3
    bad_velocity = perturb(program, "initialVelocity=[0, vy, vz]", "initialVelocity=[0, vy, 1.05 * vz]")
    assert _string_errors(v, bad_velocity, elastic=False)[0] > 1e-3


@pytest.mark.parametrize("seed", SEEDS)
def test_mass_point_on_elastic_string(seed):
    v, program = reference("mass_point_on_elastic_string", seed)
    start_err, momentum_err, energy_err, _ = _string_errors(v, program, elastic=True)
    assert start_err < 1e-12
    assert momentum_err < 2e-5
    assert energy_err < 2e-5


def test_mass_point_on_elastic_string_detects_wrong_parameters():
    v, program = reference("mass_point_on_elastic_string", 1, damping=10.0)
    for old, new in [
        ("mass=mass,", "mass=1.05 * mass,"),
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
        ("gravity=[0, 0, -gravity]", "gravity=[0, 0, -1.05 * gravity]"),
    ]:
        assert _string_errors(v, perturb(program, old, new), elastic=True)[2] > 1e-4, old


# ---------------------------------------------------------------------------------------------
# 27 two mass points with springs, 28 two mass points with distances


def _two_masses(v: dict, q: np.ndarray, vel: np.ndarray) -> float:
    """Largest relative deviation of the linear momentum and the angular momentum (about the
    origin) from their initial values [0, m1*v1 - m2*v2, 0] and [0, 0, -a*(m1*v1 + m2*v2)]."""
    m1, m2 = v["mass1"], v["mass2"]
    momentum = m1 * vel[:, :3] + m2 * vel[:, 3:]
    angular = m1 * np.cross(q[:, :3], vel[:, :3]) + m2 * np.cross(q[:, 3:], vel[:, 3:])
    p0 = np.array([0, m1 * v["velocity1"] - m2 * v["velocity2"], 0])
    a = v["half_distance"]
    h0 = np.array([0, 0, -a * (m1 * v["velocity1"] + m2 * v["velocity2"])])
    scale = m1 * v["velocity1"] + m2 * v["velocity2"]
    momentum_err = float(max(np.max(np.abs(momentum - p0)) / scale, np.max(np.abs(angular - h0)) / (a * scale)))
    return momentum_err


def _two_springs_errors(v: dict, program: str) -> tuple[float, float]:
    t, q, vel, _, _ = _run(program, refine=5, conservative=True)
    assert np.max(np.abs(q[:, [2, 5]])) == 0.0  # planar
    spring = [(0, 1, v["stiffness"], v["damping"], 2 * v["half_distance"])]
    energy_err = _spring_chain_energy_error(q, vel, t, [v["mass1"], v["mass2"]], [0, 0, 0], spring)
    return _two_masses(v, q, vel), energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_two_mass_points_with_springs(seed):
    v, program = reference("two_mass_points_with_springs", seed)
    momentum_err, energy_err = _two_springs_errors(v, program)
    assert momentum_err < 2e-5
    assert energy_err < 2e-5


def test_two_mass_points_with_springs_detects_wrong_parameters():
    v, program = reference("two_mass_points_with_springs", 0, damping=5.0)
    for old, new in [
        ("mass=mass1", "mass=1.05 * mass1"),
        ("initialVelocity=[0, -velocity2, 0]", "initialVelocity=[0, -1.05 * velocity2, 0]"),
    ]:
        assert _two_springs_errors(v, perturb(program, old, new))[0] > 1e-2, old
    for old, new in [
        ("stiffness=stiffness", "stiffness=1.05 * stiffness"),
        ("damping=damping", "damping=1.05 * damping"),
    ]:
        assert _two_springs_errors(v, perturb(program, old, new))[1] > 1e-4, old


def _dumbbell_errors(v: dict, program: str) -> tuple[float, float, float]:
    """(position error vs the closed form / a, rod force error / centripetal force, momentum error)."""
    t, q, vel, force, _ = _run(program, refine=5)
    m1, m2, a = v["mass1"], v["mass2"], v["half_distance"]
    v1, v2 = v["velocity1"], v["velocity2"]
    mt = m1 + m2
    centre = np.array([a * (m2 - m1) / mt, 0, 0]) + np.outer(t, [0, (m1 * v1 - m2 * v2) / mt, 0])
    omega = -(v1 + v2) / (2 * a)
    rel = 2 * a * np.column_stack([np.cos(omega * t), np.sin(omega * t), np.zeros_like(t)])
    exact = np.hstack([centre - m2 / mt * rel, centre + m1 / mt * rel])
    pos_err = float(np.max(np.abs(q - exact)) / a)
    centripetal = m1 * m2 / mt * omega**2 * 2 * a
    force_err = float(np.max(np.abs(force[:, 0] - centripetal)) / centripetal)
    return pos_err, force_err, _two_masses(v, q, vel)


@pytest.mark.parametrize("seed", SEEDS)
def test_two_mass_points_with_distances_closed_form(seed):
    v, program = reference("two_mass_points_with_distances", seed)
    pos_err, force_err, momentum_err = _dumbbell_errors(v, program)
    assert pos_err < 5e-5
    assert force_err < 1e-4
    assert momentum_err < 1e-6


def test_two_mass_points_with_distances_detects_wrong_parameters():
    v, program = reference("two_mass_points_with_distances", 0)
    for old, new in [
        ("mass=mass1", "mass=1.05 * mass1"),
        ("mass=mass2", "mass=1.05 * mass2"),
        ("initialVelocity=[0, velocity1, 0]", "initialVelocity=[0, 1.05 * velocity1, 0]"),
        ("distance=2 * half_distance", "distance=2.02 * half_distance"),
    ]:
        pos_err, force_err, _ = _dumbbell_errors(v, perturb(program, old, new))
        assert max(pos_err, force_err) > 1e-2, old
