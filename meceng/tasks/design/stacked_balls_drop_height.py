"""Task 405 (level 4): the drop height that sends the upper of two stacked balls to a given height.

The system is task 41's two balls (solid spheres, the light one a small gap above the heavy one
and slightly offset, penalty contacts with Gonthier / Carvalho-Martins hysteresis damping at the
floor and between the balls), here with a gap of only 5-20 mm; the drop height (the lower ball's
start height) is left open. The spec is an extreme: the largest height of the upper ball's centre after it is thrown up.

Why a closed form misses: with the small gap the upper ball arrives while the lower one is still
pressed into the floor, so the three bodies share one soft impact (the floor pushes through the
lower ball); no sequence of rigid two-body impacts describes it, and the offset turns part of the
motion sideways.

Estimate: rigid successive impacts, head-on: the lower ball rebounds from the floor with e times its
speed, meets the still falling upper ball after gap / ((1 + e) g t_f), and a rigid impact with
restitution e throws it up; z_max = z_meet + v1'^2 / (2 g), solved for the drop height.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec, closest_on_grid
from meceng.tasks.design_measures import highest_after_first_rise
from meceng.tasks.sphere_sphere_and_sphere_ground_impact import TASK as STACKED

#: The stacked balls' design tasks (405, 433) take task 41's balls with a gap of 5-20 mm (not 0.1-0.2 m), so that
#: the upper ball lands while the lower one is still pressed into the floor, and a smaller offset.
SMALL_GAP = {"gap": Param("gap", 0.005, 0.02, "m", digits=2), "offset": Param("offset", 0.002, 0.01, "m", digits=2)}


def small_gap_params(open_name: str) -> tuple[Param, ...]:
    """Task 41's parameters with the small gap, less the one the design leaves open."""
    return tuple(SMALL_GAP.get(p.name, p) for p in STACKED.params if p.name != open_name)


def upper_ball_height(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return highest_after_first_rise(q[:, 9])  # ball 1 is the second rigid body: position in columns 7..9


def rigid_meeting(values: dict, height: float, e: float) -> tuple[float, float, float, float]:
    """Rigid, head-on: where and how fast the balls meet after the lower one's floor rebound (with e),
    dropped from ``height``: (lower ball's z, its speed up, upper ball's z, its speed, negative down)."""
    g, gap, r0 = values["gravity"], values["gap"], values["radius0"]
    t_f = np.sqrt(2.0 * (height - r0) / g)
    dt = gap / ((1.0 + e) * g * t_f)
    u0, u1 = e * g * t_f - g * dt, -g * t_f - g * dt
    z0 = r0 + e * g * t_f * dt - 0.5 * g * dt**2
    z1 = height + r0 + values["radius1"] + gap - 0.5 * g * (t_f + dt) ** 2
    return z0, u0, z1, u1


def rigid_height(values: dict, height: float) -> float:
    g, e, m0, m1 = (values[k] for k in ("gravity", "restitution", "mass0", "mass1"))
    _, u0, z1, u1 = rigid_meeting(values, height, e)
    v1 = (m0 * u0 * (1.0 + e) + (m1 - e * m0) * u1) / (m0 + m1)
    return z1 + max(v1, 0.0) ** 2 / (2.0 * g)


def estimate(values: dict, target: float) -> dict[str, float]:
    return {"height": closest_on_grid(np.linspace(0.1, 2.0, 19001), lambda h: rigid_height(values, h), target)}


TASK = DesignModel(
    id=405,
    name="stacked balls drop height",
    system=STACKED,
    open_description=STACKED.open_description.replace("[0, 0, {height}] m", "[0, 0, H] m").replace("{height} + r0", "H + r0"),
    params=small_gap_params("height"),
    variables=(DesignVariable("height", 0.3, 0.8, "m", "the start height H of the lower ball's centre"),),
    spec=Spec("the largest height of the upper ball's centre after it is thrown up", "extreme", "m",
              upper_ball_height),
    spec_text="""after the impacts, the upper ball 1 is thrown up; the largest height its centre reaches
        (z-coordinate, counted from its first upward motion to the end of the simulated time) is
        {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="rigid successive head-on impacts (floor, then ball on ball, restitution e), the "
                  "meeting point from the gap: h = z_meet + v1'^2/(2 g)",
    sim=SimSettings(end_time=1.5, steps=15000, extra=STACKED.sim.extra),
)
