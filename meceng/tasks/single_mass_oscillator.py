"""Task 3 (level 1): single mass oscillator — a mass point on a spring-damper to ground.

Physics check: with d = 0 the mass oscillates harmonically with period 2*pi*sqrt(m/k).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=3,
    name="single mass oscillator",
    level="1",
    description="""
        A single mass oscillator consisting of a mass point with mass m = {mass} kg that is connected
        to ground by a linear spring-damper with stiffness k = {stiffness} N/m and damping
        coefficient d = {damping} N*s/m. The spring-damper is attached to ground at [0, 0, 0] and to
        the mass point. The mass point's reference position is p_ref = [{length}, 0, 0] m, so the
        spring's relaxed length is L = {length} m. The mass point starts with an initial
        displacement of [{displacement}, 0, 0] m from its reference position and with zero
        velocity. Gravity is neglected.
    """,
    open_description="""
        A single mass oscillator without gravity: a point mass m = {mass} kg (no rotational inertia)
        is tied to a fixed point at the origin [0, 0, 0] by a linear spring-damper that acts along
        the line between the fixed point and the mass, with stiffness k = {stiffness} N/m, damping
        coefficient d = {damping} N*s/m (force proportional to the rate of change of its length) and
        unstretched length L = {length} m. With the spring unstretched the mass would sit at
        [{length}, 0, 0] m. At the start the mass is at rest, pulled {displacement} m further along
        the positive x-direction from that point, so the spring is stretched by {displacement} m.
        Gravity is neglected.
    """,
    params=(
        Param("mass", 0.5, 5.0, "kg"),
        Param("stiffness", 100.0, 2000.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
        Param("length", 0.5, 2.0, "m"),
        Param("displacement", 0.02, 0.2, "m"),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[length, 0, 0],
                                    initialDisplacement=[displacement, 0, 0],
                                    mass=mass)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
