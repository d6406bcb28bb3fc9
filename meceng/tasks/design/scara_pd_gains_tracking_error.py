"""Task 416 (level 4): the PD gains of a 2R SCARA arm that give a largest tool-tip tracking error.

The system is task 49's two-link SCARA robot following cosine joint trajectories through PD
joint torques; both gains kP and kD (the same for the two joints) are open, in a soft range where
the arm lags its trajectory by several degrees. The spec is an extreme: the largest distance of the
tip of link 2 from its desired position (the trajectory's angles through the arm's geometry) over
the run; the elbow swings from bent one way (q2 = -90..-40 degrees) to bent the other way
(40..90 degrees). At such gains the error is dynamic, not quasi-static (at high gains the lag is J q''/kP
and an estimate is within 0.4 %): the arm's inertia about joint 1 changes with q2, the joints
couple through the off-diagonal inertia and the centrifugal and Coriolis torques, and the errors
of the two joints add as vectors at the tip. Many (kP, kD) pairs pass: a curve's band.

Estimate: the error dynamics linearised with the mass matrix frozen at the mean elbow angle,
M e'' + kD e' + kP e = M q_d'' (the joint errors e driven by the desired accelerations; no
centrifugal or Coriolis torques), kD in the middle of its range, kP such that the largest tip error
of these joint errors (through the arm's Jacobian along the desired path) is the target.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z
from meceng.tasks.t2r_scara_robot import TASK as SCARA

KD_RANGE = (1.0, 6.0)
#: the elbow swings through the stretched pose (the mass matrix changes most)
RANGES = {"q2_start_deg": (-90.0, -40.0), "q2_end_deg": (40.0, 90.0)}


def _desired(values: dict, t: np.ndarray) -> tuple[np.ndarray, ...]:
    """Desired joint angles and accelerations of the cosine trajectories at the times ``t``."""
    big_t = values["duration"]
    s = np.clip(t / big_t, 0.0, 1.0)
    out = []
    for joint in ("1", "2"):
        qs, qe = np.radians(values[f"q{joint}_start_deg"]), np.radians(values[f"q{joint}_end_deg"])
        out.append(qs + (qe - qs) * (1 - np.cos(np.pi * s)) / 2)
        out.append(np.where(t < big_t, (qe - qs) * np.pi**2 / (2 * big_t**2) * np.cos(np.pi * s), 0.0))
    return tuple(out)


def largest_tip_error(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    l1, l2 = values["length1"], values["length2"]
    phi2 = angle_z(q, 10)  # link 2: position in columns 7..9, Euler parameters in 10..13
    tip = q[:, 7:9] + 0.5 * l2 * np.column_stack([np.cos(phi2), np.sin(phi2)])
    q1d, _, q2d, _ = _desired(values, times)
    goal = np.column_stack([l1 * np.cos(q1d) + l2 * np.cos(q1d + q2d), l1 * np.sin(q1d) + l2 * np.sin(q1d + q2d)])
    return float(np.max(np.linalg.norm(tip - goal, axis=1)))


def estimate(values: dict, target: float) -> dict[str, float]:
    rho, l1, l2, w = values["density"], values["length1"], values["length2"], 0.04
    m1, m2 = rho * l1 * w * w, rho * l2 * w * w
    i1, i2 = m1 * (l1**2 + w**2) / 12, m2 * (l2**2 + w**2) / 12
    c2 = np.cos(np.radians(0.5 * (values["q2_start_deg"] + values["q2_end_deg"])))
    m12 = i2 + m2 * (l2**2 / 4 + l1 * l2 * c2 / 2)
    mass = np.array([[i1 + m1 * l1**2 / 4 + i2 + m2 * (l1**2 + l2**2 / 4 + l1 * l2 * c2), m12],
                     [m12, i2 + m2 * l2**2 / 4]])
    inverse = np.linalg.inv(mass)
    dt = 1e-3
    t = np.arange(0.0, 2.0, dt)
    q1d, a1d, q2d, a2d = _desired(values, t)
    acc = np.column_stack([a1d, a2d])
    kd = 0.5 * (KD_RANGE[0] + KD_RANGE[1])

    def tip_error(kp: float) -> float:
        e, v, out = np.zeros(2), np.zeros(2), np.empty_like(acc)
        for n in range(len(t)):  # semi-implicit Euler on M e'' + kD e' + kP e = M q_d''
            v = v + dt * (acc[n] - inverse @ (kd * v + kp * e))
            e = e + dt * v
            out[n] = e
        e1, e2 = out.T  # tip error = Jacobian (desired pose) times the joint errors
        dx = -(l1 * np.sin(q1d) + l2 * np.sin(q1d + q2d)) * e1 - l2 * np.sin(q1d + q2d) * e2
        dy = (l1 * np.cos(q1d) + l2 * np.cos(q1d + q2d)) * e1 + l2 * np.cos(q1d + q2d) * e2
        return float(np.max(np.hypot(dx, dy)))

    lo, hi = 1.0, 2000.0
    for _ in range(30):  # the error falls as kP grows
        kp = np.sqrt(lo * hi)
        lo, hi = (kp, hi) if tip_error(kp) > target else (lo, kp)
    return {"kp": float(np.sqrt(lo * hi)), "kd": kd}


TASK = DesignModel(
    id=416,
    name="scara pd gains tracking error",
    system=SCARA,
    open_description=SCARA.open_description.replace("k_P = {kp} N*m/rad", "the gains k_P (N*m/rad)").replace(
        "k_D = {kd} N*m*s/rad", "k_D (N*m*s/rad), the same for both joints"),
    params=tuple(p if p.name not in RANGES else Param(p.name, *RANGES[p.name], p.unit, digits=p.digits)
                 for p in SCARA.params if p.name not in ("kp", "kd")),
    variables=(
        DesignVariable("kp", 20.0, 120.0, "N*m/rad", "the proportional gain k_P of both joints"),
        DesignVariable("kd", *KD_RANGE, "N*m*s/rad", "the derivative gain k_D of both joints"),
    ),
    spec=Spec("the largest distance of link 2's tip from its desired position during the run", "extreme", "m",
              largest_tip_error),
    spec_text="""the largest tracking error of the tool tip (the free end of link 2, on its centre line)
        during the simulated 2 s, that is the largest distance between the tip and the point the
        desired joint angles q_1,d(t), q_2,d(t) put it at, L1*[cos(q_1,d), sin(q_1,d), 0] +
        L2*[cos(q_1,d + q_2,d), sin(q_1,d + q_2,d), 0], is {target} m, within ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="linear error dynamics M e'' + kD e' + kP e = M q_d'' with M frozen at the mean elbow angle, "
                  "kD mid-range, kP such that the largest tip error (through the Jacobian) is the target",
    sim=SimSettings(end_time=2.0, steps=1000,
                    extra=("simulationSettings.timeIntegration.computeLoadsJacobian = 2",)),
)
