"""Task 412 (level 4): the motor-side damping that settles a two-disc torsional drive with a hardening
shaft in a required time.

The system is task 15's torsional oscillator (a disc on a hinge with a torsional spring-damper to
the fixed world, a constant torque) with a second, heavier disc on the same axis coupled to the
first by a soft undamped torsional shaft that hardens with its twist: its torque is
k_s*delta + k_3*delta^3 (delta the twist of disc 1 against disc 2), the cubic term as large as the
linear one at a twist of 0.5-0.7 times the final angle T/k (k_3 = h k_s (k/T)^2, h = 2-4), a twist
the transient reaches. The
torque is applied suddenly at t = 0 to disc 1 and both discs start at rest. The damping coefficient
d of the spring-damper between the world and disc 1 is left open. The spec is a settling time:
when the swing of the load disc 2 about its final angle T/k has decayed to a band b, read off the
envelope through the peaks of |phi2 - T/k| (log-linear between the last peak above b and the next).

Why a hand calculation misses: with a linear shaft the drive is a linear 2-DOF system, and the
exact complex root of its slow mode and that mode's residue gave the envelope and its settling
time. The hardening shaft makes the early, large swings nonlinear: the modes' frequencies depend
on the amplitude and the shaft passes energy between them, so the slow mode leaves the transient
with an amplitude (and phase) no modal solution gives; only the last, small swings are linear, and
the settling time is the logarithm of that amplitude over the slow mode's decay rate, so a few
per cent off in the amplitude is more than the 1 % tolerance. (With the linear shaft the settling
time differs by 5-20 % from this one.)

Estimate: disc 1 massless (quasi-static) and the shaft linearised (k_s, its small-twist
stiffness), so disc 2 swings on k and k_s in series, k_e = k k_s / (k + k_s), damped through the
shaft by c_e = d (k_s / (k + k_s))^2; the 1-DOF envelope (T/k) exp(-c_e t / (2 J2)) reaching b:
d = 2 J2 ln(T / (k b)) / (t_s (k_s/(k + k_s))^2).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings, round_significant
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import angle_z, local_maxima
from meceng.tasks.torsional_oscillator import TASK as TORSIONAL


def envelope_settling(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    final = values["torque"] / values["stiffness"]
    deviation = np.abs(angle_z(q, 10) - final)  # disc 2: columns 7..13, Euler parameters 10..13
    band = 0.01 * values["band_percent"] * final
    peaks = local_maxima(deviation)
    above = np.nonzero(deviation[peaks] > band)[0]
    if above.size == 0 or above[-1] + 1 >= peaks.size:
        return float("nan")
    i, j = peaks[above[-1]], peaks[above[-1] + 1]
    fraction = np.log(deviation[i] / band) / np.log(deviation[i] / deviation[j])
    return float(times[i] + fraction * (times[j] - times[i]))


def estimate(values: dict, target: float) -> dict[str, float]:
    k, k_s = values["stiffness"], values["shaft_stiffness"]
    j2 = 0.5 * values["mass2"] * values["radius2"] ** 2
    ratio = k_s / (k + k_s)
    return {"damping": float(2 * j2 * np.log(100 / values["band_percent"]) / (target * ratio**2))}


TASK = DesignModel(
    id=412,
    name="torsional drive settling",
    system=TORSIONAL,
    open_description="""
        A torsional oscillator with two discs on one axis. Disc 1 is a homogeneous solid cylinder of
        mass m1 = {mass} kg, radius {radius} m and thickness {width} m, centred at the origin
        [0, 0, 0]; disc 2 is a homogeneous solid cylinder of mass m2 = {mass2} kg, radius {radius2} m
        and thickness {width} m, centred at [0, 0, {offset}] m. The axes of symmetry of both discs lie
        along the global z-axis; each disc turns on its own frictionless hinge about the z-axis
        through its centre (its centre stays fixed, it can only turn about z). A linear torsional
        spring-damper between the fixed world and disc 1 acts about the z-axis with stiffness
        k = {stiffness} N*m/rad and damping coefficient d; a hardening torsional spring (a shaft, no
        damping) between disc 1 and disc 2 acts about the z-axis: with delta = phi1 - phi2 the twist
        of disc 1 against disc 2 (rotation angles about z from the start), it exerts the torque
        k_s*delta + k_3*delta^3 on disc 2 (and the opposite torque on disc 1), with
        k_s = {shaft_stiffness} N*m/rad and k_3 = {shaft_cubic} N*m/rad^3. Both springs are relaxed
        at the start. A constant torque of
        T = {torque} N*m about the positive z-axis acts on disc 1 from t = 0 on. Gravity is neglected.
        Both discs start at rest.
    """,
    params=(
        Param("mass", 4.0, 8.0, "kg"),
        Param("radius", 0.15, 0.2, "m"),
        Param("width", 0.02, 0.04, "m"),
        Param("mass2", 12.0, 16.0, "kg"),
        Param("radius2", 0.22, 0.25, "m"),
        Param("offset", 0.3, 0.6, "m"),
        Param("stiffness", 400.0, 500.0, "N*m/rad"),
        Param("shaft_stiffness", 120.0, 150.0, "N*m/rad"),
        Param("torque", 5.0, 20.0, "N*m"),
        Param("band_percent", 2.0, 5.0, "%", digits=2),
        Param("hardening", 2.0, 4.0, ""),  # k_3 (T/k)^2 / k_s: the cubic term against the linear at a twist T/k
    ),
    derive=lambda v: {"shaft_cubic": round_significant(
        v["hardening"] * v["shaft_stiffness"] * (v["stiffness"] / v["torque"]) ** 2, 3)},
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    inertia=InertiaCylinder(density=mass / (np.pi * radius**2 * width),
                                                            length=width, outerRadius=radius, axis=2))
        oDisc2 = mbs.CreateRigidBody(referencePosition=[0, 0, offset],
                                     referenceRotationMatrix=np.eye(3),
                                     inertia=InertiaCylinder(density=mass2 / (np.pi * radius2**2 * width),
                                                             length=width, outerRadius=radius2, axis=2))
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc2], position=[0, 0, offset], axis=[0, 0, 1])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1],
                                        stiffness=stiffness, damping=damping)
        def shaft_torque(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
            return stiffness * rotation + shaft_cubic * rotation**3

        mbs.CreateTorsionalSpringDamper(itemNumbers=[oDisc, oDisc2], position=[0, 0, offset], axis=[0, 0, 1],
                                        stiffness=shaft_stiffness, damping=0, springTorqueUserFunction=shaft_torque)
        mbs.CreateTorque(itemNumber=oDisc, loadVector=[0, 0, torque])
    """,
    variables=(DesignVariable("damping", 7.0, 17.0, "N*m*s/rad",
                              "the damping coefficient d of the spring-damper between the world and disc 1"),),
    spec=Spec("the time at which the envelope of disc 2's swing about its final angle T/k decays to b",
              "settling_time", "s", envelope_settling),
    spec_text="""disc 2 settles at its final angle phi_f = T/k in the required time. Let e(t) = |phi2(t) -
        phi_f|, phi2 the rotation angle of disc 2 about z from the start; with the band
        b = {band_percent} % of phi_f, take the
        last local maximum (peak) of e above b, at (t_a, e_a), and the next local maximum of e, at
        (t_b, e_b); the settling time t_a + (t_b - t_a) ln(e_a/b) / ln(e_a/e_b) (where the envelope
        through the peaks, interpolated linearly in log e, falls to b) must be {target} s, within
        ±{tolerance_percent} %.""",
    estimate=estimate,
    estimate_text="disc 1 massless, the shaft linearised (k_s): disc 2 on k and k_s in series, damped through the shaft by "
                  "c_e = d (k_s/(k + k_s))^2; the 1-DOF envelope (T/k) exp(-c_e t / (2 J2)) reaching b",
    sim=SimSettings(end_time=10.0, steps=10000),
)
