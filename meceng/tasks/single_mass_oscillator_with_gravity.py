"""Task 4 (level 1): single mass oscillator with gravity — a mass point hanging from ground on a
vertical spring-damper.

Physics checks: with d = 0 the mass oscillates harmonically about the static equilibrium, which
lies m*g/k below the reference position, with period 2*pi*sqrt(m/k); energy is conserved.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=4,
    name="single mass oscillator with gravity",
    level="1",
    description="""
        A vertical single mass oscillator consisting of a mass point with mass m = {mass} kg that
        hangs from ground by a linear spring-damper with stiffness k = {stiffness} N/m and damping
        coefficient d = {damping} N*s/m. The spring-damper is attached to ground at [0, 0, 0] and
        to the mass point. The mass point's reference position is p_ref = [0, -{length}, 0] m,
        directly below the ground point, so the spring's relaxed length is L = {length} m.
        Gravity g = {gravity} m/s^2 acts in the negative y-direction. The mass point starts with
        an initial displacement of [0, {displacement}, 0] m from its reference position (i.e. it
        is lifted by {displacement} m) and with zero velocity.
    """,
    open_description="""
        A vertical single mass oscillator: a point mass m = {mass} kg (no rotational inertia) hangs
        below a fixed point at the origin [0, 0, 0] on a linear spring-damper that acts along the
        line between the fixed point and the mass, with stiffness k = {stiffness} N/m, damping
        coefficient d = {damping} N*s/m (force proportional to the rate of change of its length) and
        unstretched length L = {length} m. With the spring unstretched the mass would sit directly
        below the fixed point at [0, -{length}, 0] m. Gravity g = {gravity} m/s^2 acts in the
        negative y-direction. At the start the mass is at rest, lifted {displacement} m straight up
        (in the positive y-direction) from that point, so the spring is compressed by
        {displacement} m.
    """,
    params=(
        Param("mass", 0.5, 5.0, "kg"),
        Param("stiffness", 200.0, 2000.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
        Param("length", 0.5, 2.0, "m"),
        Param("displacement", 0.02, 0.2, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[0, -length, 0],
                                    initialDisplacement=[0, displacement, 0],
                                    mass=mass, gravity=[0, -gravity, 0])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
