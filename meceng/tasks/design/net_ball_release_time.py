"""Task 431 (level 4): the net's pretension that lets a ball go again at a given time.

The system is task 45's net (an n x n grid of point masses on pre-tensioned springs to each other
and to a fixed square frame) and the large ball thrown down onto its centre, touching the nodes
through penalty contacts with hysteresis damping; the springs' prestrain (how much shorter their
unstretched length is than the spacing) is left open. The spec is an event's time: when the ball,
thrown back up, rises again through the height at which it first touched the net.

Why a closed form misses: the net is not a linear spring. Its resistance to the ball comes from the
pretension and from the stretch the sag itself makes, which grows with the square of the depth, so
the time in the net depends on how deep the ball goes; the ball presses on more nodes the deeper it
goes; the nodes have mass, start at rest and are still vibrating when the ball leaves; and the
contacts are soft and damped.

Estimate: the net as the linear cable grid under its pretension T = k * prestrain * a, loaded at
the node(s) under the ball (massless nodes, rigid contact): the ball arrives after its 0.05 m fall,
moves on that spring with its weight (half an oscillation about the sagged equilibrium, from the
first touch back to it) and leaves; t = t_fall + (pi + 2 atan(w s / v1)) / w, with s = M g / K_net,
solved for the prestrain.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design.net_ball_deepest_point import START_GAP, ball_height, centre_compliance
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid
from meceng.tasks.design_measures import first_crossing
from meceng.tasks.grid_mesh_and_large_sphere_impact import TASK as NET

G = 9.81
NODE_RADIUS = 0.01  # the nodes' contact radius (task 45)


def release_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    z = ball_height(q, values)
    touch = values["sphere_radius"] + NODE_RADIUS
    deepest = int(np.argmin(z))
    return first_crossing(times[deepest:], z[deepest:], touch) if deepest < len(z) - 1 else float("nan")


def linear_release_time(values: dict, prestrain: float) -> float:
    mass, v0, a = values["sphere_mass"], values["velocity"], values["spacing"]
    gap = START_GAP - NODE_RADIUS
    v1 = np.sqrt(v0**2 + 2.0 * G * gap)
    t_fall = (v1 - v0) / G
    stiffness = values["spring_stiffness"] / centre_compliance(int(values["n"]), a, prestrain * a)
    w = np.sqrt(stiffness / mass)
    sag = mass * G / stiffness
    return float(t_fall + (np.pi + 2.0 * np.arctan(w * sag / v1)) / w)


def estimate(values: dict, target: float) -> dict[str, float]:
    grid = np.linspace(0.005, 0.3, 29501)
    return {"prestrain": closest_on_grid(grid, lambda p: linear_release_time(values, p), target)}


TASK = DesignModel(
    id=431,
    name="net ball release time",
    system=NET,
    open_description=NET.open_description.replace("L0 = (1 - {prestrain})*a", "L0 = (1 - p)*a"),
    params=tuple(p for p in NET.params if p.name != "prestrain"),
    variables=(DesignVariable("prestrain", 0.02, 0.15, "",
                              "the prestrain p of the net's springs (their unstretched length is (1 - p)*a)"),),
    spec=Spec("the time at which the ball, thrown back up by the net, rises through the height of its first touch",
              "event_time", "s", release_time),
    spec_text="""the ball first touches the net's nodes when its centre comes down to the height
        z = R + 0.01 m, sinks in and is thrown back up; the time at which its centre rises back
        through z = R + 0.01 m (the first upward crossing after its lowest point) is {target} s,
        within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the net as a linear cable grid under its pretension (massless nodes, rigid contact): half an "
                  "oscillation of the ball on that spring, about its sagged equilibrium, after the fall",
    sim=SimSettings(end_time=0.4, steps=4000, extra=NET.sim.extra),
)
