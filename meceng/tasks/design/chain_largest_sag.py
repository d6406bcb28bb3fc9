"""Task 409 (level 4): the spring stiffness that gives an elastic chain a required largest sag.

The system is task 33's elastic chain (n point masses on n + 1 pretensioned spring-dampers between
two fixed points, released from the straight line under gravity), with a weak pretension (the
unstretched length 0.95-0.99 of the spacing); the springs' stiffness k is left open. The spec is
an extreme: the largest sag of the chain (the lowest point of any mass below the line A-B) over the
run. With the weak pretension the tension comes mostly from the stretch the sag makes (a geometric
hardening, sag ~ k^(-1/3) rather than 1/k); the masses do not reach their lowest points together,
and the damping takes part of the first swing.

Estimate: energy balance at the lowest point of the first swing, the chain at rest there in the
parabolic shape y_i = s*4 x_i (L - x_i)/L^2 (Rayleigh's assumed shape, no damping): gravity's work
m g s sum(phi_i) equals the springs' energy gained, sum k/2 ((l_j - l0)^2 - (h - l0)^2), solved
for k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.elastic_chain import TASK as CHAIN


def largest_sag(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    n = int(values["n_masses"])
    heights = q[:, [3 * i + 1 for i in range(n)]]  # mass point i: columns 3i..3i+2
    return float(np.max(-heights))


def estimate(values: dict, target: float) -> dict[str, float]:
    n, span = int(values["n_masses"]), values["span"]
    h = span / (n + 1)
    l0 = values["length_ratio"] * h
    x = np.arange(n + 2) * h
    shape = 4 * x * (span - x) / span**2  # 0 at A and B
    shape *= 1.0 / np.max(shape[1:-1])  # the lowest mass sags by s
    work = values["mass"] * values["gravity"] * target * np.sum(shape[1:-1])
    lengths = np.sqrt(h**2 + (target * np.diff(shape)) ** 2)
    energy_per_k = 0.5 * np.sum((lengths - l0) ** 2 - (h - l0) ** 2)
    return {"stiffness": float(work / energy_per_k)}


TASK = DesignModel(
    id=409,
    name="chain largest sag",
    system=CHAIN,
    open_description=CHAIN.open_description.replace("k = {stiffness} N/m", "k"),
    params=(
        Param("n_masses", 3, 8, integer=True),
        Param("span", 1.0, 3.0, "m"),
        Param("mass", 0.05, 0.5, "kg"),
        Param("damping", 0.5, 3.0, "N*s/m"),
        Param("length_ratio", 0.95, 0.99, ""),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("stiffness", 500.0, 5000.0, "N/m", "the stiffness k of every spring-damper"),),
    spec=Spec("the largest sag of the chain (the largest distance of any mass below the line A-B) over the run",
              "extreme", "m", largest_sag),
    spec_text="""the largest sag of the chain over the simulated time, i.e. the largest distance by which any
        of the masses comes below the straight line y = 0 through A and B at any time, is {target} m,
        within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="energy balance at the lowest point of the first swing, the chain at rest in a parabolic "
                  "shape, no damping: m g s sum(phi_i) = sum k/2 ((l_j - l0)^2 - (h - l0)^2), solved for k",
)
