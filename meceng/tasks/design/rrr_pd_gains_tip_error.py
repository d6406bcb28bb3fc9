"""Task 424 (level 4): the PD gains of a three-joint articulated arm that give a largest tool-tip error.

The system is task 50's RRR arm (a column turning about the vertical, an upper arm and a forearm
on horizontal hinges, cuboid links, no gravity compensation) following cubic joint trajectories
through PD joint torques; both gains kP and kD (the same for the three joints) are open, in a soft
range where the arm sags and lags by several degrees. The spec is an extreme: the largest distance
of the forearm's outer end from where the trajectory's angles put it, from the middle of the motion
(t = T/2, the base turning fastest) to the end of the run. (Over the whole run the largest error is
the arm's first drop under gravity from the start pose, where the trajectory has hardly moved: a
linear step response, which a hand analysis gets exactly; a blind answer did, at 0.03 tolerances.)

Why a closed form misses: the error is gravity's sag and the dynamic lag together, in three
dimensions: the upper arm and forearm carry each other's weight through the changing pose, the
column's inertia about the vertical changes with the arm's reach, the joints couple through the
off-diagonal inertia and the centrifugal and Coriolis torques of the base's turn, and with soft
gains the errors overshoot after the motion ends. Many (kP, kD) pairs pass: a curve's band.

Estimate: quasi-static joint errors, each joint's gravity torque and its own inertia times the
desired acceleration over kP (the pose frozen along the desired path, no coupling), mapped to the
tip through the arm's geometry; kD in the middle of its range, kP such that the largest tip error
is the target.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import body_axis
from meceng.tasks.rrr_articulated_robot_with_3d_cubic_trajectory import TASK as RRR

KD_RANGE = (4.0, 30.0)
SIDE = 0.05  # the links' square cross-section (task 50)


def _desired(values: dict, t: np.ndarray) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The cubic trajectories' angles and accelerations of the three joints at the times ``t``."""
    big_t = values["duration"]
    s = np.clip(t / big_t, 0.0, 1.0)
    angles, accelerations = [], []
    for joint in ("1", "2", "3"):
        end = np.radians(values[f"q{joint}_end_deg"])
        angles.append(end * (3 * s**2 - 2 * s**3))
        accelerations.append(np.where(t < big_t, end * 6 * (1 - 2 * s) / big_t**2, 0.0))
    return angles, accelerations


def _tip(values: dict, q1: np.ndarray, q2: np.ndarray, q3: np.ndarray) -> np.ndarray:
    """The forearm's outer end for joint angles (forward kinematics of the arm)."""
    reach = values["length2"] * np.cos(q2) + values["length3"] * np.cos(q2 + q3)
    height = values["length1"] + values["length2"] * np.sin(q2) + values["length3"] * np.sin(q2 + q3)
    return np.column_stack([reach * np.cos(q1), reach * np.sin(q1), height])


def largest_tip_error(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    # link 3: position in columns 14..16, Euler parameters 17..20, the link along its local x-axis
    tip = q[:, 14:17] + 0.5 * values["length3"] * body_axis(q, 17, 0)
    angles, _ = _desired(values, times)
    late = times >= 0.5 * values["duration"]
    return float(np.max(np.linalg.norm(tip - _tip(values, *angles), axis=1)[late]))


def estimate(values: dict, target: float) -> dict[str, float]:
    rho, l2, l3, g = values["density"], values["length2"], values["length3"], 9.81
    m2, m3 = rho * l2 * SIDE**2, rho * l3 * SIDE**2
    t = np.linspace(0.5 * values["duration"], 2.0, 801)
    (q1, q2, q3), (a1, a2, a3) = _desired(values, t)
    reach2, reach3 = l2 * np.cos(q2), l3 * np.cos(q2 + q3)
    # gravity torques at the shoulder and the elbow, and each joint's own inertia about its axis
    tau2 = g * (m2 * reach2 / 2 + m3 * (reach2 + reach3 / 2))
    tau3 = g * m3 * reach3 / 2
    inertia1 = m2 * (l2**2 / 3) * np.cos(q2) ** 2 + m3 * (reach2 + reach3 / 2) ** 2
    inertia2 = m2 * l2**2 / 3 + m3 * (l2**2 + l3**2 / 3 + l2 * l3 * np.cos(q3))
    inertia3 = m3 * l3**2 / 3

    def tip_error(kp: float) -> float:
        e1 = inertia1 * a1 / kp
        e2 = (inertia2 * a2 + tau2) / kp
        e3 = (inertia3 * a3 + tau3) / kp
        return float(np.max(np.linalg.norm(_tip(values, q1, q2, q3) - _tip(values, q1 - e1, q2 - e2, q3 - e3),
                                           axis=1)))

    lo, hi = 1.0, 1e5
    for _ in range(40):  # the error falls as kP grows
        kp = np.sqrt(lo * hi)
        lo, hi = (kp, hi) if tip_error(kp) > target else (lo, kp)
    return {"kp": float(np.sqrt(lo * hi)), "kd": 0.5 * (KD_RANGE[0] + KD_RANGE[1])}


TASK = DesignModel(
    id=424,
    name="rrr pd gains tip error",
    system=RRR,
    open_description=RRR.open_description.replace("with k_P = {kp} N*m/rad\n        and k_D = {kd} N*m*s/rad",
                                                  "with the gains k_P and\n        k_D"),
    params=tuple(p for p in RRR.params if p.name not in ("kp", "kd")),
    variables=(DesignVariable("kp", 150.0, 800.0, "N*m/rad", "the proportional gain k_P of all three joints"),
               DesignVariable("kd", *KD_RANGE, "N*m*s/rad", "the derivative gain k_D of all three joints")),
    spec=Spec("the largest distance of the forearm's outer end from its desired position from t = T/2 on", "extreme",
              "m", largest_tip_error),
    spec_text="""the tool tip (the outer end of link 3, on its axis) follows its desired position: the
        position the desired joint angles q_i,d(t) give it through the arm's geometry. The largest
        distance between the actual and the desired tip position from the middle of the motion,
        t = T/2, to the end of the simulated time is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="quasi-static joint errors (gravity torque plus the joint's own inertia times the desired "
                  "acceleration, over kP; no coupling) mapped to the tip, kD mid-range",
    sim=SimSettings(end_time=2.0, steps=2000),
)
