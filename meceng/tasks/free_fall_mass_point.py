"""Task 2 (level 1): free fall mass point — a mass point dropped from rest under gravity.

Physics check: x and y stay constant and z(t) = z0 - g*t^2/2 (constant acceleration, so the
integrator reproduces it to round-off).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=2,
    name="free fall mass point",
    level="1",
    description="""
        Free fall of a mass point with mass m = {mass} kg. The mass point's reference position,
        which is also its initial position, is p0 = [{x0}, {y0}, {height}] m, i.e. it is dropped
        from the height z0 = {height} m. It starts from rest (zero initial velocity). Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. No other forces act on the mass
        point; there is no ground, air resistance or contact.
    """,
    open_description="""
        Free fall: a point mass m = {mass} kg (no rotational inertia) is released from rest at the
        position [{x0}, {y0}, {height}] m, i.e. at the height {height} m. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. No other force acts on it: there is no
        ground, no air resistance and no contact.
    """,
    params=(
        Param("mass", 0.2, 5.0, "kg"),
        Param("x0", -1.0, 1.0, "m"),
        Param("y0", -1.0, 1.0, "m"),
        Param("height", 5.0, 20.0, "m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("MassPoint",),
    model_code="""
        oMass = mbs.CreateMassPoint(referencePosition=[x0, y0, height],
                                    mass=mass, gravity=[0, 0, -gravity])
    """,
    sim=SimSettings(end_time=1.0, steps=1000),
)
