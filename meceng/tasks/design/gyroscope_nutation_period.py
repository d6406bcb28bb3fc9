"""Task 414 (level 4): the spin rate that gives a heavy gyroscope with a viscous ball joint a required
nutation period.

The system is task 48's gyroscope (a disc on a massless axle, its end on a ball joint at a fixed
point, released with pure spin and the axle raised above the horizontal) whose ball joint has
viscous friction: it exerts on the disc the torque -c omega (omega the disc's angular velocity).
The spin rate is left open, in a range where the gyroscope is not fast (the precession rate is a
good part of the nutation rate). The spec is a period: the mean nutation period over the first six
nutations, the time of the disc centre's sixth height maximum after the start divided by six
(the start is a maximum: the axle starts without precession at the top of its nutation).

Why a hand calculation misses: without friction the heavy symmetric top is integrable, and the
exact nutation period from the roots of its cubic and an elliptic integral gave the answer. The
friction in the joint breaks the conservation of energy, of the vertical angular momentum and of
the spin at once: the spin decays (by a fifth to two fifths over the six nutations), the
precession is braked so the axle sinks, and the nutation amplitude is damped, so each nutation has
its own period that depends on the state the friction left; no integral of the motion is left to
reduce it to a quadrature, and the slow drift has to be followed over six cycles.

Estimate: the fast-top nutation frequency omega_nut = I_a omega_s / I_t (I_a the disc's moment of
inertia about its axis, I_t about a transverse axis through the pivot) with the spin decaying as
omega_s(t) = omega_0 exp(-t/tau), tau = I_a/c: the mean period over the window [0, 6 T] is
(2 pi I_t / (I_a omega_0)) tau (exp(6 T/tau) - 1) / (6 T), solved for omega_0.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings, round_significant
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import local_maxima
from meceng.tasks.gyroscope_nutation import TASK as GYROSCOPE

NUTATIONS = 6


def nutation_period(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    z = q[:, 2]  # the disc's centre: columns 0..2, height in 2
    peaks = local_maxima(z)
    if peaks.size < NUTATIONS:
        return float("nan")
    i = peaks[NUTATIONS - 1]
    a, b, c = z[i - 1], z[i], z[i + 1]  # the maximum's time refined by a parabola through 3 rows
    shift = 0.5 * (a - c) / (a - 2 * b + c)
    return float((times[i] + shift * (times[i + 1] - times[i])) / NUTATIONS)


def _inertias(values: dict) -> tuple[float, float]:
    radius, t, length = values["disc_radius"], values["thickness"], values["axle_length"]
    mass = values["density"] * np.pi * radius**2 * t
    return 0.5 * mass * radius**2, mass * (radius**2 / 4 + t**2 / 12 + length**2)


def estimate(values: dict, target: float) -> dict[str, float]:
    axial, transverse = _inertias(values)
    tau = axial / values["pivot_damping"]
    window = NUTATIONS * target
    return {"spin": float(2 * np.pi * transverse / (axial * target) * tau * np.expm1(window / tau) / window)}


TASK = DesignModel(
    id=414,
    name="gyroscope nutation period",
    system=GYROSCOPE,
    open_description=GYROSCOPE.open_description.replace(
        "{spin}*u rad/s (that\n        is {spin} rad/s about u", "omega_s*u (that\n        is omega_s about u").replace(
        "there is no friction.",
        "the ball joint has viscous friction: it exerts on the disc the torque -c*omega about O, omega "
        "being the disc's angular velocity vector (spin, precession and nutation alike), with "
        "c = {pivot_damping} N*m*s/rad; there is no other friction.").replace(
        "frictionless ball joint", "ball joint"),
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("disc_radius", 0.08, 0.1, "m"),
        Param("thickness", 0.01, 0.02, "m"),
        Param("axle_length", 0.08, 0.12, "m"),
        Param("elevation_deg", 0.0, 30.0, "deg"),
        Param("spin_decay_time", 5.0, 10.0, "s"),  # I_a / c: sets the friction
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    derive=lambda v: {"pivot_damping": round_significant(_inertias(v)[0] / v["spin_decay_time"], 3)},
    model_code=GYROSCOPE.model_code + """
        mbs.CreateRigidBodySpringDamper(itemNumbers=[oGround, oDisc], localPosition0=[0, 0, 0],
                                        localPosition1=[-axle_length, 0, 0], stiffness=np.zeros((6, 6)),
                                        damping=np.diag([0, 0, 0, pivot_damping, pivot_damping, pivot_damping]))
    """,
    extra_components=("RigidBodySpringDamper",),
    variables=(DesignVariable("spin", 55.0, 120.0, "rad/s", "the initial spin rate omega_s of the disc about its axis"),),
    spec=Spec("the mean nutation period over the first six nutations: the time of the disc centre's sixth "
              "height maximum after the start, divided by six", "period", "s", nutation_period),
    spec_text="""the mean nutation period over the first six nutations is {target} s, within
        ±{tolerance_percent} %: the disc centre's height (z-coordinate) starts at a maximum; take the
        time t6 of its sixth local maximum after the start; the mean period is t6/6.""",
    estimate=estimate,
    estimate_text="fast-top nutation frequency omega_nut = I_a omega_s / I_t (I_t about the pivot) with the spin "
                  "decaying as exp(-c t / I_a), averaged over the six periods and solved for omega_s",
    sim=SimSettings(end_time=3.0, steps=15000),
)
