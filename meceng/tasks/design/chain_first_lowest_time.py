"""Task 428 (level 4): the spring stiffness that brings an elastic chain to its first lowest point at a given time.

The system is task 33's elastic chain (n point masses on n + 1 spring-dampers between two fixed
points, released from the straight line under gravity) with a weak pretension, as in task 409; the
springs' stiffness k is left open. The spec is an event's time: when the middle of the chain
(its lowest point on average) first reaches the bottom of its fall.

Why a closed form misses: with the weak pretension the chain's stiffness against sagging comes
mostly from the stretch the sag itself makes (a geometric hardening), so the fall is a nonlinear
oscillation whose quarter period depends on how deep it goes; the masses near the supports are
held back and those in the middle fall almost freely at first, so the chain changes its shape as
it falls, and the dampers slow it.

Estimate: the chain's fall as one linear mode, the parabolic shape on the springs' small-sag
stiffness under the pretension (T0 = k (h - l0)), released from rest at the top of its swing about
the sagged equilibrium: its lowest point half a small-oscillation period after the release,
t = pi / w with w = 2 sqrt(T0 / (m h)) sin(pi / (2 (n + 1))), solved for k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.design.chain_largest_sag import TASK as SAG
from meceng.tasks.design_base import DesignModel, Spec
from meceng.tasks.design_measures import local_maxima


def mean_height(q: np.ndarray, n: int) -> np.ndarray:
    return q[:, [3 * i + 1 for i in range(n)]].mean(axis=1)  # mass point i: columns 3i..3i+2


def first_lowest_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    depth = -mean_height(q, int(values["n_masses"]))
    peaks = local_maxima(depth)
    if peaks.size == 0:
        return float("nan")
    i = int(peaks[0])  # refine between the neighbouring steps by a parabola through three samples
    y0, y1, y2 = depth[i - 1], depth[i], depth[i + 1]
    shift = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2)
    return float(times[i] + shift * (times[i + 1] - times[i]))


def estimate(values: dict, target: float) -> dict[str, float]:
    n = int(values["n_masses"])
    h = values["span"] / (n + 1)
    stretch = h - values["length_ratio"] * h
    # first mode of a string of n beads: w = 2 sqrt(T0 / (m h)) sin(pi / (2 (n + 1))); t = pi / w
    w = np.pi / target
    tension = values["mass"] * h * (w / (2.0 * np.sin(np.pi / (2 * (n + 1))))) ** 2
    return {"stiffness": float(tension / stretch)}


TASK = DesignModel(
    id=428,
    name="chain first lowest time",
    system=SAG.system,
    open_description=SAG.open_description,
    params=SAG.params,
    variables=SAG.variables,
    spec=Spec("the time of the first lowest point of the chain's mean height", "event_time", "s", first_lowest_time),
    spec_text="""released, the chain falls and swings back up: the mean height of the n point masses (the
        average of their y-coordinates) first reaches its lowest point (its first local minimum over time)
        at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="one linear mode of a string of beads under the pretension T0 = k (h - l0), released at the top "
                  "of its swing: the lowest point half a period later",
)
