"""Task 406 (level 4): the cue ball's sideways offset that makes it end at a given distance off its line.

The system is task 44's billiard break (four equal balls as point masses on a frictionless table,
penalty contacts with Gonthier / Carvalho-Martins hysteresis damping between every pair); the cue
ball's sideways offset from the apex ball's line is left open. The spec is a position: the cue
ball's y-coordinate at the end of the simulated time.

Why a closed form misses: the apex ball, pushed into the rack, bounces back off balls 2 and 3 and
hits the cue ball a second time (and the cue ball can graze a rack ball), so the cue ball's final
direction is not the one the first oblique impact gives it; the soft contacts overlap in time.

Estimate: one rigid oblique impact of the cue ball on the apex ball, then free sliding: with
sin(alpha) = offset/(2 r), the cue ball keeps its tangential speed and (1 - e)/2 of its normal
speed, so v_y = v sin(alpha) cos(alpha) (1 + e)/2, and y(T) = v_y (T - (d - 2 r cos(alpha))/v),
solved for the offset.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.billiard_with_4_spheres import TASK as BILLIARD
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid


def cue_ball_final_y(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(q[-1, 1])  # the cue ball is the first mass point: y in column 1


def rigid_final_y(values: dict, offset: float) -> float:
    v, r, e = values["velocity"], values["radius"], values["restitution"]
    sin_a = offset / (2.0 * r)
    cos_a = np.sqrt(1.0 - sin_a**2)
    t_hit = (values["distance"] - 2.0 * r * cos_a) / v
    return v * sin_a * cos_a * (1.0 + e) / 2.0 * (BILLIARD.sim.end_time - t_hit)


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"offset": closest_on_grid(np.linspace(0.0, 0.05, 50001), lambda o: rigid_final_y(values, o), target)}


TASK = DesignModel(
    id=406,
    name="billiard cue offset",
    system=BILLIARD,
    open_description=BILLIARD.open_description.replace("[0, {offset}, 0] m", "[0, y0, 0] m"),
    params=tuple(p for p in BILLIARD.params if p.name != "offset"),
    variables=(DesignVariable("offset", 0.004, 0.02, "m",
                              "the cue ball's sideways start offset y0 (its start position is [0, y0, 0])"),),
    spec=Spec("the cue ball's y-coordinate at the end of the simulated time", "position", "m", cue_ball_final_y),
    spec_text="""at the end of the simulated time, the centre of the cue ball 0 is at y = {target} m,
        within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="one rigid oblique impact on the apex ball, then free sliding: "
                  "y(T) = v sin(a) cos(a) (1 + e)/2 (T - t_hit), sin(a) = offset/(2 r)",
)
