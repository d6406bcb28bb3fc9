"""Task 429 (level 4): the coupling stiffness of two flying bars that sets how far their joint
opens late in the motion.

The system is task 14's two free bars joined end to end by a zero-length spring-damper, thrown with
opposite transverse velocities (no gravity), here with a soft coupling; its stiffness k is left
open. The spec is an extreme: the largest gap between the two joined end points from t = T/2 on.

Why a closed form misses: the ends first fly apart (the bars translate, the coupling is relaxed)
until the spring catches them and starts the pair's spin; from then on the gap carries the
centrifugal pull of the spinning pair, which itself depends on the gap (the arm lengthens, the spin
slows), and the coupling's transverse and axial ringing, which exchange energy with the spin and
decay through the damper at rates that change as the pair's geometry changes. The late gap is what
is left of all of them, at an instant only the coupled equations give.

Estimate: the pair spins as one rigid bar (angular momentum m v a over 2 m a^2 / 3, so
w = 3 v / (2 a)); each bar's centre on a circle of radius a/2 needs the coupling to pull with
m w^2 a / 2, and a load applied suddenly to a relaxed spring stretches it twice as far as it would
statically: gap = m w^2 a / k.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import body_axis
from meceng.tasks.spring_coupled_flying_rigid_bodies import TASK as BARS

K_RANGE = (300.0, 3000.0)


def late_gap(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    half = 0.5 * values["size_x"]
    # bar 1: position in columns 0..2, Euler parameters 3..6; bar 2: 7..9 and 10..13
    end1 = q[:, 0:3] + half * body_axis(q, 3, 0)
    end2 = q[:, 7:10] - half * body_axis(q, 10, 0)
    late = times >= 0.5 * times[-1]
    return float(np.max(np.linalg.norm(end1 - end2, axis=1)[late]))


def estimate(values: dict, target: float) -> dict[str, float]:
    m = values["density"] * values["size_x"] * values["size_y"] * values["size_z"]
    a = values["size_x"]
    spin = 3.0 * values["velocity"] / (2.0 * a)
    return {"stiffness": float(m * spin**2 * a / target)}


TASK = DesignModel(
    id=429,
    name="flying bars late gap",
    system=BARS,
    open_description=BARS.open_description.replace("with k = {stiffness} N/m and", "with the stiffness k and"),
    params=(
        Param("density", 1000.0, 2000.0, "kg/m^3"),
        Param("size_x", 0.4, 0.6, "m"),
        Param("size_y", 0.1, 0.15, "m"),
        Param("size_z", 0.05, 0.08, "m"),
        Param("damping", 0.5, 3.0, "N*s/m"),
        Param("velocity", 0.5, 2.0, "m/s"),
    ),
    variables=(DesignVariable("stiffness", *K_RANGE, "N/m", "the stiffness k of the coupling"),),
    spec=Spec("the largest gap between the two joined end points from t = T/2 on", "extreme", "m", late_gap),
    spec_text="""from half the simulated time on, the two joined end points (the centre of bar 1's end face
        at +x and the centre of bar 2's end face at -x) are never farther apart than {target} m:
        their largest distance from t = T/2 to the end is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="the pair spinning as one rigid bar (w = 3 v / (2 a)), the coupling's pull m w^2 a / 2 applied "
                  "suddenly: twice its static stretch, gap = m w^2 a / k",
)
