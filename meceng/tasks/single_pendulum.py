"""Task 11 (level 1): single pendulum — a mass point on a massless rigid rod (distance constraint).

Physics checks: small-angle period 2*pi*sqrt(L/g); total energy conserved (no damping).
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=11,
    name="single pendulum",
    level="1",
    description="""
        A single pendulum consisting of a mass point with mass m = {mass} kg that hangs from a fixed
        support (ground) at [0, 0, 0] on a massless rigid rod of length L = {length} m, modeled as a
        distance constraint between ground and the mass point. The pendulum moves in the x-y plane.
        Initially the rod is deflected by phi0 = {angle_deg} degrees from the downward vertical
        towards positive x, i.e. the mass point is at
        p0 = [L*sin(phi0), -L*cos(phi0), 0] and starts from rest. Gravity g = {gravity} m/s^2 acts
        in the negative y-direction. Define the mass point's reference position as p0.
    """,
    open_description="""
        A simple pendulum: a point mass m = {mass} kg (no rotational inertia) on a massless rigid
        rod of length L = {length} m, whose other end is pinned to a fixed support at the origin
        [0, 0, 0] without friction; the rod only keeps the distance between support and mass equal
        to L. Gravity g = {gravity} m/s^2 acts in the negative y-direction. At the start the mass is
        at rest with the rod turned phi0 = {angle_deg} degrees from hanging straight down towards
        positive x, i.e. at [L*sin(phi0), -L*cos(phi0), 0], so the pendulum swings in the x-y plane.
    """,
    params=(
        Param("mass", 0.2, 3.0, "kg"),
        Param("length", 0.3, 2.0, "m"),
        Param("angle_deg", 5.0, 60.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        p0 = [length * np.sin(phi0), -length * np.cos(phi0), 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=p0, mass=mass, gravity=[0, -gravity, 0])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], distance=length)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
