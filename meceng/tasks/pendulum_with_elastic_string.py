"""Task 6 (level 1): pendulum with elastic string — a mass point on a spring-damper to ground (an
elastic pendulum) in the x-y plane under gravity, released from a deflected, relaxed position with an
initial velocity.

An elastic pendulum is chaotic when the spring frequency is close to twice the pendulum frequency
(autoparametric resonance). The string is stiff here: sqrt(k/m) >= sqrt(500) = 22 rad/s against a
pendulum frequency sqrt(g/L) <= 4.5 rad/s, a ratio of at least 5, so the motion stays regular over
the simulated 2 s and a re-ordered but correct model stays within the 1e-5 solution tolerance. The
static stretch m*g/k is below 4 % of the length, the largest stretch during the swing below 20 %.

Physics checks: mechanical energy (kinetic + gravity + spring) minus the work dissipated by the
damper, d * integral of (dL/dt)^2, stays equal to the initial energy; the start state is p0 and v0;
the motion stays in the x-y plane.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=6,
    name="pendulum with elastic string",
    level="1",
    description="""
        A pendulum with an elastic string moving in the x-y plane: a mass point with mass
        m = {mass} kg hangs from a fixed support (ground) at [0, 0, 0] on an elastic string that is
        modeled as a linear spring-damper between ground and the mass point with stiffness
        k = {stiffness} N/m and damping coefficient d = {damping} N*s/m. The string's relaxed
        length is L = {length} m. The mass point's reference position is
        p0 = [L*sin(phi0), -L*cos(phi0), 0] with phi0 = {angle_deg} degrees (converted to radians),
        i.e. the string is deflected by phi0 from the downward vertical towards positive x and is
        relaxed in this reference configuration, which is also the initial position. The mass
        point starts with the initial velocity v0 = [{vx}, {vy}, 0] m/s. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction. Create the ground, the mass point and
        then the spring-damper.
    """,
    open_description="""
        An elastic pendulum in the x-y plane: a point mass m = {mass} kg (no rotational inertia)
        hangs from a fixed support at the origin [0, 0, 0] on an elastic string, idealised as a
        massless linear spring-damper acting along the line from the support to the mass (it pulls
        when stretched and also pushes when compressed), with stiffness k = {stiffness} N/m, damping
        coefficient d = {damping} N*s/m (force proportional to the rate of change of its length) and
        unstretched length L = {length} m. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction. At the start the string is unstretched and turned {angle_deg} degrees from
        hanging straight down towards positive x, so the mass is at [L*sin(phi0), -L*cos(phi0), 0]
        with phi0 = {angle_deg} degrees, and the mass moves with the velocity [{vx}, {vy}, 0] m/s.
    """,
    params=(
        Param("mass", 0.5, 2.0, "kg"),
        Param("length", 0.5, 1.5, "m"),
        Param("stiffness", 1000.0, 3000.0, "N/m"),
        Param("damping", 0.0, 2.0, "N*s/m"),
        Param("angle_deg", 10.0, 60.0, "deg", digits=2),
        Param("vx", -1.0, 1.0, "m/s"),
        Param("vy", -1.0, 1.0, "m/s"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        phi0 = angle_deg * np.pi / 180
        p0 = [length * np.sin(phi0), -length * np.cos(phi0), 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=p0, initialVelocity=[vx, vy, 0],
                                    mass=mass, gravity=[0, -gravity, 0])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
