"""Task 419 (level 4): the excitation amplitude that makes a hardening spring oscillator swing to a
given largest displacement.

The system is task 7's mass oscillator with a user-function force, with the spring made hardening
(a cubic term in its force law, a spring-damper user function): m x'' + d x' + k x + k3 x^3 =
F0 sin(omega t), from rest, with the excitation below resonance (omega = 0.6..0.9 of sqrt(k/m)).
The amplitude F0 of the user-function force is left open. The spec is an extreme: the largest
displacement from the start position during the run. The run is short against the damping's decay
time, so the free vibration started at t = 0 beats with the forced one, and the cubic term detunes
both: neither the steady-state harmonic balance nor the linear response from rest gives it.

Estimate: the linear response from rest (steady state plus the free vibration that starts it)
with the equivalent stiffness k + 3/4 k3 a^2 of harmonic balance at the target amplitude a; its
largest value over the run is proportional to F0, so F0 = a / (largest unit response).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.mass_oscillator_with_user_function import TASK as OSCILLATOR

END_TIME = 2.0


def largest_displacement(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(np.max(np.abs(q[:, 0] - values["length"])))  # the mass point: columns 0..2


def estimate(values: dict, target: float) -> dict[str, float]:
    m, d = values["mass"], values["damping"]
    k = values["stiffness"] + 0.75 * values["cubic_stiffness"] * target**2
    w = values["omega"]
    wn = np.sqrt(k / m)
    zeta = d / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta**2)
    t = np.linspace(0.0, END_TIME, 20001)
    # steady state x_p = A sin(w t) + B cos(w t) per unit force, then the free vibration from rest
    den = (k - m * w**2) ** 2 + (d * w) ** 2
    a, b = (k - m * w**2) / den, -d * w / den
    c1 = -b
    c2 = (-a * w + zeta * wn * c1) / wd
    x = a * np.sin(w * t) + b * np.cos(w * t) + np.exp(-zeta * wn * t) * (c1 * np.cos(wd * t) + c2 * np.sin(wd * t))
    return {"force_amplitude": target / float(np.max(np.abs(x)))}


MODEL_CODE = """
    def UFspring(mbs, t, itemNumber, deltaL, deltaL_t, stiffness, damping, force):
        return stiffness * deltaL + cubic_stiffness * deltaL**3 + damping * deltaL_t

    def UFforce(mbs, t, loadVector):
        return [force_amplitude * np.sin(omega * t), 0, 0]

    oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
    oMass = mbs.CreateMassPoint(referencePosition=[length, 0, 0], mass=mass)
    mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping,
                           springForceUserFunction=UFspring)
    mbs.CreateForce(itemNumber=oMass, loadVector=[force_amplitude, 0, 0], loadVectorUserFunction=UFforce)
"""

TASK = DesignModel(
    id=419,
    name="oscillator hardening force amplitude",
    system=OSCILLATOR,
    open_description=OSCILLATOR.open_description.replace(
        "with stiffness\n        k = {stiffness} N/m,",
        "with a hardening force law: its force (tension positive) is k*s + k3*s^3 + d*s', s being its stretch "
        "(length minus the unstretched length) and s' the rate of change of its length, with k = {stiffness} "
        "N/m, k3 = {cubic_stiffness} N/m^3,").replace(
        "damping coefficient d = {damping} N*s/m (force proportional to the rate\n        of change of its length)",
        "d = {damping} N*s/m").replace("F0 = {force_amplitude} N", "F0 (to be chosen)"),
    params=(
        Param("mass", 0.5, 2.0, "kg"),
        Param("stiffness", 500.0, 2000.0, "N/m"),
        Param("cubic_stiffness", 1.0e5, 4.0e5, "N/m^3"),
        Param("damping", 1.0, 4.0, "N*s/m"),
        Param("length", 0.5, 1.0, "m"),
        Param("frequency_ratio", 0.6, 0.9, ""),
    ),
    derive=lambda v: {"omega": float(np.round(v["frequency_ratio"] * np.sqrt(v["stiffness"] / v["mass"]), 2))},
    variables=(DesignVariable("force_amplitude", 5.0, 40.0, "N", "the amplitude F0 of the harmonic force"),),
    spec=Spec("the largest displacement of the mass from its start position during the run", "extreme", "m",
              largest_displacement),
    spec_text="""the largest distance of the mass from its start position [{length}, 0, 0] reached during the
        simulated 2 s is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the linear response from rest with the harmonic-balance stiffness k + 3/4 k3 a^2 at the "
                  "target amplitude a; F0 = a / its largest unit response",
    model_code=MODEL_CODE,
    sim=SimSettings(end_time=END_TIME, steps=2000),
)
