"""Task 418 (level 4): the PD gains of a pivot motor that bring an inverted pendulum on a free cart
from a large tilt to near upright at a given time.

The system is task 16's inverted pendulum on a cart (two point masses, a massless rod, the cart
free along x, the bob heavier than the cart), released at rest with the rod tilted by a large angle theta0 = 55..75 degrees. A
motor at the pivot applies the torque tau = -kP*theta - kD*theta' on the rod (on the bob, with
its reaction on the cart); both gains are open. The spec is an event's time: when the rod's
angle from the upward vertical first falls to 2 degrees (underdamped gains overshoot later, but
this first entry is continuous in the gains, a settling time is not). The cart recoils as the bob
swings (the inertia the motor sees changes with cos(theta)^2), gravity's torque is m g L
sin(theta), not m g L theta, and the motion is a damped oscillation of two degrees of freedom.

Estimate: the linearised pendulum on a free cart, J theta'' + kD theta' + (kP - m g L) theta = 0
with J = m L^2 M / (M + m), kD in the middle of its range and kP such that this linear response
from theta0 first falls to 2 degrees at the target time.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.base import Param, SimSettings
from meceng.tasks.design_base import DesignModel, DesignVariable, Spec
from meceng.tasks.design_measures import first_crossing
from meceng.tasks.inverted_single_pendulum import TASK as PENDULUM

BAND_DEG = 2.0
KD_RANGE = (0.2, 1.2)


def rod_upright_time(times: np.ndarray, q: np.ndarray, values: dict) -> float:
    # cart columns 0..2, bob 3..5; the angle from the upward vertical, positive towards +x
    theta = np.degrees(np.arctan2(q[:, 3] - q[:, 0], q[:, 4] - q[:, 1]))
    return first_crossing(times, np.abs(theta), BAND_DEG, rising=False)


def _linear_entry_time(inertia: float, stiffness: float, kd: float, theta0: float) -> float:
    """The first time the linear response theta0 (r2 e^(r1 t) - r1 e^(r2 t)) / (r2 - r1) falls to the band."""
    disc = complex(kd**2 - 4 * inertia * stiffness) + 1e-12j
    r1, r2 = (-kd + np.sqrt(disc)) / (2 * inertia), (-kd - np.sqrt(disc)) / (2 * inertia)
    t = np.linspace(0.0, 5.0, 50001)
    theta = np.real(theta0 * (r2 * np.exp(r1 * t) - r1 * np.exp(r2 * t)) / (r2 - r1))
    inside = np.nonzero(np.abs(theta) <= BAND_DEG)[0]
    return float(t[inside[0]]) if inside.size else float("inf")


def estimate(values: dict, target: float) -> dict[str, float]:
    m, big_m, length, g = values["pendulum_mass"], values["cart_mass"], values["length"], values["gravity"]
    inertia = m * length**2 * big_m / (big_m + m)
    kd = 0.5 * (KD_RANGE[0] + KD_RANGE[1])  # kD in the middle of its range, kP from the linear model
    lo, hi = m * g * length + 1e-3, 100.0
    for _ in range(60):  # the entry time falls as kP grows
        kp = 0.5 * (lo + hi)
        if _linear_entry_time(inertia, kp - m * g * length, kd, values["angle_deg"]) > target:
            lo = kp
        else:
            hi = kp
    return {"kp": 0.5 * (lo + hi), "kd": kd}


MODEL_CODE = """
    theta0 = angle_deg * np.pi / 180
    oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
    oCart = mbs.CreateMassPoint(referencePosition=[0, 0, 0], mass=cart_mass, gravity=[0, -gravity, 0])
    oPendulum = mbs.CreateMassPoint(referencePosition=[length * np.sin(theta0), length * np.cos(theta0), 0],
                                    mass=pendulum_mass, gravity=[0, -gravity, 0])
    mbs.CreateSphericalJoint(itemNumbers=[oGround, oCart], position=[0, 0, 0], constrainedAxes=[0, 1, 1])
    mbs.CreateDistanceConstraint(itemNumbers=[oCart, oPendulum], distance=length)

    def MotorForce(t):
        p = mbs.GetObjectOutputBody(oPendulum, exu.OutputVariableType.Position) - \\
            mbs.GetObjectOutputBody(oCart, exu.OutputVariableType.Position)
        v = mbs.GetObjectOutputBody(oPendulum, exu.OutputVariableType.Velocity) - \\
            mbs.GetObjectOutputBody(oCart, exu.OutputVariableType.Velocity)
        theta = np.arctan2(p[0], p[1])
        omega = (p[1] * v[0] - p[0] * v[1]) / (p[0]**2 + p[1]**2)
        tau = -kp * theta - kd * omega
        return tau / length * np.array([np.cos(theta), -np.sin(theta), 0])

    def UFbob(mbs, t, loadVector):
        return list(MotorForce(t))

    def UFcart(mbs, t, loadVector):
        return list(-MotorForce(t))

    mbs.CreateForce(itemNumber=oPendulum, loadVector=[0, 0, 0], loadVectorUserFunction=UFbob)
    mbs.CreateForce(itemNumber=oCart, loadVector=[0, 0, 0], loadVectorUserFunction=UFcart)
"""

TASK = DesignModel(
    id=418,
    name="inverted pendulum pd upright time",
    system=PENDULUM,
    open_description="""
        An inverted pendulum on a cart, both idealised as point masses. The cart, a point mass of
        m1 = {cart_mass} kg, starts at the origin [0, 0, 0] and slides without friction along the
        global x-axis only: its y- and z-coordinates stay zero. The pendulum bob, a point mass of
        m2 = {pendulum_mass} kg, is joined to the cart by a massless rigid rod of length
        L = {length} m, pinned at the cart (the rod only keeps the distance between cart and bob at
        L). The rod's angle theta is measured from the upward vertical (+y), positive when the bob
        is on the +x side of the cart. At the start both are at rest, with the rod tilted by
        theta0 = {angle_deg} degrees: the bob is at [L*sin(theta0), L*cos(theta0), 0]. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on both point masses. A motor in the
        pin at the cart drives the rod with the PD torque tau = -kP*theta - kD*theta' (theta in
        radians, theta' its rate), positive in the sense of increasing theta; its reaction acts on
        the cart. As the rod is massless, the motor's torque reaches the bob as the force tau/L
        perpendicular to the rod, tau/L*[cos(theta), -sin(theta), 0], and the cart feels the
        opposite force. There is no other load and no friction.
    """,
    params=(
        Param("cart_mass", 0.3, 0.6, "kg"),
        Param("pendulum_mass", 0.4, 0.8, "kg"),
        Param("length", 0.4, 0.6, "m"),
        Param("angle_deg", 55.0, 75.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    variables=(
        DesignVariable("kp", 6.0, 14.0, "N*m/rad", "the proportional gain kP of the motor torque"),
        DesignVariable("kd", *KD_RANGE, "N*m*s/rad", "the derivative gain kD of the motor torque"),
    ),
    spec=Spec(f"the time the rod first comes within ±{BAND_DEG:g} degrees of upright", "event_time", "s",
              rod_upright_time),
    spec_text=f"""the rod's angle from the upward vertical first comes within ±{BAND_DEG:g} degrees (its
        magnitude first falls to {BAND_DEG:g} degrees) at t = {{target}} s, within ±{{tolerance_percent}} %.""",
    estimate=estimate,
    estimate_text="the linearised pendulum on a free cart, J = m L^2 M / (M + m), kD mid-range, kP such that "
                  "the linear response first falls to 2 degrees at the target time",
    model_code=MODEL_CODE,
    sim=SimSettings(end_time=1.5, steps=1000),
)
