"""Task 402 (level 4): the restitution that makes the last ball of a Newton's cradle rise to a given height.

The system is task 43's Newton's cradle (four balls on rigid rods, soft penalty contacts with
Gonthier / Carvalho-Martins hysteresis damping, 2 mm gaps); the coefficient of restitution e of the
ball contacts is left open. The spec is an extreme: the largest height the last ball (3) reaches
above its start within 1.2 s, after ball 0 has swung down from the horizontal.

Why a closed form misses: with soft contacts and gaps the impacts overlap in time (balls 1 and 2
are still in contact when ball 3 is hit), the hysteresis damping is defined per contact, and the
balls swing on circles while they touch, so even e = 1 does not pass all of the energy on.

Estimate: rigid, successive impacts of equal masses, each passing on (1 + e)/2 of the speed:
the last ball's rise h = L ((1 + e)/2)^6, so e = 2 (h/L)^(1/6) - 1.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.newtons_cradle import TASK as CRADLE


def last_ball_rise(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    z = q[:, 11]  # ball 3 is the fourth mass point: columns 9..11, z last
    return float(np.max(z) - z[0])


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"restitution": 2.0 * (target / values["length"]) ** (1.0 / 6.0) - 1.0}


TASK = DesignModel(
    id=402,
    name="cradle restitution rise",
    system=CRADLE,
    open_description=CRADLE.open_description.replace("e = {restitution}", "e"),
    params=tuple(p for p in CRADLE.params if p.name != "restitution"),
    variables=(DesignVariable("restitution", 0.82, 0.98, "",
                              "the coefficient of restitution e of the contacts between neighbouring balls"),),
    spec=Spec("the largest height of ball 3 above its start position", "extreme", "m", last_ball_rise),
    spec_text="""within the simulated time, ball 3 (the last ball) rises to a largest height of {target} m
        above its start position (its centre's z-coordinate), within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid successive impacts of equal balls, each passing on (1 + e)/2 of the speed: "
                  "h = L ((1 + e)/2)^6",
    sim=SimSettings(end_time=1.2, steps=12000, extra=CRADLE.sim.extra),
)
