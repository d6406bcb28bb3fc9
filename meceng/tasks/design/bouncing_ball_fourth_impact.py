"""Task 404 (level 4): the restitution that makes a bouncing ball's fourth impact start at a given time.

The system is task 40's ball (a mass point thrown horizontally onto the ground, a penalty contact
with Gonthier / Carvalho-Martins hysteresis damping); the coefficient of restitution e is left open.
The spec is an event's time: the start of the fourth ground impact (the ball's surface reaching the
ground for the fourth time).

Why a closed form misses: every soft contact lasts a finite time, longer for a heavy ball on a soft
ground, and gravity acts during it; the rigid bounce sequence leaves out three contact phases, a few
per cent of the time to the fourth impact.

Estimate: rigid bounces. The first impact after t0 = sqrt(2 (h - r)/g) at the speed v0 = g t0, each
flight after it 2 v0 e^n / g: t4 = t0 + (2 v0/g)(e + e^2 + e^3), solved for e.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import crossings
from meceng.tasks.falling_mass_point_with_ground_contact import TASK as FALLING_BALL


def fourth_impact_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    centre = q[:, 0:3] - np.array([0.0, 0.0, -1000.0])  # the ball's centre from the ground sphere's
    gap = np.linalg.norm(centre, axis=1) - 1000.0 - values["radius"]
    downs = crossings(times, -gap, 0.0)  # the gap closing: a contact starts
    return float(downs[3]) if downs.size >= 4 else float("nan")


def estimate(values: dict, target: float) -> dict[str, float]:
    g = values["gravity"]
    t0 = np.sqrt(2.0 * (values["height"] - values["radius"]) / g)
    flights = (target - t0) * g / (2.0 * g * t0)  # e + e^2 + e^3
    roots = np.roots([1.0, 1.0, 1.0, -flights])
    real = [r.real for r in roots if abs(r.imag) < 1e-9 and r.real > 0]
    return {"restitution": float(real[0]) if real else 0.0}


TASK = DesignModel(
    id=404,
    name="bouncing ball fourth impact",
    system=FALLING_BALL,
    open_description=FALLING_BALL.open_description.replace("e = {restitution}", "e"),
    params=(
        Param("mass", 0.3, 1.0, "kg"),
        Param("radius", 0.02, 0.1, "m"),
        Param("height", 0.3, 1.0, "m"),
        Param("velocity", 0.1, 0.5, "m/s"),
        Param("stiffness", 1e4, 3e4, "N/m", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("restitution", 0.5, 0.9, "", "the coefficient of restitution e of the ground contact"),),
    spec=Spec("the time at which the fourth ground impact starts", "event_time", "s", fourth_impact_time),
    spec_text="""the ball's fourth impact on the ground starts (its surface reaches the ground for the
        fourth time: the distance of the ball's centre from the ground sphere's centre falls to
        1000 m + r) at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid bounces: t4 = t0 + (2 v0/g)(e + e^2 + e^3), t0 = sqrt(2 (h - r)/g), v0 = g t0",
    sim=SimSettings(end_time=3.0, steps=30000, extra=FALLING_BALL.sim.extra),
)
