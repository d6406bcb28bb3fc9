"""Task 422 (level 4): the spring stiffness that gives an elliptic trammel a given oscillation period.

The system is task 22's elliptic trammel: two point-mass sliders on perpendicular guides joined by
a massless link, the horizontal slider held by a spring-damper to the origin that is unstretched
at the start; gravity pulls the vertical slider down. The spring's stiffness k is left open. The
spec is a period: slider 2's height oscillates about its equilibrium, and the period is the time
between the first and the fourth upward crossing of its mean height over the run, divided by 3.
The sliders start far from the equilibrium (the spring is unstretched), so the swing is large:
the effective mass m1 sin^2(beta) + m2 cos^2(beta) of the link angle beta and the spring's lever
change along it, and the damper takes energy out, so the period drifts from swing to swing.

Estimate: the static equilibrium beta_e of the link angle (k (L cos beta - x0) sin beta =
m2 g cos beta), the motion linearised about it (stiffness V''(beta_e), mass
L^2 (m1 sin^2 beta_e + m2 cos^2 beta_e), damping d L^2 sin^2 beta_e), its damped period solved
for k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import crossings
from meceng.tasks.link_on_two_prismatic_joints import TASK as TRAMMEL


def swing_period(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    height = q[:, 5]  # slider 2: columns 3..5 (slider 1 is 0..2)
    ups = crossings(times, height, float(np.mean(height)))
    return float((ups[3] - ups[0]) / 3) if ups.size >= 4 else float("nan")


def _linear_period(values: dict, k: float) -> float:
    m1, m2, g, d = values["mass1"], values["mass2"], values["gravity"], values["damping"]
    x0, z0 = values["x0"], values["z0"]
    length = np.hypot(x0, z0)
    lo, hi = -np.pi / 2 + 1e-9, np.arctan2(z0, x0)  # the equilibrium lies below the start angle
    for _ in range(80):
        beta = 0.5 * (lo + hi)
        force = k * (length * np.cos(beta) - x0) * np.sin(beta) - m2 * g * np.cos(beta)  # = -dV/dbeta / L
        lo, hi = (lo, beta) if force < 0 else (beta, hi)
    beta = 0.5 * (lo + hi)
    h = 1e-6

    def dv(b: float) -> float:
        return -k * (length * np.cos(b) - x0) * length * np.sin(b) + m2 * g * length * np.cos(b)

    stiffness = (dv(beta + h) - dv(beta - h)) / (2 * h)
    mass = length**2 * (m1 * np.sin(beta) ** 2 + m2 * np.cos(beta) ** 2)
    damping = d * length**2 * np.sin(beta) ** 2
    omega = np.sqrt(max(stiffness / mass - (damping / (2 * mass)) ** 2, 1e-12))
    return float(2 * np.pi / omega)


def estimate(values: dict, target: float) -> dict[str, float]:
    lo, hi = 10.0, 1.0e5
    for _ in range(60):  # the period falls as k grows
        k = np.sqrt(lo * hi)
        lo, hi = (k, hi) if _linear_period(values, k) > target else (lo, k)
    return {"stiffness": float(np.sqrt(lo * hi))}


TASK = DesignModel(
    id=422,
    name="trammel spring period",
    system=TRAMMEL,
    open_description=TRAMMEL.open_description.replace("k =\n        {stiffness} N/m", "k (to be chosen)"),
    params=(
        Param("mass1", 1.0, 5.0, "kg"),
        Param("mass2", 0.5, 1.5, "kg"),
        Param("x0", 0.6, 0.9, "m"),
        Param("z0", 0.6, 1.0, "m"),
        Param("damping", 1.0, 4.0, "N*s/m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("stiffness", 500.0, 2000.0, "N/m", "the spring's stiffness k"),),
    spec=Spec("slider 2's oscillation period: a third of the time from its first to its fourth upward crossing "
              "of its mean height", "period", "s", swing_period),
    spec_text="""slider 2's height oscillates about its mean over the simulated 3 s (the average of its
        height over all time steps); the period of this oscillation, a third of the time between the
        first and the fourth time the height crosses that mean upwards, is {target} s, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the static equilibrium of the link angle, the motion linearised about it (with the damping), "
                  "its damped period solved for k",
    sim=SimSettings(end_time=3.0, steps=3000),
)
