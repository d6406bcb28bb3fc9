"""Task 433 (level 4): the restitution that lets the lower of two stacked balls rebound to a given height.

The system is task 41's two balls (solid spheres, the light one a small gap above the heavy one and
slightly offset, penalty contacts with Gonthier / Carvalho-Martins hysteresis damping at the floor
and between the balls), with a gap of 5-20 mm as in task 405; the coefficient of restitution e of
all contacts is left open. The spec is an extreme: the largest height the lower ball's centre
reaches after its first impact on the floor.

Why a closed form misses: with the small gap the upper ball lands on the lower one while it is
still pressed into the floor, so floor, lower and upper ball share one soft impact, and the lower
ball's rebound is what is left of its momentum after it has thrown the upper ball up: a small
difference of large impulses, each with its own hysteresis at its own speed; the offset turns a
part of the impact sideways.

Estimate: rigid successive head-on impacts: the lower ball rebounds from the floor with e times its
speed, meets the still falling upper ball after gap / ((1 + e) g t_f), a rigid impact with the same
e slows it down (a second floor impact if it is driven down again), and it rises freely:
z_max = z_meet + v0'^2 / (2 g), solved for e.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design.stacked_balls_drop_height import rigid_meeting, small_gap_params
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid
from meceng.tasks.design_measures import highest_after_first_rise
from meceng.tasks.sphere_sphere_and_sphere_ground_impact import TASK as STACKED


def lower_ball_rebound(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return highest_after_first_rise(q[:, 2])  # ball 0 is the first rigid body: position in columns 0..2


def rigid_rebound(values: dict, e: float) -> float:
    g, m0, m1, r0 = (values[k] for k in ("gravity", "mass0", "mass1", "radius0"))
    z0, u0, _, u1 = rigid_meeting(values, values["height"], e)
    v0 = (m0 * u0 + m1 * u1 - e * m1 * (u0 - u1)) / (m0 + m1)
    if v0 < 0.0:  # driven down again: back to the floor from z0 with |v0|, rebound with e
        v0 = e * np.sqrt(v0**2 + 2.0 * g * (z0 - r0))
        z0 = r0
    return float(z0 + v0**2 / (2.0 * g))


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"restitution": closest_on_grid(np.linspace(0.3, 1.0, 7001), lambda e: rigid_rebound(values, e), target)}


TASK = DesignModel(
    id=433,
    name="stacked balls lower rebound",
    system=STACKED,
    open_description=STACKED.open_description.replace("e = {restitution}", "e"),
    params=small_gap_params("restitution"),
    variables=(DesignVariable("restitution", 0.5, 0.95, "",
                              "the coefficient of restitution e of every contact (floor and ball-ball)"),),
    spec=Spec("the largest height of the lower ball's centre after its first impact on the floor", "extreme", "m",
              lower_ball_rebound),
    spec_text="""after its first impact on the floor, the lower ball 0 rises again; the largest height its
        centre reaches (z-coordinate, counted from its first upward motion to the end of the simulated
        time) is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid successive head-on impacts (floor, then ball on ball, restitution e), the meeting "
                  "point from the gap: z_max = z_meet + v0'^2/(2 g)",
    sim=SimSettings(end_time=1.5, steps=15000, extra=STACKED.sim.extra),
)
