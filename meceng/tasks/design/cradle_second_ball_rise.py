"""Task 432 (level 4): the restitution that lets the second ball of a Newton's cradle rise to a given height.

The system is task 43's Newton's cradle (four balls on rigid rods, soft penalty contacts with
Gonthier / Carvalho-Martins hysteresis damping, 2 mm gaps), as in task 402; the coefficient of
restitution e of the ball contacts is left open. The spec is an extreme: the largest height ball 1
(the second ball, which an ideal cradle would leave at rest) reaches above its start within 0.8 s:
its first swing (rods of 0.2-0.45 m, so the last ball is not back before the end).

Why a closed form misses: ball 1 moves only by what the impacts fail to pass on, a small difference
of large momenta; with soft contacts and gaps the impacts overlap in time (ball 1 is still pressed
by ball 0 while it pushes ball 2), ball 0 follows and strikes again, and the balls swing on circles
between and during the impacts, so its rise depends on the whole train of contacts, not on e alone.

Estimate: rigid, successive impacts of equal balls in a row, repeated until no pair approaches
(each impact keeps (1 - e)/2 and passes on (1 + e)/2 of the relative speed), the balls moving
freely between impacts; ball 1 then swings up with the speed it keeps: h1 = v1^2 / (2 g), solved
for e.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid
from meceng.tasks.newtons_cradle import TASK as CRADLE

#: rods short enough for the first swing to end before the last ball is back; stiff enough contacts
#: that the rise falls steadily with e (at 1.2e4 N/m and 0.9 < e it levels off and turns back up)
OWN = {"length": Param("length", 0.2, 0.45, "m"), "stiffness": Param("stiffness", 2e4, 5e4, "N/m", digits=2)}


def second_ball_rise(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    z = q[:, 5]  # ball 1 is the second mass point: columns 3..5, z last
    return float(np.max(z) - z[0])


def rigid_speeds(e: float, speed: float, balls: int = 4) -> np.ndarray:
    """The balls' speeds after rigid pairwise impacts, ball 0 arriving with ``speed``, repeated
    until no neighbour pair approaches (equal masses)."""
    v = np.zeros(balls)
    v[0] = speed
    for _ in range(10000):
        approaching = [i for i in range(balls - 1) if v[i] > v[i + 1] + 1e-12]
        if not approaching:
            break
        i = approaching[0]
        relative = v[i] - v[i + 1]
        v[i] -= (1.0 + e) / 2.0 * relative
        v[i + 1] += (1.0 + e) / 2.0 * relative
    return v


def rigid_rise(values: dict, e: float) -> float:
    speed = np.sqrt(2.0 * values["gravity"] * values["length"])
    return float(rigid_speeds(e, speed)[1] ** 2 / (2.0 * values["gravity"]))


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"restitution": closest_on_grid(np.linspace(0.5, 1.0, 5001), lambda e: rigid_rise(values, e), target)}


TASK = DesignModel(
    id=432,
    name="cradle second ball rise",
    system=CRADLE,
    open_description=CRADLE.open_description.replace("e = {restitution}", "e"),
    params=tuple(OWN.get(p.name, p) for p in CRADLE.params if p.name != "restitution"),
    variables=(DesignVariable("restitution", 0.82, 0.98, "",
                              "the coefficient of restitution e of the contacts between neighbouring balls"),),
    spec=Spec("the largest height of ball 1 above its start position", "extreme", "m", second_ball_rise),
    spec_text="""within the simulated time, ball 1 (the second ball, next to the one released) rises to a
        largest height of {target} m above its start position (its centre's z-coordinate), within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid successive impacts of equal balls repeated until no pair approaches, each passing on "
                  "(1 + e)/2 of the relative speed; ball 1's kept speed swung up: h1 = v1^2/(2 g)",
    sim=SimSettings(end_time=0.8, steps=8000, extra=CRADLE.sim.extra),
)
