"""The measurements of the net (423), the three-joint arm (424) and the chain pendulum (425) read
the right coordinates with the system's own conventions, checked against physics: a stiffly
controlled arm follows its trajectory, a chain released at rest never swings out beyond its reach
and keeps its energy, and the ball that sinks into the net has stored its energy in the net."""

from __future__ import annotations

import numpy as np
import pytest

from meceng.tasks.design_base import DesignTask
from meceng.tasks.design_sim import simulate
from meceng.tasks.registry import default_registry


def _design(slug: str, seed: int = 0) -> DesignTask:
    return default_registry().get(slug).instance(seed).design


def test_a_stiffly_controlled_arm_follows_its_trajectory_and_soft_gains_lag() -> None:
    """Tip error through the links' Euler parameters and the trajectory's forward kinematics: with
    gains 100x the range's the arm tracks within a millimetre (a wrong axis or sign in either would
    show centimetres), and the error grows as the gains soften."""
    task = _design("rrr_pd_gains_tip_error")
    stiff = {"kp": 5e4, "kd": 2e3}
    times, q = simulate(task.program(stiff))
    assert task.measure(times, q, stiff) < 1e-3
    soft = task.measure(*simulate(task.program({"kp": 200.0, "kd": 10.0})), {"kp": 200.0, "kd": 10.0})
    firm = task.measure(*simulate(task.program({"kp": 700.0, "kd": 25.0})), {"kp": 700.0, "kd": 25.0})
    assert soft > firm > 1e-3


def test_the_chain_swings_out_within_its_reach_and_keeps_its_energy() -> None:
    task = _design("chain_pendulum_far_swing")
    v, design = task.values, task.gold
    n, length, g, m = int(v["n_masses"]), v["length"], v["gravity"], v["mass"]
    times, q = simulate(task.program(design))
    phi0 = np.radians(design["angle_deg"])
    assert q[0, 3 * (n - 1)] == pytest.approx(n * length * np.sin(phi0), rel=1e-3)  # the last mass's x
    far = task.measure(times, q, design)
    assert -n * length < far < 0.0
    # energy: kinetic + potential of the point masses, from positions (velocities by differences)
    y = q[:, 1::3][:, :n]
    dt = times[1] - times[0]
    speed2 = (np.diff(q[:, 0::3][:, :n], axis=0) ** 2 + np.diff(y, axis=0) ** 2) / dt**2
    energy = 0.5 * m * speed2.sum(axis=1) + m * g * 0.5 * (y[1:] + y[:-1]).sum(axis=1)
    start = m * g * y[0].sum()
    assert np.max(np.abs(energy - start)) < 0.02 * m * g * n * length


def test_the_ball_sinks_into_the_net_as_deep_as_its_energy_allows() -> None:
    task = _design("net_ball_deepest_point")
    v, design = task.values, task.gold
    n = int(v["n"])
    times, q = simulate(task.program(design))
    ball_z = q[:, 3 * n * n + 2]
    assert ball_z[0] == pytest.approx(v["sphere_radius"] + 0.05 - v["velocity"] * times[0], abs=1e-3)
    depth = task.measure(times, q, design)
    assert 0.0 < depth < v["sphere_radius"]
    # at the deepest point the ball is (nearly) at rest: its kinetic energy and its weight's work
    # went into the net's springs, the nodes' motion and the contacts (hysteresis takes some)
    lowest = int(np.argmin(ball_z))
    assert abs(ball_z[lowest + 1] - ball_z[lowest - 1]) / (2 * (times[1] - times[0])) < 0.05 * v["velocity"]
    assert task.measure(times, q, design) == pytest.approx(task.target, rel=1e-3)


def test_the_top_string_carries_more_than_the_chain_s_weight_and_starts_unstretched() -> None:
    task = _design("chain_springs_top_stretch")
    v, design = task.values, task.gold
    times, q = simulate(task.program(design))
    assert np.hypot(q[0, 0], q[0, 1]) - v["length"] == pytest.approx(0.0, abs=1e-4)  # mass 1, unstretched
    # swinging through the bottom, the top string holds the whole chain's weight and its centrifugal pull
    weight_stretch = int(v["n_masses"]) * v["mass"] * v["gravity"] / design["stiffness"]
    assert task.measure(times, q, design) > weight_stretch


def test_the_ball_rebounds_no_higher_than_its_energy_allows() -> None:
    task = _design("net_ball_rebound_height")
    design = task.gold
    times, q = simulate(task.program(design))
    rise = task.measure(times, q, design)
    # energy: v0^2/(2g) above the start, the start 0.05 m above the net; the contacts and the net keep some
    ceiling = 0.05 + design["velocity"] ** 2 / (2 * 9.81)
    assert 0.0 < rise < ceiling
    assert rise == pytest.approx(task.target, rel=1e-3)


def test_a_strongly_pretensioned_chain_reaches_its_lowest_point_half_a_linear_period_after_release() -> None:
    """In the linear limit (pretension 20 %, no damping) the chain's mean height is its first bead-string
    mode: released at the top of its swing, it is lowest half a period later; the measure reads it."""
    model = default_registry().get("chain_first_lowest_time")
    task = _design("chain_first_lowest_time")
    v = {**task.values, "length_ratio": 0.8, "damping": 0.0}
    k = 3000.0
    times, q = simulate(model.program(v, {"stiffness": k}, "linear limit"))
    n = int(v["n_masses"])
    h = v["span"] / (n + 1)
    w = 2 * np.sqrt(k * 0.2 * h / (v["mass"] * h)) * np.sin(np.pi / (2 * (n + 1)))
    assert model.spec.measure(times, q, {**v, "stiffness": k}) == pytest.approx(np.pi / w, rel=0.03)
