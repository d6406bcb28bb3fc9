"""Task 413 (level 4): the stiffness of the upper string that limits its largest stretch in a
double pendulum on elastic strings.

The system is task 17's double pendulum on two spring-dampers (elastic strings), released from
rest with both springs unstretched; the stiffness k1 of the upper spring is left open. The spec is
an extreme: the largest stretch of spring 1 (the distance of mass 1 from the pivot minus L1) over
the run. Released unstretched, both strings bounce while the two masses swing: the stretch adds
the bounce, the swing's centrifugal pull and the lower mass's varying pull along a string that is
not aligned with the upper one, each at its own frequency.

Estimate: both masses as one pendulum swinging from phi1 (tension at the bottom of the swing
(m1 + m2) g (3 - 2 cos phi1)), plus the bounce of a string released unstretched (amplitude its
static stretch at release, (m1 + m2) g cos phi1 / k1): k1 = (m1 + m2) g (3 - cos phi1) / stretch.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.double_pendulum_elastic_spring import TASK as PENDULUM


def largest_stretch(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    return float(np.max(np.linalg.norm(q[:, 0:3], axis=1)) - values["length1"])  # mass 1: columns 0..2


def estimate(values: dict, target: float) -> dict[str, float]:
    weight = (values["mass1"] + values["mass2"]) * values["gravity"]
    phi1 = np.radians(values["angle1_deg"])
    return {"stiffness1": float(weight * (3 - np.cos(phi1)) / target)}


TASK = DesignModel(
    id=413,
    name="elastic pendulum largest stretch",
    system=PENDULUM,
    open_description=PENDULUM.open_description.replace("k1 = {stiffness1} N/m", "k1"),
    params=(
        Param("mass1", 0.5, 3.0, "kg"),
        Param("mass2", 0.5, 3.0, "kg"),
        Param("length1", 0.3, 1.0, "m"),
        Param("length2", 0.3, 1.0, "m"),
        Param("stiffness2", 1000.0, 5000.0, "N/m"),
        Param("damping", 0.0, 2.0, "N*s/m"),
        Param("angle1_deg", 10.0, 30.0, "deg", digits=2),
        Param("angle2_deg", -30.0, 30.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("stiffness1", 2000.0, 8000.0, "N/m", "the stiffness k1 of spring-damper 1"),),
    spec=Spec("the largest stretch of spring 1 (distance of mass 1 from the pivot minus L1) over the run",
              "extreme", "m", largest_stretch),
    spec_text="""the largest stretch of spring 1 over the simulated time, i.e. the largest distance of point
        mass 1 from the pivot minus its unstretched length L1, is {target} m, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="both masses as one pendulum from phi1 (bottom tension (m1 + m2) g (3 - 2 cos phi1)) plus the "
                  "bounce of a string released unstretched: k1 = (m1 + m2) g (3 - cos phi1) / stretch",
)
