"""Task 420 (level 4): the drive torque that turns a damped, spring-loaded four-bar linkage's crank five
times in a given time.

The system is task 36's four-bar linkage (crank, coupler and rocker as steel bars under gravity),
with a constant drive torque T on the crank, a viscous rotary damper d in the crank's pivot A and,
in the rocker's pivot D, a torsional spring-damper (stiffness k_r, relaxed at the start, damping
d_r); T is left open. The spec is an event's time: when the crank has turned five full revolutions
from its start.

Why a hand calculation misses: without the rocker's spring-damper and over three turns, a careful
kinetic-energy stepping of the one-degree-of-freedom equation (J(theta), V(theta) on 24 angles)
reached 0.73 of the tolerance. Now the rocker's spring works against the crank through the
linkage's transmission ratio (its peak torque seen at the crank is of the order of the drive
torque), so the crank's speed rises and falls by a large part each turn, and the rocker's damper
takes energy at a rate that varies with the square of that ratio; the motion is non-conservative
and strongly non-uniform, and over five turns the error of a coarse J(theta), V(theta), dissipation
table and a few hundred steps adds up beyond 1 %.

Estimate: the crank as a bar about A with half the coupler's mass at the crank pin, no gravity, the
spring left out (it gives back over a turn what it takes), the rocker's damper as its mean over a
turn seen at the crank, d_r (a/c)^2 / 2 (the rocker swinging harmonically by +-a/c):
J theta'' = T - d_e theta', d_e = d + d_r (a/c)^2 / 2, theta(t) = (T/d_e) (t - tau (1 - exp(-t/tau)))
with tau = J/d_e, set to 10 pi at the target time.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z, first_crossing
from meceng.tasks.four_bar_mechanism_rigid_bodies import TASK as FOUR_BAR


def fifth_revolution_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    turned = angle_z(q, 3)  # the crank is the first body: Euler parameters in columns 3..6
    return first_crossing(times, turned - turned[0], 10 * np.pi)


def estimate(values: dict, target: float) -> dict[str, float]:
    rho, w, a = values["density"], values["width"], values["crank_length"]
    d = values["damping"] + 0.5 * values["rocker_damping"] * (a / values["rocker_length"]) ** 2
    inertia = rho * a * w * w * a**2 / 3 + 0.5 * rho * values["coupler_length"] * w * w * a**2
    tau = inertia / d
    return {"torque": 10 * np.pi * d / (target - tau * (1 - np.exp(-target / tau)))}


TASK = DesignModel(
    id=420,
    name="four bar damped drive torque",
    system=FOUR_BAR,
    open_description=FOUR_BAR.open_description.replace(
        "there is no drive,\n        no friction and no damping.",
        "a motor drives the crank with the constant torque T (to be chosen) about the positive z-axis "
        "(counter-clockwise), and a viscous rotary damper in the pivot A resists the crank's rotation "
        "with the torque -d*omega, omega being the crank's angular velocity, d = {damping} N*m*s/rad; "
        "in the pivot D a torsional spring-damper acts on the rocker: a torsional spring of stiffness "
        "k_r = {rocker_stiffness} N*m/rad, relaxed at the start (its torque on the rocker is "
        "-k_r*(gamma - gamma0), gamma being the rocker's angle and gamma0 its angle at the start), and "
        "in parallel a viscous rotary damper with the torque -d_r*omega_r on the rocker, omega_r its "
        "angular velocity, d_r = {rocker_damping} N*m*s/rad; there is no other friction."),
    params=(
        Param("density", 7500.0, 8000.0, "kg/m^3"),
        Param("ground_length", 0.4, 0.5, "m"),
        Param("crank_length", 0.08, 0.15, "m"),
        Param("coupler_length", 0.4, 0.5, "m"),
        Param("rocker_length", 0.3, 0.4, "m"),
        Param("width", 0.02, 0.025, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("damping", 0.3, 0.6, "N*m*s/rad"),
        Param("rocker_stiffness", 5.0, 12.0, "N*m/rad"),
        Param("rocker_damping", 0.5, 2.0, "N*m*s/rad"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("torque", 6.0, 15.0, "N*m", "the constant drive torque T on the crank"),),
    spec=Spec("the time at which the crank has turned five full revolutions from its start", "event_time", "s",
              fifth_revolution_time),
    spec_text="""the crank completes its fifth full revolution (has turned 5*360 degrees from its start
        angle) at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the crank as a bar about A with half the coupler's mass at the crank pin, no gravity, "
                  "no spring, the rocker damper as its mean d_r (a/c)^2/2 at the crank: J theta'' = T - d_e theta' "
                  "integrated in closed form to 10 pi at the target time",
    model_code=FOUR_BAR.model_code + """
        mbs.CreateTorque(itemNumber=oCrank, loadVector=[0, 0, torque])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oCrank], position=pA, axis=[0, 0, 1],
                                        stiffness=0, damping=damping)
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oRocker], position=pD, axis=[0, 0, 1],
                                        stiffness=rocker_stiffness, damping=rocker_damping)
    """,
    sim=SimSettings(end_time=6.0, steps=6000),
)
