"""Task 421 (level 4): the start angle of a double pendulum that makes its lower mass rise to a given
height late in the run.

The system is task 12's double pendulum (two point masses on massless rods), released at rest
with rod 2 hanging straight down (phi2 = 0) and rod 1 turned by phi1; phi1 is left open. The spec
is an extreme: the largest height of mass 2 above its lowest possible point (y2 + L1 + L2) during
the last 3 s of a 6 s run. The two modes exchange energy: how high mass 2 swings late in the run
depends on the beat of the two modes, whose frequencies shift with the amplitude (large angles,
phi1 = 25..45 degrees), so after several swings the linear modes' phases are off.

Estimate: the linearised double pendulum (two normal modes from the mass and stiffness matrices
at the hanging pose), started from (phi1, 0): the largest small-angle height
L1 (1 - cos phi1(t)) + L2 (1 - cos phi2(t)) in the window, which grows with phi1, solved for phi1.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.double_pendulum import TASK as DOUBLE_PENDULUM

WINDOW = (3.0, 6.0)


def late_rise(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    rise = q[:, 4] + values["length1"] + values["length2"]  # mass 2: columns 3..5
    inside = (times >= WINDOW[0]) & (times <= WINDOW[1])
    return float(np.max(rise[inside]))


def _linear_rise(values: dict, angle_deg: float) -> float:
    m1, m2, l1, l2, g = (values[k] for k in ("mass1", "mass2", "length1", "length2", "gravity"))
    mass = np.array([[(m1 + m2) * l1**2, m2 * l1 * l2], [m2 * l1 * l2, m2 * l2**2]])
    stiffness = np.diag([(m1 + m2) * g * l1, m2 * g * l2])
    w2, modes = np.linalg.eig(np.linalg.solve(mass, stiffness))
    amplitudes = np.linalg.solve(modes, [np.radians(angle_deg), 0.0])
    t = np.linspace(*WINDOW, 30001)
    phi = modes @ (amplitudes[:, None] * np.cos(np.sqrt(w2.real)[:, None] * t))
    return float(np.max(l1 * (1 - np.cos(phi[0])) + l2 * (1 - np.cos(phi[1]))))


def estimate(values: dict, target: float) -> dict[str, float]:
    lo, hi = 1.0, 90.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _linear_rise(values, mid) < target else (lo, mid)
    return {"angle1_deg": 0.5 * (lo + hi)}


TASK = DesignModel(
    id=421,
    name="double pendulum late rise",
    system=DOUBLE_PENDULUM,
    open_description=DOUBLE_PENDULUM.open_description.replace(
        "phi1 = {angle1_deg} degrees", "phi1 (to be chosen)").replace("{angle2_deg}", "0"),
    params=(
        Param("mass1", 0.5, 2.0, "kg"),
        Param("mass2", 0.5, 2.0, "kg"),
        Param("length1", 0.4, 1.0, "m"),
        Param("length2", 0.4, 1.0, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    derive=lambda v: {"angle2_deg": 0.0},
    variables=(DesignVariable("angle1_deg", 25.0, 45.0, "deg", "the start angle phi1 of rod 1"),),
    spec=Spec("the largest height of mass 2 above its lowest possible point during 3 s <= t <= 6 s", "extreme",
              "m", late_rise),
    spec_text="""the largest height of mass 2 above its lowest possible point (its y-coordinate plus
        L1 + L2) during the last 3 s of the run (3 s <= t <= 6 s) is {target} m, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the linearised double pendulum's two normal modes from (phi1, 0): the largest small-angle "
                  "height in the window, solved for phi1",
    sim=SimSettings(end_time=6.0, steps=6000),
)
