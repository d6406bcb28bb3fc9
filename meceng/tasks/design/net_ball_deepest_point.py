"""Task 423 (level 4): the spring stiffness of a pre-tensioned net that stops a falling ball at a given depth.

The system is task 45's net: an n x n grid of point masses on linear springs to each other and to
a fixed square frame, pre-tensioned (unstretched length below the spacing), and a large ball thrown
down onto its centre that touches the nodes through penalty contacts with hysteresis damping. The
springs' stiffness k is left open. The spec is an extreme: how deep the ball's lowest point sinks
below the plane of the frame.

Why a closed form misses: the ball is large against the spacing, so it presses on several nodes at
once and on more of them the deeper it goes; the net stiffens as it deflects (the springs stretch
with the sag, on top of the pretension); the nodes have mass and the contacts are soft and damped,
so part of the ball's energy goes into the net's own vibration and into the contacts' hysteresis.

Estimate: the net as a linear pre-tensioned cable grid (out-of-plane stiffness from the pretension
T = k * prestrain * a alone), loaded at the node(s) under the ball's centre, and energy: the ball's
kinetic energy and the work of its weight over its fall are stored in that stiffness at the lowest
point (rigid contact, massless nodes), solved for k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.grid_mesh_and_large_sphere_impact import TASK as NET

START_GAP = 0.05  # the ball's lowest point starts this high above the net (task 45)


def ball_height(q: np.ndarray, values: dict) -> np.ndarray:
    """The z-coordinate of the ball's centre per step: the ball is the point mass after the n x n nodes."""
    n = int(values["n"])
    return q[:, 3 * n * n + 2]


def ball_depth(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(values["sphere_radius"] - np.min(ball_height(q, values)))


def centre_compliance(n: int, spacing: float, tension: float) -> float:
    """Deflection per unit load of the node(s) under the net's centre: the linear out-of-plane
    stiffness of the cable grid under the tension ``tension`` (each spring T/a)."""
    index = {(i, j): (j - 1) * n + (i - 1) for j in range(1, n + 1) for i in range(1, n + 1)}
    stiffness = np.zeros((n * n, n * n))
    c = tension / spacing
    for (i, j), a in index.items():
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            stiffness[a, a] += c
            b = index.get((i + di, j + dj))
            if b is not None:
                stiffness[a, b] -= c
    middle = [(n + 1) // 2] if n % 2 else [n // 2, n // 2 + 1]
    load = np.zeros(n * n)
    for i in middle:
        for j in middle:
            load[index[(i, j)]] = 1.0 / len(middle) ** 2
    return float(load @ np.linalg.solve(stiffness, load))


def estimate(values: dict, target: float) -> dict[str, float]:
    mass, v0, g = values["sphere_mass"], values["velocity"], 9.81
    energy = 0.5 * mass * v0**2 + mass * g * (START_GAP + target)
    stiffness_needed = 2.0 * energy / target**2  # N/m at the centre
    per_unit_k = 1.0 / centre_compliance(int(values["n"]), values["spacing"], values["prestrain"] * values["spacing"])
    return {"spring_stiffness": float(stiffness_needed / per_unit_k)}


TASK = DesignModel(
    id=423,
    name="net ball deepest point",
    system=NET,
    open_description=NET.open_description.replace("stiffness k = {spring_stiffness} N/m", "stiffness k"),
    params=tuple(p for p in NET.params if p.name != "spring_stiffness"),
    variables=(DesignVariable("spring_stiffness", 800.0, 4000.0, "N/m",
                              "the stiffness k of every spring of the net"),),
    spec=Spec("the largest depth of the ball's lowest point below the plane of the frame", "extreme", "m",
              ball_depth),
    spec_text="""the ball sinks into the net: the largest depth of its lowest point below the plane z = 0 of
        the frame (the contact radius R minus the lowest z-coordinate of its centre over the run) is
        {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the net as a linear cable grid under its pretension, loaded at the centre; the ball's kinetic "
                  "energy and its weight's work stored in that stiffness at the lowest point",
    sim=SimSettings(end_time=0.4, steps=4000, extra=NET.sim.extra),
)
