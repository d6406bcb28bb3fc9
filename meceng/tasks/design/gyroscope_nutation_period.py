"""Task 414 (level 4): the spin rate that gives a heavy gyroscope a required nutation period.

The system is task 48's gyroscope (a disc on a massless axle, its end on a ball joint at a fixed
point, released with pure spin and the axle raised above the horizontal); the spin rate is left
open, in a range where the gyroscope is not fast (the precession rate is a good part of the
nutation rate). The spec is a period: the mean time between upward crossings of the disc centre's
height through its mean, i.e. the nutation period. Starting without precession, the axle falls
from its initial elevation and rises back in cusps; at these spin rates the nutation is large and
its period depends on gravity and on the inclination, not only on the spin.

Estimate: the fast-top nutation frequency omega_nut = I_a omega_s / I_t (I_a the disc's moment of
inertia about its axis, I_t about a transverse axis through the pivot), so
omega_s = 2 pi I_t / (I_a T_nut).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import mean_period
from meceng.tasks.gyroscope_nutation import TASK as GYROSCOPE


def nutation_period(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return mean_period(times, q[:, 2])  # the disc's centre: columns 0..2, height in 2


def estimate(values: dict, target: float) -> dict[str, float]:
    radius, t, length = values["disc_radius"], values["thickness"], values["axle_length"]
    mass = values["density"] * np.pi * radius**2 * t
    axial = 0.5 * mass * radius**2
    transverse = mass * (radius**2 / 4 + t**2 / 12 + length**2)
    return {"spin": float(2 * np.pi * transverse / (axial * target))}


TASK = DesignModel(
    id=414,
    name="gyroscope nutation period",
    system=GYROSCOPE,
    open_description=GYROSCOPE.open_description.replace("{spin}*u rad/s (that\n        is {spin} rad/s about u",
                                                        "omega_s*u (that\n        is omega_s about u"),
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("disc_radius", 0.08, 0.1, "m"),
        Param("thickness", 0.01, 0.02, "m"),
        Param("axle_length", 0.08, 0.12, "m"),
        Param("elevation_deg", 0.0, 30.0, "deg"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("spin", 40.0, 100.0, "rad/s", "the initial spin rate omega_s of the disc about its axis"),),
    spec=Spec("the nutation period: the mean time between upward crossings of the disc centre's height "
              "through its mean height", "period", "s", nutation_period),
    spec_text="""the nutation period, measured as the mean time between successive upward crossings of the
        disc centre's height (z-coordinate) through its mean value over the simulated time, is
        {target} s, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="fast-top nutation frequency omega_nut = I_a omega_s / I_t (I_t about the pivot): "
                  "omega_s = 2 pi I_t / (I_a T_nut)",
    sim=SimSettings(end_time=2.0, steps=10000),
)
