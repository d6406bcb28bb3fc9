"""Task 401 (level 4): the drive torque that turns a spring-loaded, damped slider-crank's crank three
times in a given time.

The system is task 35's slider crank (rigid crank, rod and slider under gravity) with a load on the
slider: a linear spring-damper along the x-axis between the slider's centre and a fixed point to its
right, relaxed at the start. The constant torque on the crank is left open. The spec is an event's
time: when the crank has turned three full revolutions from its start (the name keeps "first
revolution" from the first version of this model, which asked for one turn of the unloaded crank).

Why a hand calculation misses: the unloaded crank is conservative with one degree of freedom, so an
energy quadrature over J(theta) gave its first revolution to 0.03 %. Now the slider's damper takes
energy at the rate c v^2, with v the slider's speed (r omega times a factor of the angle that
changes twice a turn), and the spring pushes the slider back with a force that grows with its
travel: the crank's speed is the solution of a nonlinear, non-conservative ODE over three turns,
rising and falling each half turn by a large part (the spring's peak torque on the crank and the
damper's are of the order of the drive torque), so neither energy nor a few coarse steps give its
time to 1 %.

Estimate: the crank as a bar about O plus the slider's mass at the crank pin, no gravity, the
spring left out (it gives back over a turn what it takes), the slider damper as its mean over a
turn, c r^2 / 2, on the crank: J theta'' = T - d theta', theta(t) = (T/d) (t - tau (1 - exp(-t/tau)))
with tau = J/d, set to 6 pi at the target time.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings, round_significant
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z, first_crossing
from meceng.tasks.slider_crank_rigid_bodies import TASK as SLIDER_CRANK


def third_revolution_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    turned = angle_z(q, 3)  # the crank is the first body: Euler parameters in columns 3..6
    return first_crossing(times, turned - turned[0], 6 * np.pi)


def estimate(values: dict, target: float) -> dict[str, float]:
    r, w, rho = values["crank_length"], values["width"], values["density"]
    crank = rho * r * w * w
    slider = rho * values["slider_size"] ** 3
    inertia = crank * r**2 / 3 + slider * r**2
    d = 0.5 * values["slider_damping"] * r**2
    tau = inertia / d
    return {"torque": float(6 * np.pi * d / (target - tau * (1 - np.exp(-target / tau))))}


TASK = DesignModel(
    id=401,
    name="crank first revolution",
    system=SLIDER_CRANK,
    open_description=SLIDER_CRANK.open_description.replace("{torque} N*m", "T").replace(
        "There is no friction and no damping.",
        "A linear spring-damper along the x-axis connects the slider's centre C to the fixed point "
        "E = [xC0 + {spring_length}, 0, 0], xC0 being the slider centre's x-coordinate at the start: "
        "the spring has stiffness k = {slider_stiffness} N/m and is relaxed at the start (its "
        "unstretched length is {spring_length} m), the damper in parallel has the viscous damping "
        "coefficient c = {slider_damping} N*s/m (force -c times the slider's velocity). E lies farther "
        "right than the slider ever gets, so spring and damper act along x. There is no other friction or "
        "damping."),
    params=(
        Param("density", 2000.0, 4000.0, "kg/m^3"),
        Param("crank_length", 0.1, 0.2, "m"),
        Param("rod_length", 0.35, 0.6, "m"),
        Param("width", 0.02, 0.03, "m"),
        Param("slider_size", 0.05, 0.08, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("load_ratio", 0.5, 0.8, ""),  # the spring's peak torque 2 k r^2 over the lowest torque
        Param("slider_damping", 3.0, 6.0, "N*s/m"),
        # longer than the slider's whole stroke 2 r: the slider never reaches E, so the spring acts along x
        Param("spring_length", 0.45, 0.6, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    model_code=SLIDER_CRANK.model_code + """
        mbs.CreateSpringDamper(itemNumbers=[oGround, oSlider], localPosition0=[xC + spring_length, 0, 0],
                               localPosition1=[0, 0, 0], referenceLength=spring_length,
                               stiffness=slider_stiffness, damping=slider_damping)
    """,
    variables=(DesignVariable("torque", 1.5, 4.0, "N*m", "the constant drive torque T on the crank"),),
    spec=Spec("the time at which the crank has turned three full revolutions from its start", "event_time", "s",
              third_revolution_time),
    spec_text="""the crank completes its third full revolution (has turned 3*360 degrees from its start
        angle) at t = {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the crank as a bar about O with the slider's mass at the crank pin, no gravity, no spring, "
                  "the slider damper as its mean c r^2/2 on the crank: J theta'' = T - d theta' integrated in "
                  "closed form to 6 pi at the target time",
    derive=lambda v: {"slider_stiffness": round_significant(v["load_ratio"] * 1.5 / (2 * v["crank_length"] ** 2), 3)},
    sim=SimSettings(end_time=2.5, steps=10000),
)
