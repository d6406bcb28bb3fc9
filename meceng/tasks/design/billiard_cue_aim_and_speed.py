"""Task 408 (level 4): the cue ball's sideways offset and speed that make it end at a given distance
off its line (two values open: a curve of answers).

The system is task 44's billiard break (four equal balls as point masses on a frictionless table,
penalty contacts with Gonthier / Carvalho-Martins hysteresis damping between every pair); the cue
ball's sideways start offset y0 and its speed v are left open. The spec is a position: the cue
ball's y-coordinate at the end of the simulated time. Every (y0, v) on a curve meets it.

Why a closed form misses: as in task 406, the apex ball bounces back off the rack and hits the cue
ball a second time, so the final direction is not the first oblique impact's; a faster cue ball
also presses deeper into the soft contacts, so the motion does not simply scale with v.

Estimate: the speed in the middle of its range (3 m/s), and the offset from one rigid oblique
impact on the apex ball followed by free sliding (task 406's formula:
y(T) = v sin(a) cos(a) (1 + e)/2 (T - (d - 2 r cos(a))/v), sin(a) = y0/(2 r)).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.billiard_with_4_spheres import TASK as BILLIARD
from meceng.tasks.design.billiard_cue_offset import cue_ball_final_y, rigid_final_y
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid


def estimate(values: dict, target: float) -> dict[str, float]:
    chosen = {**values, "velocity": 3.0}
    offset = closest_on_grid(np.linspace(0.0, 0.05, 50001), lambda o: rigid_final_y(chosen, o), target)
    return {"offset": offset, "velocity": 3.0}


TASK = DesignModel(
    id=408,
    name="billiard cue aim and speed",
    system=BILLIARD,
    open_description=BILLIARD.open_description.replace("[0, {offset}, 0] m", "[0, y0, 0] m")
    .replace("[{velocity}, 0, 0] m/s", "[v, 0, 0] m/s"),
    params=tuple(p for p in BILLIARD.params if p.name not in ("offset", "velocity")),
    variables=(
        DesignVariable("offset", 0.004, 0.02, "m", "the cue ball's sideways start offset y0 (its start position "
                                                  "is [0, y0, 0])"),
        DesignVariable("velocity", 2.0, 4.0, "m/s", "the cue ball's start speed v (its velocity is [v, 0, 0])"),
    ),
    spec=Spec("the cue ball's y-coordinate at the end of the simulated time", "position", "m", cue_ball_final_y),
    spec_text="""at the end of the simulated time, the centre of the cue ball 0 is at y = {target} m,
        within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="v = 3 m/s (mid-range) and one rigid oblique impact on the apex ball, then free sliding: "
                  "y(T) = v sin(a) cos(a) (1 + e)/2 (T - t_hit), sin(a) = y0/(2 r)",
)
