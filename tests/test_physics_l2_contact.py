"""Physics checks of the level-2 contact and rolling ground truths against mechanics.

Tasks: disc rolling on ground (32), sphere-sphere impact (39), falling mass point with ground
contact (40), sphere-sphere and sphere-ground impact (41), pendulum wall impacting (42), billiard
with 4 spheres (44), grid mesh and large sphere impact (45), non-steerable scooter (46) and
non-steerable four-wheeled car (47).

Masses, inertias and expected values are recomputed here from the parameters (not read from the
model), so a wrong parameter in a ground truth shows up as a violated balance law, a wrong
restitution ratio or a wrong acceleration. Impacts are measured where the contact gap, computed
from the positions, closes and opens again; some checks override parameters (within their ranges
where possible) to isolate one effect, e.g. a head-on impact or a stiff, light ball so that gravity
during the short contact does not bias the restitution ratio.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from simulate import reference, retime, simulate, simulate_bodies

SEEDS = (0, 1, 2)

#: Added before ``mbs.Assemble()``: position, velocity (and for rigid bodies angular velocity and
#: rotation matrix) sensors for every body, in creation order, recorded at every step.
def _program(slug: str, seed: int, *, extra: str = "", **overrides) -> tuple[dict, str]:
    values, program = reference(slug, seed, **overrides)
    return values, retime(program, extra=extra)


def _bodies(program: str) -> tuple[np.ndarray, np.ndarray, list[dict[str, np.ndarray]]]:
    """Body sensors on every mass point and rigid body, in creation order."""
    return simulate_bodies(program, mass_points=True)

def _crossings(t: np.ndarray, gap: np.ndarray) -> list[tuple[int, float, str]]:
    """Sign changes of a contact gap: (index before, interpolation factor, 'close'|'open')."""
    out = []
    for i in np.nonzero(np.sign(gap[:-1]) != np.sign(gap[1:]))[0]:
        s = gap[i] / (gap[i] - gap[i + 1])
        out.append((int(i), float(s), "close" if gap[i] > 0 else "open"))
    return out


def _before(t: np.ndarray, values: np.ndarray, crossing: tuple, acc=0.0) -> np.ndarray:
    """Value at a closing crossing, from the last contact-free step and the free acceleration."""
    i, s, _ = crossing
    return values[i] + np.multiply(acc, s * (t[i + 1] - t[i]))


def _after(t: np.ndarray, values: np.ndarray, crossing: tuple, acc=0.0) -> np.ndarray:
    """Value at an opening crossing, from the first contact-free step and the free acceleration."""
    i, s, _ = crossing
    return values[i + 1] - np.multiply(acc, (1 - s) * (t[i + 1] - t[i]))


def _assert_contact_starts(t: np.ndarray, vel: np.ndarray, crossing: tuple, acc=0.0) -> None:
    """The contact force sets in exactly where the gap computed from the given radii closes: free
    motion up to the step before, a clear deviation from it two steps after."""
    i = crossing[0]
    scale = np.linalg.norm(vel[i])
    assert np.linalg.norm(vel[i] - vel[i - 5] - np.multiply(acc, t[i] - t[i - 5])) < 1e-9 * scale
    assert np.linalg.norm(vel[i + 3] - vel[i] - np.multiply(acc, t[i + 3] - t[i])) > 1e-5 * scale


def _at(values: np.ndarray, crossing: tuple) -> np.ndarray:
    """Linear interpolation of ``values`` (e.g. positions) at a gap crossing."""
    i, s, _ = crossing
    return values[i] + s * (values[i + 1] - values[i])


def _impacts(t: np.ndarray, gap: np.ndarray) -> list[tuple[tuple, tuple]]:
    """Pairs of (closing, opening) crossings, one per complete impact."""
    cs = _crossings(t, gap)
    pairs = []
    for a, b in itertools.pairwise(cs):
        if a[2] == "close" and b[2] == "open":
            pairs.append((a, b))
    return pairs


def _cylinder(density: float, length: float, radius: float) -> tuple[float, float]:
    """Mass and polar moment of inertia of a solid cylinder."""
    m = density * math.pi * radius**2 * length
    return m, 0.5 * m * radius**2


# ------------------------------------------------------------------------ 39 sphere-sphere impact


@pytest.mark.parametrize("seed", SEEDS)
def test_sphere_sphere_impact_momentum_and_oblique_restitution(seed):
    p, program = _program("sphere_sphere_impact", seed)
    t, _, (b0, b1) = _bodies(program)
    m0, m1 = p["mass0"], p["mass1"]
    momentum = m0 * b0["Velocity"] + m1 * b1["Velocity"]
    assert np.max(np.abs(momentum - [m0 * p["velocity"], 0, 0])) < 1e-10 * m0 * p["velocity"]
    # exactly one impact; the relative velocity along the line of centres is reversed with factor e,
    # the tangential relative velocity is kept (no friction)
    rel = b1["Position"] - b0["Position"]
    gap = np.linalg.norm(rel, axis=1) - p["radius0"] - p["radius1"]
    ((close, open_),) = _impacts(t, gap)
    vrel = b1["Velocity"] - b0["Velocity"]
    _assert_contact_starts(t, vrel, close)
    n_in = _at(rel, close) / np.linalg.norm(_at(rel, close))
    n_out = _at(rel, open_) / np.linalg.norm(_at(rel, open_))
    vn_in, vn_out = _before(t, vrel, close) @ n_in, _after(t, vrel, open_) @ n_out
    assert vn_in == pytest.approx(-p["velocity"] * math.sqrt(1 - (p["offset"] / (p["radius0"] + p["radius1"]))**2),
                                  rel=1e-6)
    # the normal turns during the contact: the ratio along the normals at closing/opening and the one
    # along the mean impulse direction err in opposite directions; their mean is accurate
    impulse = b1["Velocity"][-1] - b1["Velocity"][0]
    n_mean = impulse / np.linalg.norm(impulse)
    ratio = 0.5 * (-vn_out / vn_in - (vrel[-1] @ n_mean) / (vrel[0] @ n_mean))
    assert ratio == pytest.approx(p["restitution"], rel=2e-3)
    # contact is over at the end: kinetic energy lost = (1 - e^2) * mu * vn^2 / 2 (approximately, the
    # normal turns slightly during the contact)
    mu = m0 * m1 / (m0 + m1)
    ke = 0.5 * m0 * np.sum(b0["Velocity"]**2, axis=1) + 0.5 * m1 * np.sum(b1["Velocity"]**2, axis=1)
    assert ke[0] - ke[-1] == pytest.approx(0.5 * mu * (1 - p["restitution"]**2) * vn_in**2, rel=1e-2)


@pytest.mark.parametrize("seed", SEEDS)
def test_sphere_sphere_impact_head_on(seed):
    p, program = _program("sphere_sphere_impact", seed, offset=0.0)
    _, q, (b0, b1) = _bodies(program)
    m0, m1, e, v = p["mass0"], p["mass1"], p["restitution"], p["velocity"]
    expected0 = (m0 - e * m1) * v / (m0 + m1)
    expected1 = (1 + e) * m0 * v / (m0 + m1)
    assert b0["Velocity"][-1, 0] == pytest.approx(expected0, abs=2e-4 * v)
    assert b1["Velocity"][-1, 0] == pytest.approx(expected1, rel=2e-4)
    assert np.max(np.abs(q[:, [1, 2, 4, 5]])) < 1e-12  # stays on the x-axis


# -------------------------------------------------------- 40 falling mass point with ground contact


@pytest.mark.parametrize("seed", SEEDS)
def test_falling_mass_point_free_flight_and_rebound(seed):
    # a light ball on a stiff contact: gravity during the contact changes the ratio by < 0.7 %
    p, program = _program("falling_mass_point_with_ground_contact", seed, mass=0.1, stiffness=5e4)
    t, q, (ball,) = _bodies(program)
    g, r, h, vx = p["gravity"], p["radius"], p["height"], p["velocity"]
    # exact gap to the ground sphere (radius 1000 m, centre 1000 m below the origin)
    pos, vel = ball["Position"], ball["Velocity"]
    gap = np.linalg.norm(pos - [0, 0, -1000.0], axis=1) - 1000.0 - r
    impacts = _impacts(t, gap)
    assert len(impacts) >= 1
    close, open_ = impacts[0]
    _assert_contact_starts(t, vel, close, [0, 0, -g])
    free = t < t[close[0]]
    parabola = np.column_stack([vx * t, 0 * t, h - 0.5 * g * t**2])
    assert np.max(np.abs(q[free] - parabola[free])) < 1e-9
    v_in, v_out = _before(t, vel, close, [0, 0, -g]), _after(t, vel, open_, [0, 0, -g])
    assert -v_in[2] == pytest.approx(math.sqrt(2 * g * (h - r)), rel=1e-4)
    assert -v_out[2] / v_in[2] == pytest.approx(p["restitution"], rel=1e-2)
    # the ground sphere's normal at the contact point is tilted by x/1000 towards +x
    x_contact = _at(pos, close)[0]
    assert v_out[0] == pytest.approx(vx + (v_out[2] - v_in[2]) * x_contact / 1000, abs=1e-4 * vx)


# ---------------------------------------------------- 41 sphere-sphere and sphere-ground impact


@pytest.mark.parametrize("seed", SEEDS)
def test_stacked_balls_floor_and_sphere_impacts(seed):
    p, program = _program("sphere_sphere_and_sphere_ground_impact", seed, mass0=0.1, stiffness=5e4)
    t, q, (s0, s1) = _bodies(program)
    g, e = p["gravity"], p["restitution"]
    m0, m1, r0, r1 = p["mass0"], p["mass1"], p["radius0"], p["radius1"]
    floor0 = _impacts(t, s0["Position"][:, 2] - r0)
    rel = s1["Position"] - s0["Position"]
    pair = _impacts(t, np.linalg.norm(rel, axis=1) - r0 - r1)
    assert len(floor0) >= 1 and len(pair) == 1
    (f_close, f_open), (p_close, p_open) = floor0[0], pair[0]
    assert f_open[0] < p_close[0]  # floor impact over before the balls meet
    # free fall of both balls up to the floor impact
    free = t < t[f_close[0]]
    z0 = np.array([0, 0, p["height"]])
    z1 = np.array([p["offset"], 0, p["height"] + r0 + r1 + p["gap"]])
    fall = np.outer(0.5 * t**2, [0, 0, -g])
    assert np.max(np.abs(s0["Position"][free] - z0 - fall[free])) < 1e-9
    assert np.max(np.abs(s1["Position"][free] - z1 - fall[free])) < 1e-9
    # floor rebound
    v_in = _before(t, s0["Velocity"][:, 2], f_close, -g)
    assert -v_in == pytest.approx(math.sqrt(2 * g * (p["height"] - r0)), rel=1e-4)
    assert -_after(t, s0["Velocity"][:, 2], f_open, -g) / v_in == pytest.approx(e, rel=1e-2)
    # between the floor impacts, momentum only changes by the weight (the sphere-sphere contact is
    # internal); the integrator's algorithmic accelerations need some 50 steps to settle after the impact
    floor_next = floor0[1][0][0] if len(floor0) > 1 else len(t) - 1
    window = slice(f_open[0] + 50, floor_next)
    momentum = m0 * s0["Velocity"][window] + m1 * s1["Velocity"][window]
    momentum = momentum + np.outer(t[window], [0, 0, (m0 + m1) * g])
    assert np.max(np.abs(momentum - momentum[0])) < 1e-8 * np.abs(momentum[0]).max()
    # relative normal velocity reversed with factor e (uniform gravity does not act on it)
    vrel = s1["Velocity"] - s0["Velocity"]
    n_in = _at(rel, p_close) / np.linalg.norm(_at(rel, p_close))
    n_out = _at(rel, p_open) / np.linalg.norm(_at(rel, p_open))
    assert -(_after(t, vrel, p_open) @ n_out) / (_before(t, vrel, p_close) @ n_in) == pytest.approx(e, rel=5e-3)
    # rotation stays zero (no friction)
    assert np.max(np.abs(q[:, [4, 5, 6, 11, 12, 13]])) < 1e-12


# ------------------------------------------------------------------- 42 pendulum wall impacting


@pytest.mark.parametrize("seed", SEEDS)
def test_pendulum_wall_impact(seed):
    p, program = _program("pendulum_wall_impacting", seed, mass=0.1, stiffness=5e4,
                          extra="simulationSettings.timeIntegration.generalizedAlpha.spectralRadius = 1")
    t, _, (bob,) = _bodies(program)
    pos, vel = bob["Position"], bob["Velocity"]
    L, g = p["length"], p["gravity"]
    assert np.max(np.abs(np.linalg.norm(pos, axis=1) - L)) < 1e-9 * L
    assert np.max(np.abs(pos[:, 1])) < 1e-12
    impacts = _impacts(t, -pos[:, 0])  # wall x = r: gap = r - (x + r)
    assert len(impacts) >= 1
    close, open_ = impacts[0]
    phi0 = math.radians(p["angle_deg"])
    v_in = _before(t, vel, close)
    assert v_in[0] == pytest.approx(math.sqrt(2 * g * L * (1 - math.cos(phi0))), rel=1e-4)
    assert abs(v_in[2]) < 1e-3 * v_in[0]  # horizontal at the lowest point
    assert -_after(t, vel, open_)[0] / v_in[0] == pytest.approx(p["restitution"], rel=5e-3)


# ------------------------------------------------------------------- 44 billiard with 4 spheres


def _billiard_kinetic(p: dict, balls: list[dict]) -> np.ndarray:
    return sum(0.5 * p["mass"] * np.sum(b["Velocity"]**2, axis=1) for b in balls)


@pytest.mark.parametrize("seed", SEEDS)
def test_billiard_momentum_and_energy(seed):
    p, program = _program("billiard_with_4_spheres", seed)
    _, q, balls = _bodies(program)
    m, v = p["mass"], p["velocity"]
    s = 2 * p["radius"] + p["gap"]
    x2 = p["distance"] + s * math.sqrt(3) / 2
    start = [[0, p["offset"], 0], [p["distance"], 0, 0], [x2, s / 2, 0], [x2, -s / 2, 0]]
    assert np.allclose(q[0], np.ravel(start), rtol=0, atol=1e-14)
    momentum = sum(m * b["Velocity"] for b in balls)
    assert np.max(np.abs(momentum - [m * v, 0, 0])) < 1e-10 * m * v
    assert np.max(np.abs(q[:, 2::3])) < 1e-14  # stays in the table plane
    ke = _billiard_kinetic(p, balls)
    assert ke[-1] < ke[0]
    # the two rear balls are hit
    assert min(np.linalg.norm(b["Velocity"][-1]) for b in balls[2:]) > 0.1 * v
    # with e = 1 the break is elastic: kinetic energy kept once all contacts are open
    p1, program1 = _program("billiard_with_4_spheres", seed, restitution=1.0,
                            extra="simulationSettings.timeIntegration.generalizedAlpha.spectralRadius = 1")
    _, _, balls1 = _bodies(program1)
    ke1 = _billiard_kinetic(p1, balls1)
    assert ke1[-1] == pytest.approx(ke1[0], rel=2e-3)


@pytest.mark.parametrize("seed", SEEDS)
def test_billiard_first_impact_head_on(seed):
    # head-on and with the rack far apart, the first impact is a classical straight central impact
    p, program = _program("billiard_with_4_spheres", seed, offset=0.0, gap=0.1)
    t, _, balls = _bodies(program)
    e, v, r = p["restitution"], p["velocity"], p["radius"]
    rel = balls[1]["Position"] - balls[0]["Position"]
    close, open_ = _impacts(t, np.linalg.norm(rel, axis=1) - 2 * r)[0]
    _assert_contact_starts(t, balls[1]["Velocity"] - balls[0]["Velocity"], close)
    assert _after(t, balls[0]["Velocity"], open_)[0] == pytest.approx(v * (1 - e) / 2, abs=1e-3 * v)
    assert _after(t, balls[1]["Velocity"], open_)[0] == pytest.approx(v * (1 + e) / 2, rel=1e-3)


# ---------------------------------------------------------- 45 grid mesh and large sphere impact


def _net_energy(p: dict, t: np.ndarray, bodies: list[dict]) -> np.ndarray:
    n, a, g = p["n"], p["spacing"], 9.81
    L0 = (1 - p["prestrain"]) * a
    nodes, sphere = bodies[:-1], bodies[-1]
    assert len(nodes) == n * n
    pos = {(i, j): nodes[(j - 1) * n + (i - 1)]["Position"] for j in range(1, n + 1) for i in range(1, n + 1)}

    def point(i, j):
        return pos[(i, j)] if (i, j) in pos else np.array([i * a, j * a, 0.0])

    energy = np.zeros(len(t))
    for b in nodes:
        energy += 0.5 * p["node_mass"] * np.sum(b["Velocity"]**2, axis=1) + p["node_mass"] * g * b["Position"][:, 2]
    energy += 0.5 * p["sphere_mass"] * np.sum(sphere["Velocity"]**2, axis=1)
    energy += p["sphere_mass"] * g * sphere["Position"][:, 2]
    springs = [((i, j), (i + 1, j)) for j in range(1, n + 1) for i in range(n + 1)]
    springs += [((i, j), (i, j + 1)) for i in range(1, n + 1) for j in range(n + 1)]
    for pa, pb in springs:
        length = np.linalg.norm(np.broadcast_to(point(*pa), (len(t), 3)) - point(*pb), axis=1)
        energy += 0.5 * p["spring_stiffness"] * (length - L0)**2
    for b in nodes:
        overlap = np.maximum(p["sphere_radius"] + 0.01 - np.linalg.norm(sphere["Position"] - b["Position"], axis=1), 0)
        energy += 0.5 * p["contact_stiffness"] * overlap**2
    return energy


@pytest.mark.parametrize("seed", SEEDS)
def test_grid_mesh_energy_and_symmetry(seed):
    p, program = _program("grid_mesh_and_large_sphere_impact", seed, restitution=1.0,
                          extra="simulationSettings.timeIntegration.generalizedAlpha.spectralRadius = 1")
    t, q, bodies = _bodies(program)
    n, a = p["n"], p["spacing"]
    sphere = bodies[-1]
    energy = _net_energy(p, t, bodies)
    kinetic0 = 0.5 * p["sphere_mass"] * p["velocity"]**2
    assert np.max(np.abs(energy - energy[0])) < 5e-3 * kinetic0
    # the sphere really hits the net and is thrown back
    overlap = p["sphere_radius"] + 0.01 - np.linalg.norm(sphere["Position"] - bodies[(n // 2) * (n + 1)]["Position"],
                                                         axis=1)
    assert overlap.max() > 0 and sphere["Velocity"][:, 2].max() > 0
    # symmetry: the sphere stays above the centre, node (i, j) mirrors node (j, i)
    c = (n + 1) * a / 2
    assert np.max(np.abs(sphere["Position"][:, :2] - c)) < 1e-9
    nodes = q[:, :-3].reshape(len(t), n, n, 3)  # [step, j-1, i-1, xyz]
    mirrored = nodes.transpose(0, 2, 1, 3)[..., [1, 0, 2]]
    assert np.max(np.abs(nodes - mirrored)) < 1e-9


@pytest.mark.parametrize("seed", SEEDS)
def test_grid_mesh_free_flight_before_contact(seed):
    p, program = _program("grid_mesh_and_large_sphere_impact", seed)
    t, q, _ = simulate(program)
    z = q[:, -1]
    t_contact = 0.04 / p["velocity"]  # the 0.04 m gap closes before the net moves much
    free = t < 0.5 * t_contact
    expected = p["sphere_radius"] + 0.05 - p["velocity"] * t - 0.5 * 9.81 * t**2
    assert np.max(np.abs(z[free] - expected[free])) < 1e-10
    assert z.min() < p["sphere_radius"] - 0.01  # pushes the net down


# --------------------------------------------------------------------- 32 disc rolling on ground


@pytest.mark.parametrize("seed", SEEDS)
def test_disc_rolls_straight_without_slipping(seed):
    p, program = _program("disc_rolling_on_ground", seed)
    t, _, (disc,) = _bodies(program)
    r, v = p["radius"], p["velocity"]
    psi = math.radians(p["heading_deg"])
    axis = np.array([math.cos(psi), math.sin(psi), 0])
    direction = np.array([-math.sin(psi), math.cos(psi), 0])
    expected = np.array([p["x0"], p["y0"], r]) + np.outer(t, v * direction)
    assert np.max(np.abs(disc["Position"] - expected)) < 1e-6 * v * t[-1]
    assert np.max(np.abs(disc["Velocity"] - v * direction)) < 1e-6 * v
    # rolling without slipping: omega = -(v/r)*a, the contact point has zero velocity
    omega = disc["AngularVelocity"]
    assert np.max(np.abs(omega - (-v / r) * axis)) < 1e-6 * v / r
    contact = disc["Velocity"] + np.cross(omega, [0, 0, -r])
    assert np.max(np.abs(contact)) < 1e-6 * v
    # the disc stays upright: its axis stays horizontal along a
    assert np.max(np.abs(disc["RotationMatrix"][:, :, 0] - axis)) < 1e-6


# -------------------------------------------------- 46 non-steerable scooter, 47 four-wheeled car


def _refined(program: str, factor: int = 4) -> str:
    """More steps: the Euler-parameter integration of the fast wheel spin has a relative error of
    about (omega*h)^2; refine to test the model, not the integrator."""
    return retime(program, refine=factor)


def _vehicle_check(p: dict, bodies: list[dict], t: np.ndarray, body_mass: float, n_driven: int) -> None:
    r, v0, torque = p["wheel_radius"], p["velocity"], p["torque"]
    wheels = bodies[1:]
    m_wheel, j_wheel = _cylinder(p["wheel_density"], p["wheel_width"], r)
    m_eff = body_mass + len(wheels) * (m_wheel + j_wheel / r**2)
    acc = n_driven * torque / (r * m_eff)
    x = v0 * t + 0.5 * acc * t**2
    for body in bodies:
        assert np.max(np.abs(body["Position"][:, 0] - body["Position"][0, 0] - x)) < 2e-5 * x[-1]
        assert np.max(np.abs(body["Velocity"][:, 0] - (v0 + acc * t))) < 2e-5 * (v0 + acc * t[-1])
        assert np.max(np.abs(body["Position"][:, 2] - r)) < 1e-9
        assert np.max(np.abs(body["Velocity"][:, 1:])) < 1e-8
    # the chassis does not rotate; the wheels roll without slipping: omega = [0, v/r, 0]
    assert np.max(np.abs(bodies[0]["AngularVelocity"])) < 1e-8
    for wheel in wheels:
        omega = wheel["AngularVelocity"]
        assert np.max(np.abs(omega[:, 1] - wheel["Velocity"][:, 0] / r)) < 1e-5 * v0 / r
        assert np.max(np.abs(omega[:, [0, 2]])) < 1e-8


@pytest.mark.parametrize("seed", SEEDS)
def test_scooter_accelerates_and_rolls(seed):
    p, program = _program("non_steerable_scooter_with_ideal_rolling", seed)
    t, _, bodies = _bodies(_refined(program))
    assert len(bodies) == 3
    frame_mass = p["frame_density"] * p["wheelbase"] * p["frame_width"] * p["frame_height"]
    _vehicle_check(p, bodies, t, frame_mass, n_driven=1)


@pytest.mark.parametrize("seed", SEEDS)
def test_car_accelerates_and_rolls(seed):
    p, program = _program("non_steerable_four_wheeled_car", seed)
    t, _, bodies = _bodies(_refined(program))
    assert len(bodies) == 5
    chassis_mass = p["chassis_density"] * p["wheelbase"] * p["track"] * p["chassis_height"]
    _vehicle_check(p, bodies, t, chassis_mass, n_driven=2)
