"""Task 1 (level 1): flying mass point — a projectile: a mass point thrown with an initial velocity.

Physics check: x(t) = vx*t, y(t) = vy*t, z(t) = z0 + vz*t - g*t^2/2 (constant acceleration, so the
integrator reproduces it to round-off).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=1,
    name="flying mass point",
    level="1",
    description="""
        A flying mass point (projectile) with mass m = {mass} kg. The mass point's reference
        position, which is also its initial position, is p0 = [0, 0, {height}] m. It starts with
        the initial velocity v0 = [{vx}, {vy}, {vz}] m/s. Gravity g = {gravity} m/s^2 acts in the
        negative z-direction. No other forces act on the mass point; there is no ground, air
        resistance or contact.
    """,
    open_description="""
        A projectile: a point mass m = {mass} kg (no rotational inertia) flies freely under gravity
        g = {gravity} m/s^2, which acts in the negative z-direction. At the start it is at the
        position [0, 0, {height}] m and moves with the velocity [{vx}, {vy}, {vz}] m/s. No other
        force acts on it: there is no ground, no air resistance and no contact.
    """,
    params=(
        Param("mass", 0.5, 5.0, "kg"),
        Param("height", 0.0, 5.0, "m"),
        Param("vx", 1.0, 10.0, "m/s"),
        Param("vy", -3.0, 3.0, "m/s"),
        Param("vz", 2.0, 12.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("MassPoint",),
    model_code="""
        oMass = mbs.CreateMassPoint(referencePosition=[0, 0, height],
                                    initialVelocity=[vx, vy, vz],
                                    mass=mass, gravity=[0, 0, -gravity])
    """,
    sim=SimSettings(end_time=2.0, steps=1000),
)
