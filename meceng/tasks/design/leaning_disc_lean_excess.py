"""Task 407 (level 4): the rolling speed at which a disc started with a lean leans over by a given
angle more.

The system is task 32's disc rolling without slipping on the ground (ideal rolling, a rigid
cylinder), here started leaning sideways at the angle theta0 (15-30 degrees) with no turning rate,
rolling at the speed v (its spin consistent with rolling); v is left open. The spec is an extreme:
how far the disc leans over beyond theta0 at the first peak of its lean.

Why a closed form misses: without the turning rate of a steady lean, the disc falls further over
until the gyroscopic moment of its spin, coupled through the rolling constraint, catches it; it
then nutates. At these leans and speeds the motion is far from the linearised one about upright
rolling (the lean is large, the spin's gyroscopic moment and gravity's moment go with cos and sin
of it, and the turning rate the fall builds up changes the equilibrium lean).

Estimate: the lean equation linearised about upright rolling at the spin Omega = v/r, with the
turning rate psi' = (I_a Omega/I_d)(theta - theta0) the fall builds up from zero:
(I_d + m r^2) theta'' = m g r theta - (I_a + m r^2)(I_a/I_d) Omega^2 (theta - theta0), so the lean
swings about theta_eq between theta0 and 2 theta_eq - theta0: the excess
2 theta0 m g r / ((I_a + m r^2)(I_a/I_d) Omega^2 - m g r), solved for v (I_a = m r^2/2,
I_d = m (r^2/4 + w^2/12)).
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import local_maxima
from meceng.tasks.disc_rolling_on_ground import TASK as ROLLING_DISC


def lean_excess(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    e0, e1, e2, e3 = q[:, 3], q[:, 4], q[:, 5], q[:, 6]  # the disc's Euler parameters
    axle_z = 2.0 * (e1 * e3 - e0 * e2)  # the body x-axis (the axle) in ground, z-component
    lean = np.degrees(np.arcsin(np.clip(-axle_z, -1.0, 1.0)))
    peaks = local_maxima(lean)
    return float(lean[peaks[0]] - values["lean_deg"]) if peaks.size else float("nan")


def estimate(values: dict, target: float) -> dict[str, float]:
    r, w, g = values["radius"], values["width"], values["gravity"]
    axial, diametral = r**2 / 2.0, r**2 / 4.0 + w**2 / 12.0  # per unit mass
    spin_squared = g * r * (1.0 + 2.0 * values["lean_deg"] / target) / ((axial + r**2) * axial / diametral)
    return {"velocity": r * float(np.sqrt(spin_squared))}


TASK = DesignModel(
    id=407,
    name="leaning disc lean excess",
    system=ROLLING_DISC,
    open_description="""
        A homogeneous disc (a short solid cylinder) of density {density} kg/m^3, radius r = {radius} m
        and thickness {width} m rolls on the flat horizontal ground z = 0. The disc rolls without
        slipping: its contact point with the ground has no velocity in any direction (neither
        sliding along nor sideways), and it stays in contact with the ground (it never lifts off).
        At the start the contact point is at the origin, the disc's symmetry axis (axle) lies in
        the x-z plane and the disc leans towards +x by theta0 = {lean_deg} degrees from upright:
        its axle direction is a = [cos(theta0), 0, -sin(theta0)] and its centre is at
        [r*sin(theta0), 0, r*cos(theta0)]. The disc rolls in the +y direction with the speed v: its
        centre's velocity is [0, v, 0] and its angular velocity is -(v/r)*a (a spin about the axle
        only, consistent with rolling without slipping; no turning rate about the vertical).
        Gravity g = {gravity} m/s^2 acts in the negative z-direction; there is no rolling
        resistance and no other force.
    """,
    params=(
        Param("density", 1000.0, 8000.0, "kg/m^3"),
        Param("radius", 0.1, 0.3, "m"),
        Param("width", 0.01, 0.05, "m"),
        Param("lean_deg", 15.0, 30.0, "deg", digits=3),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(DesignVariable("velocity", 2.0, 4.0, "m/s", "the initial rolling speed v"),),
    spec=Spec("how far the disc leans over beyond its start lean at the first peak of its lean", "extreme",
              "deg", lean_excess),
    spec_text="""the disc leans further over after the start; at the first peak of its lean (the angle
        between its plane and the vertical) it leans {target} degrees more than the start lean
        theta0, within ±{tolerance_percent} % (of that excess).""",
    estimate=estimate,
    estimate_text="the lean linearised about upright rolling, the turning rate built up from zero: the "
                  "excess 2 theta0 m g r / ((I_a + m r^2)(I_a/I_d) (v/r)^2 - m g r)",
    model_code="""
        lean = lean_deg * np.pi / 180
        axis = np.array([np.cos(lean), 0, -np.sin(lean)])
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[radius * np.sin(lean), 0, radius * np.cos(lean)],
                                    referenceRotationMatrix=RotationMatrixY(lean),
                                    initialVelocity=[0, velocity, 0],
                                    initialAngularVelocity=-velocity / radius * axis,
                                    inertia=InertiaCylinder(density=density, length=width,
                                                            outerRadius=radius, axis=0),
                                    gravity=[0, 0, -gravity])
        mbs.CreateRollingDisc(bodyNumbers=[oGround, oDisc], axisPosition=[0, 0, 0], axisVector=[1, 0, 0],
                              discRadius=radius, planePosition=[0, 0, 0], planeNormal=[0, 0, 1])
    """,
    sim=SimSettings(end_time=2.0, steps=4000),
)
