"""Task 401 (level 4): the drive torque that turns a slider-crank's crank once in a given time.

The system is task 35's slider crank (rigid crank, rod and slider under gravity); the constant
torque on the crank is left open. The spec is an event's time: when the crank has turned one full
revolution from its start. The crank's inertia as seen from the drive changes with the angle (the
rod and slider speed up and stop twice a turn) and gravity works against it on the way up.

Estimate: the crank alone as a rigid bar about O plus the slider's mass at the crank pin, no
gravity: theta = T t^2 / (2 J), so T = 4 pi J / t^2.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z, first_crossing
from meceng.tasks.slider_crank_rigid_bodies import TASK as SLIDER_CRANK


def revolution_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    turned = angle_z(q, 3)  # the crank is the first body: Euler parameters in columns 3..6
    return first_crossing(times, turned - turned[0], 2 * np.pi)


def estimate(values: dict, target: float) -> dict[str, float]:
    r, w, rho = values["crank_length"], values["width"], values["density"]
    crank = rho * r * w * w
    slider = rho * values["slider_size"] ** 3
    inertia = crank * r**2 / 3 + slider * r**2
    return {"torque": 4 * np.pi * inertia / target**2}


TASK = DesignModel(
    id=401,
    name="crank first revolution",
    system=SLIDER_CRANK,
    open_description=SLIDER_CRANK.open_description.replace("{torque} N*m", "T"),
    params=(
        Param("density", 2000.0, 4000.0, "kg/m^3"),
        Param("crank_length", 0.1, 0.2, "m"),
        Param("rod_length", 0.35, 0.6, "m"),
        Param("width", 0.02, 0.03, "m"),
        Param("slider_size", 0.05, 0.08, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("torque", 1.0, 4.0, "N*m", "the constant drive torque T on the crank"),),
    spec=Spec("the time at which the crank has turned one full revolution from its start", "event_time", "s",
              revolution_time),
    spec_text="""the crank completes its first full revolution (turns 360 degrees from its start angle)
        at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the crank as a bar about O with the slider's mass at the crank pin, no gravity: "
                  "T = 4 pi J / t^2",
    sim=SimSettings(end_time=1.0, steps=8000),
)
