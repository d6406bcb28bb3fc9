"""The measurements of the nets (423, 427, 431), the chain pendulums (425, 426), the cradle's second
ball (432) and the stacked balls' lower ball (433) read the right coordinates with the systems' own
conventions, checked against physics: a chain released at rest never swings out beyond its reach
and keeps its energy, the ball that sinks into the net has stored its energy in it, a linear net
lets the ball go half an oscillation after it touched, a cradle passes its energy on, and a ball
with nothing on it rebounds to e^2 of its drop."""

from __future__ import annotations

import numpy as np
import pytest

from meceng.tasks.design_base import DesignTask
from meceng.tasks.design_sim import simulate
from meceng.tasks.registry import default_registry


def _design(slug: str, seed: int = 0) -> DesignTask:
    return default_registry().get(slug).instance(seed).design


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


def test_a_linear_net_lets_the_ball_go_half_an_oscillation_after_it_touched() -> None:
    """In the linear limit (a strong pretension, light nodes, stiff contacts, a slow ball) the net is
    the cable grid's spring under its pretension, and the ball leaves it half an oscillation about
    its sagged equilibrium after the touch: the measure and that closed form agree to 1 %."""
    from meceng.tasks.design.net_ball_release_time import linear_release_time

    model = default_registry().get("net_ball_release_time")
    values = {**_design("net_ball_release_time").values, "node_mass": 0.001, "contact_stiffness": 5e5,
              "velocity": 0.3}
    times, q = simulate(model.program(values, {"prestrain": 0.3}, "linear limit"))
    measured = model.spec.measure(times, q, {**values, "prestrain": 0.3})
    assert measured == pytest.approx(linear_release_time(values, 0.3), rel=0.01)


def test_the_cradle_passes_its_energy_on_and_the_second_ball_keeps_less_the_more_elastic_it_is() -> None:
    model = default_registry().get("cradle_second_ball_rise")
    task = _design("cradle_second_ball_rise")
    length = task.values["length"]
    rises = {}
    for e in (0.9, 0.98):
        times, q = simulate(model.program(task.values, {"restitution": e}, "physics"))
        assert q[0, 5] == pytest.approx(0.0, abs=1e-9)  # ball 1 starts hanging straight down
        rises[e] = [float(np.max(q[:, 3 * i + 2]) - q[0, 3 * i + 2]) for i in (1, 3)]
        assert rises[e][0] == model.spec.measure(times, q, {**task.values, "restitution": e})
        assert sum(rises[e]) < length  # no ball gets more than ball 0 brought
    assert rises[0.98][1] > 0.85 * length and rises[0.98][1] > rises[0.9][1]  # the last ball takes most
    assert 0.0 < rises[0.98][0] < rises[0.9][0] < 0.05 * length  # the second ball keeps a little, less at higher e


def test_a_lower_ball_without_a_load_on_it_rebounds_to_e_squared_of_its_drop() -> None:
    """With a weightless upper ball the lower one bounces alone: its rebound height above the floor
    contact is e^2 of its drop (the contact's hysteresis damping is made for that restitution)."""
    model = default_registry().get("stacked_balls_lower_rebound")
    values = {**_design("stacked_balls_lower_rebound").values, "mass1": 1e-5}
    r0, drop = values["radius0"], values["height"] - values["radius0"]
    for e in (0.6, 0.9):
        times, q = simulate(model.program(values, {"restitution": e}, "one ball"))
        rebound = model.spec.measure(times, q, {**values, "restitution": e}) - r0
        assert rebound / drop == pytest.approx(e**2, rel=0.04)
