"""Task 403 (level 4): the rod length that puts a wall-impacting pendulum's third impact at a given time.

The system is task 42's pendulum (a solid ball on a rigid rod, released at a large angle, hitting a
vertical wall through which it would hang; a soft penalty contact with hysteresis damping); the rod
length L is left open. The spec is an event's time: the start of the third impact, when the bob's
centre reaches the wall's touching position x = 0 for the third time.

Why a closed form misses: each swing between impacts has its own amplitude (the rebound loses
speed), the large-angle period depends on that amplitude, and each soft contact lasts a finite time
that the rigid-impact picture leaves out; three of them add up.

Estimate: rigid impacts (the rebound speed e times the impact speed, so 1 - cos(phi_n+1) =
e^2 (1 - cos(phi_n))), and each quarter swing of amplitude phi lasting (pi/2) sqrt(L/g)
(1 + phi^2/16): t3 = (pi/2) sqrt(L/g) [f(phi0) + 2 f(phi1) + 2 f(phi2)], solved for L.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import crossings
from meceng.tasks.pendulum_wall_impacting import TASK as WALL_PENDULUM


def third_impact_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    ups = crossings(times, q[:, 0], 0.0)  # the bob is the only body: its centre's x in column 0
    return float(ups[2]) if ups.size >= 3 else float("nan")


def estimate(values: dict, target: float) -> dict[str, float]:
    phi, e = np.radians(values["angle_deg"]), values["restitution"]
    quarters = 0.0
    for weight in (1.0, 2.0, 2.0):
        quarters += weight * (1.0 + phi**2 / 16.0)
        phi = float(np.arccos(1.0 - e**2 * (1.0 - np.cos(phi))))
    return {"length": values["gravity"] * (2.0 * target / (np.pi * quarters)) ** 2}


TASK = DesignModel(
    id=403,
    name="wall pendulum third impact",
    system=WALL_PENDULUM,
    open_description=WALL_PENDULUM.open_description.replace("L = {length} m", "L"),
    params=(
        Param("mass", 0.3, 1.0, "kg"),
        Param("radius", 0.02, 0.05, "m"),
        Param("angle_deg", 40.0, 75.0, "deg", digits=2),
        Param("stiffness", 1e4, 3e4, "N/m", digits=2),
        Param("restitution", 0.5, 0.9, "", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("length", 0.3, 1.0, "m", "the rod length L (pivot to the bob's centre)"),),
    spec=Spec("the time at which the third impact on the wall starts", "event_time", "s", third_impact_time),
    spec_text="""the bob's third impact on the wall starts (its centre reaches x = 0, where the ball first
        touches the wall, for the third time) at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid impacts (1 - cos phi_n+1 = e^2 (1 - cos phi_n)) and quarter swings of "
                  "(pi/2) sqrt(L/g) (1 + phi^2/16): t3 = (pi/2) sqrt(L/g) [f(phi0) + 2 f(phi1) + 2 f(phi2)]",
    sim=SimSettings(end_time=3.0, steps=30000, extra=WALL_PENDULUM.sim.extra),
)
