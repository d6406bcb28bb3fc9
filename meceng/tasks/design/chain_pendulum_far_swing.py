"""Task 425 (level 4): the release angle of a chain pendulum that swings its last mass out to a given point.

The system is task 13's n-pendulum (n point masses on massless rigid rods, pinned without
friction), here with 3-4 masses released straight at a large angle; the release angle phi0 is left
open. The spec is an extreme: how far the last mass swings out to the other side (its smallest
x-coordinate over the run, the chain released towards positive x).

Why a closed form misses: at large angles the chain does not swing as one piece; it bends, its
lower links whip ahead of the upper ones, and energy passes between the links in a way only the
n coupled nonlinear equations of motion give. A rigid straight chain would swing out to the mirror
of its start; the flexible chain's last mass comes out farther or shorter, depending on n and the
angle.

Estimate: the chain swings as one rigid straight bar; energy conservation then brings it to rest
at the mirror angle -phi0, so the last mass reaches x = -n L sin(phi0).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.n_pendulum import TASK as CHAIN


def far_swing(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    n = int(values["n_masses"])
    return float(np.min(q[:, 3 * (n - 1)]))  # the last mass point: columns 3(n-1)..3(n-1)+2


def estimate(values: dict, target: float) -> dict[str, float]:
    reach = int(values["n_masses"]) * values["length"]
    return {"angle_deg": float(np.degrees(np.arcsin(np.clip(-target / reach, -1.0, 1.0))))}


TASK = DesignModel(
    id=425,
    name="chain pendulum far swing",
    system=CHAIN,
    open_description=CHAIN.open_description.replace("turned {angle_deg}\n        degrees", "turned phi0").replace(
        "with phi0 =\n        {angle_deg} degrees", "with the release angle phi0"),
    params=(
        Param("n_masses", 3, 4, "", integer=True),
        Param("mass", 0.2, 2.0, "kg"),
        Param("length", 0.2, 0.35, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("angle_deg", 30.0, 60.0, "deg",
                              "the release angle phi0 of the straight chain from hanging straight down"),),
    spec=Spec("the smallest x-coordinate of the last point mass over the run", "extreme", "m", far_swing),
    spec_text="""released towards positive x, the chain swings over to the other side: the smallest
        x-coordinate the last point mass (i = n) reaches over the simulated time is {target} m, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the chain as one rigid straight bar: it swings out to the mirror angle, x = -n L sin(phi0)",
    sim=SimSettings(end_time=1.5, steps=3000),
)
