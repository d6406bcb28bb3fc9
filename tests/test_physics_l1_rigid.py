"""Physics checks of level-1 ground truths with rigid bodies, joints and springs against mechanics.

Tasks: spinning disc (8), spring coupled flying rigid bodies (14), torsional oscillator (15),
inverted single pendulum (16), link on two prismatic joints (22), suspended rigid body (24),
gyroscope on spherical joint (25), prismatic joint system (26), double pendulum / rigid bodies (30).

Every check computes an error measure from quantities recomputed here from the task parameters
(masses, inertias, closed-form solutions, or an independent RK4 integration of hand-derived
equations of motion), never read from the model. Each ``check_*`` function takes the nominal
parameters and a program and returns its largest error measure divided by that measure's
tolerance (so < 1 passes); the ``detects`` tests run it on programs built with one parameter 5 %
off and require a value > 3, so the tolerances are meaningful.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from simulate import cuboid, kinetic_energy, params, planar_angle, program_for, retime, simulate, simulate_bodies

SEEDS = (0, 1, 2)


# ---------------------------------------------------------------------------------------- helpers


def _program(slug: str, values: dict, *, refine: int = 1, spectral_radius: float | None = None) -> str:
    """The reference program for ``values``, optionally with more steps / no numerical damping."""
    return retime(program_for(slug, values), refine=refine, spectral_radius=spectral_radius)




def rk4(rhs: Callable[[list], list], y0, t_end: float, h: float, every: int) -> np.ndarray:
    """Fixed-step RK4 of an autonomous ODE on plain floats (fast for a few states); returns the
    states at t = 0, every*h, 2*every*h, ..."""
    y = [float(x) for x in y0]
    out = [y]
    for i in range(1, round(t_end / h) + 1):
        k1 = rhs(y)
        k2 = rhs([a + 0.5 * h * b for a, b in zip(y, k1, strict=True)])
        k3 = rhs([a + 0.5 * h * b for a, b in zip(y, k2, strict=True)])
        k4 = rhs([a + h * b for a, b in zip(y, k3, strict=True)])
        y = [a + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4) for a, b1, b2, b3, b4 in zip(y, k1, k2, k3, k4, strict=True)]
        if i % every == 0:
            out.append(y)
    return np.array(out)


def _solve2(a11: float, a12: float, a22: float, b1: float, b2: float) -> tuple[float, float]:
    """Solution of the symmetric 2x2 system [[a11, a12], [a12, a22]] x = b."""
    det = a11 * a22 - a12 * a12
    return (a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det


# ------------------------------------------------------------------------------- 8 spinning disc


def check_spinning_disc(v: dict, program: str) -> float:
    """Relative error of the rotation angle against omega0*t + T*t^2/(2*J), J = m*r^2/2 (tolerance
    1e-4), and of the fitted angular acceleration against T/J (1e-3); the centre stays fixed."""
    t, q, _ = simulate(program)
    j = 0.5 * v["mass"] * v["radius"] ** 2
    angle = planar_angle(q, 0, 3)
    exact = v["omega0"] * t + v["torque"] * t**2 / (2 * j)
    err_angle = np.max(np.abs(angle - exact)) / exact[-1]
    alpha = 2 * np.polyfit(t, angle, 2)[0]
    err_alpha = abs(alpha / (v["torque"] / j) - 1)
    assert np.max(np.abs(q[:, :3])) < 1e-10 and np.max(np.abs(q[:, 4:6])) < 1e-10
    return max(err_angle / 1e-4, err_alpha / 1e-3)


@pytest.mark.parametrize("seed", SEEDS)
def test_spinning_disc(seed):
    v = params("spinning_disc", seed)
    # the Euler-parameter integration has a relative spin-rate error ~ (omega*h)^2; refine 4x
    assert check_spinning_disc(v, _program("spinning_disc", v, refine=4)) < 1


# ------------------------------------------------------------------------ 15 torsional oscillator


def torsional_exact(v: dict, t: np.ndarray) -> np.ndarray:
    """J*phi'' + d*phi' + k*phi = T, phi(0) = 0, phi'(0) = omega0 (underdamped)."""
    j = 0.5 * v["mass"] * v["radius"] ** 2
    k, d, torque = v["stiffness"], v["damping"], v["torque"]
    delta = d / (2 * j)
    omega_d = math.sqrt(k / j - delta**2)
    a = -torque / k
    b = (v["omega0"] + delta * a) / omega_d
    return torque / k + np.exp(-delta * t) * (a * np.cos(omega_d * t) + b * np.sin(omega_d * t))


def check_torsional_oscillator(v: dict, program: str) -> float:
    """Max error of the rotation angle against the closed form, relative to its amplitude
    (tolerance 1e-3: the integrator's phase error over up to 40 periods at 8x refined steps)."""
    t, q, _ = simulate(program)
    angle = planar_angle(q, 0, 3)
    exact = torsional_exact(v, t)
    assert np.max(np.abs(q[:, :3])) < 1e-10
    return float(np.max(np.abs(angle - exact)) / np.max(np.abs(exact)) / 1e-3)


@pytest.mark.parametrize("seed", SEEDS)
def test_torsional_oscillator(seed):
    v = params("torsional_oscillator", seed)
    # period elongation of the integrator ~ (omega*h)^2/12: refine 8x for omega up to 120 rad/s
    assert check_torsional_oscillator(v, _program("torsional_oscillator", v, refine=8)) < 1


# ----------------------------------------------------------- 14 spring coupled flying rigid bodies


def check_spring_coupled(v: dict, program: str) -> dict[str, float]:
    """Momentum, energy and angular momentum balance of the two bodies (run with damping 0)."""
    a = v["size_x"]
    m, j = cuboid(v["density"], (a, v["size_y"], v["size_z"]))
    _, _, bodies = simulate_bodies(program)
    # linear momentum: the common centre of mass stays at [a, 0, 0]
    com = 0.5 * (bodies[0]["Position"] + bodies[1]["Position"])
    err_com = np.max(np.abs(com - [a, 0, 0])) / a
    # energy: kinetic + spring energy of the Cartesian spring between the two end points
    p1 = bodies[0]["Position"] + bodies[0]["RotationMatrix"] @ [0.5 * a, 0, 0]
    p2 = bodies[1]["Position"] + bodies[1]["RotationMatrix"] @ [-0.5 * a, 0, 0]
    energy = sum(kinetic_energy(b, m, j) for b in bodies) + 0.5 * v["stiffness"] * np.sum((p2 - p1) ** 2, axis=1)
    e0 = m * v["velocity"] ** 2
    err_energy = np.max(np.abs(energy - e0)) / e0
    # angular momentum about the origin (isotropic spring, no damping: conserved)
    momentum = 0
    for b in bodies:
        rot = b["RotationMatrix"]
        momentum = momentum + m * np.cross(b["Position"], b["Velocity"])
        momentum = momentum + np.einsum("nij,jk,nlk,nl->ni", rot, j, rot, b["AngularVelocity"])
    l0 = np.array([0, 0, m * v["velocity"] * (0.5 * a - 1.5 * a)])
    err_momentum = np.max(np.linalg.norm(momentum - l0, axis=1)) / np.linalg.norm(l0)
    return {"com": err_com, "energy": err_energy, "momentum": err_momentum}


@pytest.mark.parametrize("seed", SEEDS)
def test_spring_coupled_flying_rigid_bodies(seed):
    v = params("spring_coupled_flying_rigid_bodies", seed, damping=0.0)
    errors = check_spring_coupled(v, _program("spring_coupled_flying_rigid_bodies", v, refine=2,
                                              spectral_radius=1.0))
    assert errors["com"] < 1e-12
    assert errors["energy"] < 2e-4
    assert errors["momentum"] < 1e-4


@pytest.mark.parametrize("seed", SEEDS)
def test_spring_coupled_flying_rigid_bodies_damped(seed):
    """With damping, momentum is still conserved and the energy only decreases."""
    slug = "spring_coupled_flying_rigid_bodies"
    v = params(slug, seed, damping=20.0)
    errors = check_spring_coupled(v, _program(slug, v))
    assert errors["com"] < 1e-12
    assert errors["energy"] > 1e-2  # dissipated


# --------------------------------------------------------------------- 16 inverted single pendulum


def cart_pendulum_reference(v: dict, t_end: float, every_h: float) -> np.ndarray:
    """RK4 of the cart (x) and pendulum angle theta from the upright (bob at x + L*sin, L*cos):
    (M+m)*x'' + m*L*cos*theta'' - m*L*sin*theta'^2 = f;  m*L*cos*x'' + m*L^2*theta'' - m*g*L*sin = f*L*cos.
    Returns rows [x, theta, x', theta'] every ``every_h`` seconds."""
    big_m, m, length, f, g = v["cart_mass"], v["pendulum_mass"], v["length"], v["force"], v["gravity"]

    def rhs(y):
        _, th, xd, thd = y
        c, s = math.cos(th), math.sin(th)
        acc = _solve2(big_m + m, m * length * c, m * length**2,
                      f + m * length * s * thd**2, f * length * c + m * g * length * s)
        return [xd, thd, *acc]

    h = 1e-4
    return rk4(rhs, [0, 0, 0, 0], t_end, h, round(every_h / h))


def check_inverted_pendulum(v: dict, program: str) -> float:
    """Max position error of cart and pendulum mass against the RK4 reference, relative to L
    (tolerance 2e-3); the rod length L is kept (1e-8)."""
    t, q, _ = simulate(program)
    stride = (len(t) - 1) // 200
    t, q = t[::stride], q[::stride]
    ref = cart_pendulum_reference(v, t[-1], t[1] - t[0])
    length = v["length"]
    x, th = ref[:, 0], ref[:, 1]
    expected = np.column_stack([x, 0 * x, 0 * x, x + length * np.sin(th), length * np.cos(th), 0 * x])
    # the cart guide is kept and the pendulum stays in the x-y plane
    assert np.max(np.abs(q[:, 1:3])) < 1e-10 and np.max(np.abs(q[:, 5])) < 1e-10
    assert abs(th[-1]) > 0.5 * math.pi  # it has fallen over
    err_rod = np.max(np.abs(np.linalg.norm(q[:, 3:6] - q[:, :3], axis=1) - length))
    return float(max(np.max(np.abs(q - expected)) / length / 2e-3, err_rod / 1e-8))


@pytest.mark.parametrize("seed", SEEDS)
def test_inverted_single_pendulum(seed):
    v = params("inverted_single_pendulum", seed)
    assert check_inverted_pendulum(v, _program("inverted_single_pendulum", v, refine=4)) < 1


# ------------------------------------------------------------------ 22 link on two prismatic joints


def trammel_reference(v: dict, t_end: float, every_h: float) -> np.ndarray:
    """RK4 of the link angle theta (x1 = L*cos(theta), z2 = L*sin(theta)):
    M*theta'' + M'/2*theta'^2 + V' + d*L^2*sin^2*theta' = 0 with M = L^2*(m1*sin^2 + m2*cos^2),
    V = m2*g*L*sin + k/2*(L*cos - x0)^2. Returns rows [theta, theta']."""
    m1, m2, x0, z0 = v["mass1"], v["mass2"], v["x0"], v["z0"]
    k, d, g = v["stiffness"], v["damping"], v["gravity"]
    length = math.hypot(x0, z0)

    def rhs(y):
        th, thd = y
        c, s = math.cos(th), math.sin(th)
        mass = length**2 * (m1 * s * s + m2 * c * c)
        dmass = length**2 * 2 * s * c * (m1 - m2)
        dpot = m2 * g * length * c - k * (length * c - x0) * length * s
        return [thd, -(0.5 * dmass * thd**2 + dpot + d * length**2 * s * s * thd) / mass]

    h = 1e-4
    return rk4(rhs, [math.atan2(z0, x0), 0.0], t_end, h, round(every_h / h))


def check_link_on_two_prismatic_joints(v: dict, program: str) -> float:
    """Max error of x1 and z2 against the RK4 reference, relative to the range of motion of z2
    (tolerance 2e-3); the guides and the link length (1e-8) are kept."""
    t, q, _ = simulate(program)
    stride = (len(t) - 1) // 400
    t, q = t[::stride], q[::stride]
    ref = trammel_reference(v, t[-1], t[1] - t[0])
    length = math.hypot(v["x0"], v["z0"])
    expected = np.column_stack([length * np.cos(ref[:, 0]), length * np.sin(ref[:, 0])])
    assert np.max(np.abs(q[:, [1, 2, 3, 4]])) < 1e-10  # guides
    err_link = np.max(np.abs(np.hypot(q[:, 0], q[:, 5]) - length))
    motion = np.ptp(expected[:, 1])
    return float(max(np.max(np.abs(q[:, [0, 5]] - expected)) / motion / 2e-3, err_link / 1e-8))


@pytest.mark.parametrize("seed", SEEDS)
def test_link_on_two_prismatic_joints(seed):
    v = params("link_on_two_prismatic_joints", seed)
    program = _program("link_on_two_prismatic_joints", v, refine=4)
    assert check_link_on_two_prismatic_joints(v, program) < 1


# ------------------------------------------------------------------------ 24 suspended rigid body


def check_suspended_vertical(v: dict, program: str) -> float:
    """Run with vel_x = vel_z = 0: pure vertical motion m*y'' + 4*d*y' + 4*kv*y = -m*g from rest;
    error relative to the static sag m*g/(4*kv) (tolerance 2e-3)."""
    t, q, _ = simulate(program)
    m, _ = cuboid(v["density"], (v["size_x"], v["size_y"], v["size_z"]))
    k, d = 4 * v["stiffness_v"], 4 * v["damping"]
    sag = m * v["gravity"] / k
    delta = d / (2 * m)
    omega_d = math.sqrt(k / m - delta**2)
    exact = -sag + sag * np.exp(-delta * t) * (np.cos(omega_d * t) + delta / omega_d * np.sin(omega_d * t))
    assert np.max(np.abs(q[:, [0, 2, 4, 5, 6]])) < 1e-10  # no sway, no rotation
    return float(np.max(np.abs(q[:, 1] - exact)) / sag / 2e-3)


def check_suspended_energy(v: dict, program: str) -> float:
    """Run with damping 0: kinetic + gravity + spring energy of the four mounts is conserved;
    error relative to the initial kinetic energy (tolerance 1e-3)."""
    a, b, c = v["size_x"], v["size_y"], v["size_z"]
    m, j = cuboid(v["density"], (a, b, c))
    stiffness = np.array([v["stiffness_h"], v["stiffness_v"], v["stiffness_h"]])
    _, _, (body,) = simulate_bodies(program)
    energy = kinetic_energy(body, m, j) + m * v["gravity"] * body["Position"][:, 1]
    for sx in (-1, 1):
        for sz in (-1, 1):
            corner = np.array([sx * a / 2, b / 2, sz * c / 2])
            stretch = body["Position"] + body["RotationMatrix"] @ corner - corner
            energy = energy + 0.5 * np.sum(stiffness * stretch**2, axis=1)
    e0 = 0.5 * m * (v["vel_x"] ** 2 + v["vel_z"] ** 2)
    return float(np.max(np.abs(energy - e0)) / e0 / 1e-3)


@pytest.mark.parametrize("seed", SEEDS)
def test_suspended_rigid_body_vertical(seed):
    v = params("suspended_rigid_body", seed, vel_x=0.0, vel_z=0.0)
    assert check_suspended_vertical(v, _program("suspended_rigid_body", v, refine=4)) < 1


@pytest.mark.parametrize("seed", SEEDS)
def test_suspended_rigid_body_energy(seed):
    v = params("suspended_rigid_body", seed, damping=0.0)
    program = _program("suspended_rigid_body", v, refine=2, spectral_radius=1.0)
    assert check_suspended_energy(v, program) < 1


# ------------------------------------------------------------------ 25 gyroscope on spherical joint


def heavy_top_reference(v: dict, t_end: float, every_h: float) -> np.ndarray:
    """RK4 of a rigid body about a fixed point in body axes (x = disc axis), Euler parameters
    (w, x, y, z): J_O*om' = -om x J_O*om + c x R^T*[0, 0, -m*g], q' = q*(0, om)/2, c = [a, 0, 0],
    J_O = diag(m*r^2/2, J1, J1) with J1 = m*(r^2/4 + w^2/12) + m*a^2. Returns the centre of mass
    R*c every ``every_h`` seconds."""
    m, r, w, a, g = v["mass"], v["radius"], v["width"], v["offset"], v["gravity"]
    j3 = 0.5 * m * r * r
    j1 = m * (r * r / 4 + w * w / 12) + m * a * a

    def rhs(y):
        q0, q1, q2, q3, o1, o2, o3 = y
        n2 = q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3
        # R^T*[0, 0, -m*g] = -m*g*(third row of R); torque c x (...) = [0, -a*u3, a*u2]
        u2 = -m * g * 2 * (q2 * q3 + q0 * q1) / n2
        u3 = -m * g * (1 - 2 * (q1 * q1 + q2 * q2) / n2)
        do1 = -(j1 - j1) * o2 * o3 / j3
        do2 = (-a * u3 - (j3 - j1) * o3 * o1) / j1
        do3 = (a * u2 - (j1 - j3) * o1 * o2) / j1
        return [0.5 * (-q1 * o1 - q2 * o2 - q3 * o3), 0.5 * (q0 * o1 + q2 * o3 - q3 * o2),
                0.5 * (q0 * o2 - q1 * o3 + q3 * o1), 0.5 * (q0 * o3 + q1 * o2 - q2 * o1), do1, do2, do3]

    h = 1e-4
    states = rk4(rhs, [1, 0, 0, 0, v["omega0"], 0, 0], t_end, h, round(every_h / h))
    q0, q1, q2, q3 = (states[:, i] / np.linalg.norm(states[:, :4], axis=1) for i in range(4))
    return a * np.column_stack([1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 + q0 * q3), 2 * (q1 * q3 - q0 * q2)])


def check_gyroscope(v: dict, program: str) -> float:
    """Max error of the centre of mass against the RK4 heavy top, relative to the offset a
    (tolerance 1e-3); the joint keeps the centre of mass at distance a (1e-9)."""
    t, q, _ = simulate(program)
    stride = (len(t) - 1) // 100
    t, q = t[::stride], q[::stride]
    ref = heavy_top_reference(v, t[-1], t[1] - t[0])
    err_joint = np.max(np.abs(np.linalg.norm(q[:, :3], axis=1) - v["offset"]))
    return float(max(np.max(np.abs(q[:, :3] - ref)) / v["offset"] / 1e-3, err_joint / 1e-9))


@pytest.mark.parametrize("seed", SEEDS[:2])
def test_gyroscope_on_spherical_joint(seed):
    v = params("gyroscope_on_spherical_joint", seed)
    assert check_gyroscope(v, _program("gyroscope_on_spherical_joint", v, refine=4)) < 1


@pytest.mark.parametrize("seed", SEEDS)
def test_gyroscope_precession_and_invariants(seed):
    """Mean precession rate ~ m*g*a/(J3*omega) (fast top); energy, vertical angular momentum and
    spin about the disc axis are conserved."""
    slug = "gyroscope_on_spherical_joint"
    v = params(slug, seed)
    m, r, w, a, g = v["mass"], v["radius"], v["width"], v["offset"], v["gravity"]
    j_axis = 0.5 * m * r * r
    j_c = np.diag([j_axis, m * (r * r / 4 + w * w / 12), m * (r * r / 4 + w * w / 12)])
    t, q, (disc,) = simulate_bodies(_program(slug, v, refine=2))
    precession = np.unwrap(np.arctan2(q[:, 1], q[:, 0]))
    rate = np.polyfit(t, precession, 1)[0]
    assert rate == pytest.approx(m * g * a / (j_axis * v["omega0"]), rel=1e-2)
    energy = kinetic_energy(disc, m, j_c) + m * g * disc["Position"][:, 2]
    e0 = 0.5 * j_axis * v["omega0"] ** 2
    assert np.max(np.abs(energy - e0)) < 1e-4 * e0
    rot, om = disc["RotationMatrix"], disc["AngularVelocity"]
    momentum = m * np.cross(disc["Position"], disc["Velocity"]) + np.einsum("nij,jk,nlk,nl->ni", rot, j_c, rot, om)
    assert np.max(np.abs(momentum[:, 2])) < 1e-4 * j_axis * v["omega0"]
    spin = np.einsum("ni,ni->n", om, rot[:, :, 0])
    assert np.max(np.abs(spin / v["omega0"] - 1)) < 1e-4


# ------------------------------------------------------------------------ 26 prismatic joint system


def check_prismatic(v: dict, program: str) -> float:
    """Max error of y(t) = v0*t + (Fy/m - g)*t^2/2 (tolerance 1e-8 m); the block does not move
    sideways or rotate."""
    t, q, _ = simulate(program)
    exact = v["vel_y"] * t + 0.5 * (v["force_y"] / v["mass"] - v["gravity"]) * t**2
    assert np.max(np.abs(q[:, [0, 2, 4, 5, 6]])) < 1e-10 and np.max(np.abs(q[:, 3] - 1)) < 1e-10
    return float(np.max(np.abs(q[:, 1] - exact)) / 1e-8)


@pytest.mark.parametrize("seed", SEEDS)
def test_prismatic_joint_system(seed):
    v = params("prismatic_joint_system", seed)
    assert check_prismatic(v, _program("prismatic_joint_system", v)) < 1


# ----------------------------------------------------------------- 30 double pendulum / rigid bodies


def double_pendulum_reference(v: dict, t_end: float, every_h: float) -> np.ndarray:
    """RK4 of the absolute link angles b1, b2 (local x-axes [cos b, sin b]) of two cuboid links:
    M11*b1'' + M12*b2'' + c*sin(b1-b2)*b2'^2 + (m1/2 + m2)*g*L1*cos(b1) = 0,
    M12*b1'' + M22*b2'' - c*sin(b1-b2)*b1'^2 + m2*g*L2/2*cos(b2) = 0, c = m2*L1*L2/2.
    Returns rows [b1, b2, b1', b2']."""
    l1, l2, w, h_, rho, g = (v[k] for k in ("length1", "length2", "width", "thickness", "density", "gravity"))
    m1, m2 = rho * l1 * w * h_, rho * l2 * w * h_
    j1, j2 = m1 * (l1 * l1 + w * w) / 12, m2 * (l2 * l2 + w * w) / 12
    m11 = m1 * l1 * l1 / 4 + j1 + m2 * l1 * l1
    m22 = m2 * l2 * l2 / 4 + j2
    c = m2 * l1 * l2 / 2

    def rhs(y):
        b1, b2, d1, d2 = y
        m12 = c * math.cos(b1 - b2)
        s = c * math.sin(b1 - b2)
        acc = _solve2(m11, m12, m22, -s * d2**2 - (m1 / 2 + m2) * g * l1 * math.cos(b1),
                      s * d1**2 - m2 * g * l2 / 2 * math.cos(b2))
        return [d1, d2, *acc]

    phi0 = math.radians(v["angle_deg"])
    h = 1e-4
    return rk4(rhs, [-phi0, -phi0, 0, 0], t_end, h, round(every_h / h))


def check_double_pendulum_rigid(v: dict, program: str) -> float:
    """Max error of both link angles against the RK4 reference (tolerance 2e-3 rad); the joints
    keep the links connected (1e-8 m)."""
    t, q, _ = simulate(program)
    stride = (len(t) - 1) // 200
    t, q = t[::stride], q[::stride]
    ref = double_pendulum_reference(v, t[-1], t[1] - t[0])
    b1, b2 = planar_angle(q, 0, 3), planar_angle(q, 7, 3)
    l1, l2 = v["length1"], v["length2"]
    e1 = np.column_stack([np.cos(b1), np.sin(b1), 0 * b1])
    e2 = np.column_stack([np.cos(b2), np.sin(b2), 0 * b2])
    err_joints = max(np.max(np.abs(q[:, :3] - 0.5 * l1 * e1)), np.max(np.abs(q[:, 7:10] - (l1 * e1 + 0.5 * l2 * e2))))
    err_angles = max(np.max(np.abs(b1 - ref[:, 0])), np.max(np.abs(b2 - ref[:, 1])))
    return float(max(err_angles / 2e-3, err_joints / 1e-8))


@pytest.mark.parametrize("seed", SEEDS)
def test_double_pendulum_rigid_bodies(seed):
    v = params("double_pendulum_rigid_bodies", seed)
    assert check_double_pendulum_rigid(v, _program("double_pendulum_rigid_bodies", v, refine=4)) < 1


# ------------------------------------------------- a 5 % wrong parameter in a ground truth is detected

#: (slug, check, refine, spectral radius, overrides, parameter made 5 % wrong)
DETECTS = [
    ("spinning_disc", check_spinning_disc, 4, None, {}, "mass"),
    ("spinning_disc", check_spinning_disc, 4, None, {}, "omega0"),
    ("torsional_oscillator", check_torsional_oscillator, 8, None, {}, "stiffness"),
    ("torsional_oscillator", check_torsional_oscillator, 8, None, {}, "radius"),
    ("torsional_oscillator", check_torsional_oscillator, 8, None, {}, "torque"),
    ("inverted_single_pendulum", check_inverted_pendulum, 4, None, {}, "pendulum_mass"),
    ("inverted_single_pendulum", check_inverted_pendulum, 4, None, {}, "force"),
    ("link_on_two_prismatic_joints", check_link_on_two_prismatic_joints, 4, None, {}, "stiffness"),
    ("link_on_two_prismatic_joints", check_link_on_two_prismatic_joints, 4, None, {}, "mass1"),
    ("suspended_rigid_body", check_suspended_vertical, 4, None, {"vel_x": 0.0, "vel_z": 0.0}, "stiffness_v"),
    ("suspended_rigid_body", check_suspended_energy, 2, 1.0, {"damping": 0.0}, "stiffness_h"),
    ("gyroscope_on_spherical_joint", check_gyroscope, 4, None, {}, "offset"),
    ("gyroscope_on_spherical_joint", check_gyroscope, 4, None, {}, "omega0"),
    ("prismatic_joint_system", check_prismatic, 1, None, {}, "mass"),
    ("double_pendulum_rigid_bodies", check_double_pendulum_rigid, 4, None, {}, "length2"),
    ("double_pendulum_rigid_bodies", check_double_pendulum_rigid, 4, None, {}, "gravity"),
]


@pytest.mark.parametrize(("slug", "check", "refine", "rho", "overrides", "name"), DETECTS,
                         ids=[f"{d[0]}-{d[-1]}" for d in DETECTS])
def test_check_detects_wrong_parameter(slug, check, refine, rho, overrides, name):
    v = params(slug, 5, **overrides)
    program = _program(slug, dict(v, **{name: 1.05 * v[name]}), refine=refine, spectral_radius=rho)
    assert check(v, program) > 3


@pytest.mark.parametrize("name", ["stiffness", "density"])
def test_spring_coupled_detects_wrong_parameter(name):
    slug = "spring_coupled_flying_rigid_bodies"
    v = params(slug, 5, damping=0.0)
    program = _program(slug, dict(v, **{name: 1.05 * v[name]}), refine=2, spectral_radius=1.0)
    assert check_spring_coupled(v, program)["energy"] > 3 * 2e-4
