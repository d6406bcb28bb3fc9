"""Task 427 (level 4): the throw speed that makes a ball rebound from a pre-tensioned net to a given height.

The system is task 45's net (an n x n grid of point masses on pre-tensioned springs to each other
and to a fixed square frame) and the large ball thrown down onto its centre, touching the nodes
through penalty contacts with hysteresis damping; the ball's throw speed v0 is left open. The spec
is an extreme: the highest point the ball's bottom reaches above the net's plane after the net has
thrown it back up.

Why a closed form misses: the ball presses on several nodes at once and on more of them the deeper
it goes, each contact loses energy by its own hysteresis at its own speed, and the net does not
give back all it took: its nodes are still vibrating, out of phase with one another, when the ball
leaves, and the part of the energy they keep depends on how long the ball stays (a question of the
net's nonlinear, stiffening response).

Estimate: the net as a spring that returns the ball's speed times the contact's coefficient of
restitution e, the ball leaving at the net's plane: the rebound height above its start
(v0' e)^2 / (2 g), v0' its speed on arriving at the net after the 0.05 m fall, solved for v0.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design.net_ball_deepest_point import START_GAP, ball_height
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.grid_mesh_and_large_sphere_impact import TASK as NET

G = 9.81


def rebound_height(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    z = ball_height(q, values)
    after = int(np.argmin(z))
    return float(np.max(z[after:]) - values["sphere_radius"]) if after < len(z) - 1 else float("nan")


def estimate(values: dict, target: float) -> dict[str, float]:
    e = values["restitution"]
    # the ball leaves the net's plane (its centre at R) at e times its arrival speed there
    leave = np.sqrt(max(2.0 * G * target, 0.0))
    arrive = leave / e
    return {"velocity": float(np.sqrt(max(arrive**2 - 2.0 * G * START_GAP, 0.0)))}


TASK = DesignModel(
    id=427,
    name="net ball rebound height",
    system=NET,
    open_description=NET.open_description.replace("with the velocity [0, 0, -{velocity}] m/s",
                                                  "with the velocity [0, 0, -v0] m/s"),
    params=tuple(p for p in NET.params if p.name != "velocity"),
    variables=(DesignVariable("velocity", 1.0, 2.5, "m/s", "the ball's downward throw speed v0 at the start"),),
    spec=Spec("the highest height of the ball's lowest point above the net's plane after the rebound", "extreme", "m",
              rebound_height),
    spec_text="""the net throws the ball back up: after its lowest point, the highest the ball's lowest
        point rises above the plane z = 0 of the frame (the largest z-coordinate of its centre over
        the rest of the simulated time, minus the contact radius R) is {target} m, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the net returns the ball's speed times the contacts' restitution e, the ball leaving at the "
                  "net's plane; the rise from energy",
    sim=SimSettings(end_time=0.6, steps=6000, extra=NET.sim.extra),
)
