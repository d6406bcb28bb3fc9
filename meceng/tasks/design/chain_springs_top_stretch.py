"""Task 426 (level 4): the string stiffness of an elastic chain pendulum that limits its top string's stretch.

The system is task 18's elastic n-pendulum (n point masses on n equal linear spring-dampers, the
first hanging from a fixed pivot), here with 4-6 masses released straight, with unstretched
strings, at a large angle; the strings' stiffness k is left open. The spec is an extreme: the
largest stretch of the top string (the distance of mass 1 from the pivot minus L) over the run.

Why a closed form misses: the top string carries the weight of the whole chain plus the
centrifugal pull of every mass below it, and the chain does not swing as one piece (it bends and
its lower masses whip, the tension peaking at no single instant a hand analysis picks); the strings
start unstretched, so every string also rings in its own axial modes, whose peaks add to the
swinging tension at times only the coupled equations give.

Estimate: the chain as a rigid straight bar swinging down from phi0 (energy), the top string's
tension at the bottom of the swing its weight plus the centrifugal pull of all the masses,
T = m g n + m w^2 L sum(i), and the stretch T / k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.n_pendulum_elastic_spring import TASK as CHAIN


def top_string_stretch(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(np.max(np.hypot(q[:, 0], q[:, 1])) - values["length"])  # mass point 1: columns 0..2


def estimate(values: dict, target: float) -> dict[str, float]:
    n, m, length, g = int(values["n_masses"]), values["mass"], values["length"], values["gravity"]
    i = np.arange(1, n + 1)
    phi0 = np.radians(values["angle_deg"])
    # rigid bar of point masses: (1/2) J w^2 = m g L sum(i) (1 - cos phi0), J = m L^2 sum(i^2)
    w2 = 2.0 * g * np.sum(i) * (1.0 - np.cos(phi0)) / (length * np.sum(i**2))
    tension = m * g * n + m * w2 * length * np.sum(i)
    return {"stiffness": float(tension / target)}


TASK = DesignModel(
    id=426,
    name="chain springs top stretch",
    system=CHAIN,
    open_description=CHAIN.open_description.replace("stiffness k = {stiffness} N/m", "stiffness k"),
    params=(
        Param("n_masses", 4, 6, "", integer=True),
        Param("mass", 0.2, 1.0, "kg"),
        Param("length", 0.2, 0.4, "m"),
        Param("damping", 0.5, 3.0, "N*s/m"),
        Param("angle_deg", 40.0, 70.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("stiffness", 1000.0, 5000.0, "N/m", "the stiffness k of every spring-damper"),),
    spec=Spec("the largest stretch of the top string (mass 1's distance from the pivot minus L) over the run",
              "extreme", "m", top_string_stretch),
    spec_text="""the top string (between the pivot and point mass 1) stretches at most {target} m over the
        simulated time: the largest distance of point mass 1 from the pivot, minus the unstretched
        length L, is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the chain as a rigid straight bar swinging down (energy); the top string's tension at the "
                  "bottom its weight plus the centrifugal pull of all masses, the stretch T / k",
    sim=SimSettings(end_time=1.0, steps=2000),
)
