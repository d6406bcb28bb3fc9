"""Physics checks of the level-1 mass-point ground truths against mechanics.

Tasks: flying mass point (1), free fall mass point (2), single mass oscillator with gravity (4),
double mass oscillator (9), double pendulum (12). Every check computes an error measure; the
tolerances are chosen well below what a wrong parameter in the ground truth produces, which the
``test_*_detects_*`` tests confirm by perturbing the reference program.
"""

from __future__ import annotations

import numpy as np
import pytest
from simulate import perturb, reference, retime, simulate

SEEDS = (0, 1, 2, 3)


# ---------------------------------------------------------------------------------------------
# 1 flying mass point, 2 free fall mass point: constant acceleration, reproduced to round-off


def _projectile_error(v: dict, program: str) -> float:
    t, q, _ = simulate(program)
    vx, vy, vz = v.get("vx", 0.0), v.get("vy", 0.0), v.get("vz", 0.0)
    x0, y0 = v.get("x0", 0.0), v.get("y0", 0.0)
    exact = np.column_stack([x0 + vx * t, y0 + vy * t, v["height"] + vz * t - 0.5 * v["gravity"] * t**2])
    assert q.shape == exact.shape
    return float(np.max(np.abs(q - exact)))


@pytest.mark.parametrize("seed", SEEDS)
def test_flying_mass_point_projectile(seed):
    v, program = reference("flying_mass_point", seed)
    assert _projectile_error(v, program) < 1e-8


@pytest.mark.parametrize("seed", SEEDS)
def test_free_fall_mass_point(seed):
    v, program = reference("free_fall_mass_point", seed)
    assert _projectile_error(v, program) < 1e-8


def test_projectile_detects_wrong_gravity():
    v, program = reference("flying_mass_point", 0)
    bad = perturb(program, "gravity=[0, 0, -gravity]", "gravity=[0, 0, -1.001 * gravity]")
    assert _projectile_error(v, bad) > 1e-4
    v, program = reference("free_fall_mass_point", 0)
    bad = perturb(program, "gravity=[0, 0, -gravity]", "gravity=[0, 0, -1.001 * gravity]")
    assert _projectile_error(v, bad) > 1e-4


# ---------------------------------------------------------------------------------------------
# 4 single mass oscillator with gravity


def _hanging_oscillator_error(v: dict, program: str) -> tuple[float, float, float]:
    """(trajectory error / amplitude, period error, equilibrium error / (m g / k)), undamped or damped."""
    t, q, _ = simulate(retime(program, refine=10, spectral_radius=1.0))
    m, k, d, g = v["mass"], v["stiffness"], v["damping"], v["gravity"]
    shift = m * g / k
    y_eq = -v["length"] - shift
    a0 = -v["length"] + v["displacement"] - y_eq  # initial offset from equilibrium
    omega = np.sqrt(k / m)
    delta = d / (2 * m)
    omega_d = np.sqrt(omega**2 - delta**2)
    y = y_eq + a0 * np.exp(-delta * t) * (np.cos(omega_d * t) + delta / omega_d * np.sin(omega_d * t))
    assert np.max(np.abs(q[:, [0, 2]])) == 0.0  # stays on the vertical axis
    traj_err = float(np.max(np.abs(q[:, 1] - y)) / abs(a0))
    # period from the upward crossings of the equilibrium level (linear interpolation)
    s = q[:, 1] - y_eq
    idx = np.nonzero((s[:-1] < 0) & (s[1:] >= 0))[0]
    crossings = t[idx] - s[idx] * (t[idx + 1] - t[idx]) / (s[idx + 1] - s[idx])
    period = float(np.mean(np.diff(crossings)))
    period_err = abs(period / (2 * np.pi / omega_d) - 1)
    # equilibrium: midpoint of the extremes over whole periods (undamped only)
    n_full = idx[-1] + 1
    eq_err = abs(0.5 * (q[:n_full, 1].max() + q[:n_full, 1].min()) - y_eq) / shift if d == 0 else 0.0
    return traj_err, period_err, eq_err


@pytest.mark.parametrize("seed", SEEDS)
def test_single_mass_oscillator_with_gravity_undamped(seed):
    v, program = reference("single_mass_oscillator_with_gravity", seed, damping=0.0)
    traj_err, period_err, eq_err = _hanging_oscillator_error(v, program)
    assert traj_err < 2e-3
    assert period_err < 1e-4
    assert eq_err < 1e-3


@pytest.mark.parametrize("seed", SEEDS)
def test_single_mass_oscillator_with_gravity_damped(seed):
    v, program = reference("single_mass_oscillator_with_gravity", seed)
    assert v["damping"] > 0
    traj_err, _, _ = _hanging_oscillator_error(v, program)
    assert traj_err < 2e-3


def test_single_mass_oscillator_with_gravity_detects_wrong_parameters():
    v, program = reference("single_mass_oscillator_with_gravity", 0, damping=0.0)
    bad_mass = perturb(program, "mass=mass,", "mass=1.01 * mass,")
    assert _hanging_oscillator_error(v, bad_mass)[0] > 1e-2
    bad_gravity = perturb(program, "gravity=[0, -gravity, 0]", "gravity=[0, -1.003 * gravity, 0]")
    assert _hanging_oscillator_error(v, bad_gravity)[2] > 2e-3


# ---------------------------------------------------------------------------------------------
# 9 double mass oscillator


def _double_oscillator_matrices(v: dict):
    m1, m2 = v["mass1"], v["mass2"]
    k1, k2 = v["stiffness1"], v["stiffness2"]
    d1, d2 = v["damping1"], v["damping2"]
    M = np.diag([m1, m2])
    K = np.array([[k1 + k2, -k2], [-k2, k2]])
    D = np.array([[d1 + d2, -d2], [-d2, d2]])
    return M, K, D


def _double_oscillator_error(v: dict, program: str) -> tuple[float, float]:
    """(trajectory error / initial displacement, relative energy drift if undamped)."""
    t, q, mbs = simulate(retime(program, refine=10, spectral_radius=1.0))
    M, K, D = _double_oscillator_matrices(v)
    assert np.max(np.abs(q[:, [1, 2, 4, 5]])) == 0.0  # motion stays on the x-axis
    x = np.column_stack([q[:, 0] - v["length1"], q[:, 3] - v["length1"] - v["length2"]])
    u = v["displacement"]
    x0 = np.array([0.0, u])
    if np.all(D == 0):
        # superposition of the two normal modes of K phi = omega^2 M phi
        lam, phi = np.linalg.eig(np.linalg.solve(M, K))
        omegas = np.sqrt(lam.real)
        coeff = np.linalg.solve(phi, x0)
        exact = (phi @ (coeff[:, None] * np.cos(omegas[:, None] * t[None, :]))).T
    else:
        # first-order form z' = A z, solved through the eigen-decomposition of A
        Minv = np.linalg.inv(M)
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ K, -Minv @ D]])
        lam, V = np.linalg.eig(A)
        c = np.linalg.solve(V, np.concatenate([x0, np.zeros(2)]))
        exact = (V[:2] @ (c[:, None] * np.exp(lam[:, None] * t[None, :]))).real.T
    traj_err = float(np.max(np.abs(x - exact)) / u)
    energy_err = 0.0
    if np.all(D == 0):
        vel = np.array(mbs.systemData.GetODE2Coordinates_t())[[0, 3]]
        energy = 0.5 * vel @ M @ vel + 0.5 * x[-1] @ K @ x[-1]
        e0 = 0.5 * x0 @ K @ x0
        energy_err = abs(energy / e0 - 1)
    return traj_err, energy_err


@pytest.mark.parametrize("seed", SEEDS)
def test_double_mass_oscillator_undamped_modes_and_energy(seed):
    v, program = reference("double_mass_oscillator", seed, damping1=0.0, damping2=0.0)
    traj_err, energy_err = _double_oscillator_error(v, program)
    assert traj_err < 5e-3
    assert energy_err < 1e-6


@pytest.mark.parametrize("seed", SEEDS)
def test_double_mass_oscillator_damped(seed):
    v, program = reference("double_mass_oscillator", seed)
    traj_err, _ = _double_oscillator_error(v, program)
    assert traj_err < 5e-3


def test_double_mass_oscillator_detects_wrong_parameters():
    v, program = reference("double_mass_oscillator", 0, damping1=0.0, damping2=0.0)
    for old, new in [
        ("mass=mass1", "mass=1.01 * mass1"),
        ("mass=mass2)", "mass=1.01 * mass2)"),
        ("stiffness=stiffness1", "stiffness=1.01 * stiffness1"),
        ("stiffness=stiffness2", "stiffness=1.01 * stiffness2"),
    ]:
        assert _double_oscillator_error(v, perturb(program, old, new))[0] > 2e-2, old
    v, program = reference("double_mass_oscillator", 0)
    bad = perturb(program, "damping=damping2", "damping=1.1 * damping2")
    assert _double_oscillator_error(v, bad)[0] > 1e-2


# ---------------------------------------------------------------------------------------------
# 12 double pendulum


def _double_pendulum_errors(v: dict, program: str) -> tuple[float, float, float, float]:
    """(initial position error, constraint error, relative energy error at the end and along the way).

    Run with 10x the steps (the default numerical damping; a spectral radius of 1 makes the
    index-3 velocities oscillate) so that central differences give accurate velocities.
    """
    t, q, mbs = simulate(retime(program, refine=10))
    m1, m2, g = v["mass1"], v["mass2"], v["gravity"]
    L1, L2 = v["length1"], v["length2"]
    phi1, phi2 = np.radians(v["angle1_deg"]), np.radians(v["angle2_deg"])
    p1 = np.array([L1 * np.sin(phi1), -L1 * np.cos(phi1), 0])
    p2 = p1 + np.array([L2 * np.sin(phi2), -L2 * np.cos(phi2), 0])
    init_err = float(np.max(np.abs(q[0] - np.concatenate([p1, p2]))))
    r1 = np.linalg.norm(q[:, :3], axis=1)
    r2 = np.linalg.norm(q[:, 3:] - q[:, :3], axis=1)
    constraint_err = float(max(np.max(np.abs(r1 - L1)), np.max(np.abs(r2 - L2))))
    assert np.max(np.abs(q[:, [2, 5]])) == 0.0  # planar motion

    def energy(pos, vel):
        kinetic = 0.5 * np.sum(m1 * vel[..., :3] ** 2 + m2 * vel[..., 3:] ** 2, axis=-1)
        return kinetic + g * (m1 * pos[..., 1] + m2 * pos[..., 4])

    scale = g * (m1 * L1 + m2 * (L1 + L2))  # range of the potential energy
    e0 = energy(q[0], np.zeros(6))
    e_end = energy(q[-1], np.array(mbs.systemData.GetODE2Coordinates_t()))
    h = t[1] - t[0]
    e_fd = energy(q[1:-1], (q[2:] - q[:-2]) / (2 * h))  # central-difference velocities
    return init_err, constraint_err, abs(e_end - e0) / scale, float(np.max(np.abs(e_fd - e0))) / scale


@pytest.mark.parametrize("seed", SEEDS)
def test_double_pendulum_energy_and_constraints(seed):
    v, program = reference("double_pendulum", seed)
    init_err, constraint_err, end_err, fd_err = _double_pendulum_errors(v, program)
    assert init_err < 1e-12
    assert constraint_err < 1e-8
    assert end_err < 1e-6
    assert fd_err < 1e-4


def test_double_pendulum_large_angles():
    """The corner of the parameter ranges with the fastest motion still conserves energy."""
    v, program = reference("double_pendulum", 0, angle1_deg=40.0, angle2_deg=-40.0, mass1=0.2, mass2=3.0)
    _, constraint_err, end_err, fd_err = _double_pendulum_errors(v, program)
    assert constraint_err < 1e-8
    assert end_err < 1e-6
    assert fd_err < 1e-4


def test_double_pendulum_detects_wrong_parameters():
    v, program = reference("double_pendulum", 1)
    bad_mass = perturb(program, "mass=mass2,", "mass=1.05 * mass2,")
    assert max(_double_pendulum_errors(v, bad_mass)[2:]) > 1e-3
    bad_gravity = perturb(
        program, "mass=mass1, gravity=[0, -gravity, 0]", "mass=mass1, gravity=[0, -1.05 * gravity, 0]"
    )
    assert max(_double_pendulum_errors(v, bad_gravity)[2:]) > 5e-4
    bad_length = perturb(program, "phi1 = angle1_deg", "length2 = 1.001 * length2\nphi1 = angle1_deg")
    init_err, constraint_err, _, _ = _double_pendulum_errors(v, bad_length)
    assert init_err > 1e-4
    assert constraint_err > 1e-4
    bad_angle = perturb(program, "phi2 = angle2_deg", "phi2 = 1.01 * angle2_deg")
    assert _double_pendulum_errors(v, bad_angle)[0] > 1e-4
