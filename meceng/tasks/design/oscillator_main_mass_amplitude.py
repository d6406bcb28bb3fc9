"""Task 411 (level 4): the coupling stiffness that gives a double mass oscillator's first mass a
required largest amplitude.

The system is task 9's double mass oscillator (ground - spring-damper 1 - mass 1 - spring-damper 2 -
mass 2 along x), started with only spring 2 stretched; the stiffness k2 of spring 2 is left open.
The spec is an extreme: the largest displacement of mass 1 from its unstretched position (either
direction) over the run. Mass 1 is driven by the two modes beating against each other while both
decay at different rates; which of the beat's peaks is the largest, and how far the damping has
cut it by then, is not given by a formula.

Estimate: the undamped modal solution (2x2 eigenproblem K phi = omega^2 M phi, x1 = sum of the two
modal cosines, equal and opposite at t = 0), its largest |x1| over the run read off the closed form;
solved for k2 on a fine scan of the range.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.double_mass_oscillator import TASK as OSCILLATOR


def largest_amplitude(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(np.max(np.abs(q[:, 0] - values["length1"])))  # mass 1: columns 0..2


def undamped_amplitude(values: dict, k2: float) -> float:
    """The largest |x1| of the undamped modal solution over the run (0 to 2 s)."""
    m1, m2, k1, u = values["mass1"], values["mass2"], values["stiffness1"], values["displacement"]
    stiffness = np.array([[k1 + k2, -k2], [-k2, k2]])
    mass_sqrt = np.diag([1 / np.sqrt(m1), 1 / np.sqrt(m2)])
    omega2, vectors = np.linalg.eigh(mass_sqrt @ stiffness @ mass_sqrt)
    modes = mass_sqrt @ vectors  # columns: phi_j
    parts = np.linalg.solve(modes, [0.0, u]) * modes[0]  # x1's modal amplitudes (equal and opposite)
    t = np.linspace(0.0, 2.0, 4001)
    return float(np.max(np.abs(np.cos(np.outer(t, np.sqrt(omega2))) @ parts)))


def estimate(values: dict, target: float) -> dict[str, float]:
    k2 = np.linspace(100.0, 800.0, 701)
    gap = np.array([undamped_amplitude(values, k) for k in k2]) - target
    return {"stiffness2": float(k2[int(np.argmin(np.abs(gap)))])}


TASK = DesignModel(
    id=411,
    name="oscillator main mass amplitude",
    system=OSCILLATOR,
    open_description=OSCILLATOR.open_description.replace("k2 = {stiffness2} N/m", "k2"),
    params=(
        Param("mass1", 0.5, 5.0, "kg"),
        Param("mass2", 0.5, 5.0, "kg"),
        Param("stiffness1", 200.0, 2000.0, "N/m"),
        Param("damping1", 0.5, 5.0, "N*s/m"),
        Param("damping2", 0.5, 5.0, "N*s/m"),
        Param("length1", 0.5, 2.0, "m"),
        Param("length2", 0.5, 2.0, "m"),
        Param("displacement", 0.02, 0.1, "m"),
    ),
    variables=(DesignVariable("stiffness2", 100.0, 800.0, "N/m", "the stiffness k2 of spring-damper 2"),),
    spec=Spec("the largest displacement of mass 1 from its unstretched position over the run", "extreme", "m",
              largest_amplitude),
    spec_text="""the largest distance of mass 1 from its unstretched position [{length1}, 0, 0] m (in either
        direction along x) over the simulated time is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="undamped modal solution (2x2 eigenproblem), the largest |x1| of its closed form over the "
                  "run, solved for k2",
)
