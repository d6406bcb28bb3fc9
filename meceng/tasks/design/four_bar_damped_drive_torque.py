"""Task 420 (level 4): the drive torque that turns a damped four-bar linkage's crank three times in a
given time.

The system is task 36's four-bar linkage (crank, coupler and rocker as steel bars under gravity),
with a constant drive torque T on the crank and a viscous rotary damper d in the crank's pivot A;
T is left open. The spec is an event's time: when the crank has turned three full revolutions
from its start. The torque is a few times the linkage's largest gravity torque, so the crank
speeds up and slows down every turn as the coupler and rocker are lifted and lowered and as the
inertia the crank sees changes with its angle; the damper makes the motion non-conservative, so
no energy quadrature gives the time.

Estimate: the crank as a bar about A with half the coupler's mass at the crank pin, no gravity,
J theta'' = T - d theta': theta(t) = (T/d) (t - tau (1 - exp(-t/tau))) with tau = J/d, set to
6 pi at the target time.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z, first_crossing
from meceng.tasks.four_bar_mechanism_rigid_bodies import TASK as FOUR_BAR


def third_revolution_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    turned = angle_z(q, 3)  # the crank is the first body: Euler parameters in columns 3..6
    return first_crossing(times, turned - turned[0], 6 * np.pi)


def estimate(values: dict, target: float) -> dict[str, float]:
    rho, w, a, d = values["density"], values["width"], values["crank_length"], values["damping"]
    inertia = rho * a * w * w * a**2 / 3 + 0.5 * rho * values["coupler_length"] * w * w * a**2
    tau = inertia / d
    return {"torque": 6 * np.pi * d / (target - tau * (1 - np.exp(-target / tau)))}


TASK = DesignModel(
    id=420,
    name="four bar damped drive torque",
    system=FOUR_BAR,
    open_description=FOUR_BAR.open_description.replace(
        "there is no drive,\n        no friction and no damping.",
        "a motor drives the crank with the constant torque T (to be chosen) about the positive z-axis "
        "(counter-clockwise), and a viscous rotary damper in the pivot A resists the crank's rotation "
        "with the torque -d*omega, omega being the crank's angular velocity, d = {damping} N*m*s/rad; "
        "there is no other friction."),
    params=(
        Param("density", 7500.0, 8000.0, "kg/m^3"),
        Param("ground_length", 0.4, 0.5, "m"),
        Param("crank_length", 0.08, 0.15, "m"),
        Param("coupler_length", 0.4, 0.5, "m"),
        Param("rocker_length", 0.3, 0.4, "m"),
        Param("width", 0.02, 0.025, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("damping", 0.3, 0.6, "N*m*s/rad"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("torque", 5.0, 15.0, "N*m", "the constant drive torque T on the crank"),),
    spec=Spec("the time at which the crank has turned three full revolutions from its start", "event_time", "s",
              third_revolution_time),
    spec_text="""the crank completes its third full revolution (has turned 3*360 degrees from its start
        angle) at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the crank as a bar about A with half the coupler's mass at the crank pin, no gravity, "
                  "J theta'' = T - d theta' integrated in closed form to 6 pi at the target time",
    model_code=FOUR_BAR.model_code + """
        mbs.CreateTorque(itemNumber=oCrank, loadVector=[0, 0, torque])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oCrank], position=pA, axis=[0, 0, 1],
                                        stiffness=0, damping=damping)
    """,
    sim=SimSettings(end_time=3.0, steps=3000),
)
