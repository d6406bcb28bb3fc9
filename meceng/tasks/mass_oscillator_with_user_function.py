"""Task 7 (level 1): mass oscillator with user function — a mass point on a spring-damper to ground,
excited by the harmonic force F0*sin(omega*t) given as a load user function.

The user function is not part of the system graph, so only the solution check catches a wrong
one. The ranges keep the response small against the spring length (at most about 0.13 m of at least
0.5 m, also at resonance, because d*omega_n >= 79 N/m), so the spring never flips and the motion is
exactly linear; the excitation frequency range 5..50 rad/s covers the natural frequencies
sqrt(k/m) = 16..63 rad/s, including near-resonant instances.

Physics check: the displacement equals the closed-form response of m*x'' + d*x' + k*x = F0*sin(omega*t)
from rest (steady state plus the damped transient); the motion stays on the x-axis.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=7,
    name="mass oscillator with user function",
    level="1",
    description="""
        A single mass oscillator with a time-dependent excitation force: a mass point with mass
        m = {mass} kg is connected to ground by a linear spring-damper with stiffness
        k = {stiffness} N/m and damping coefficient d = {damping} N*s/m. The spring-damper is
        attached to ground at [0, 0, 0] and to the mass point. The mass point's reference position
        is p_ref = [{length}, 0, 0] m, so the spring's relaxed length is L = {length} m; the mass
        point starts at its reference position with zero velocity. A harmonic force
        f(t) = [F0*sin(omega*t), 0, 0] N with amplitude F0 = {force_amplitude} N and angular
        frequency omega = {omega} rad/s (t the simulation time in s) acts on the mass point; model
        it with mbs.CreateForce with loadVector=[F0, 0, 0] and a loadVectorUserFunction that
        returns [F0*sin(omega*t), 0, 0]. Gravity is neglected. Create the ground, the mass point,
        the spring-damper and then the force.
    """,
    open_description="""
        A harmonically excited mass oscillator without gravity: a point mass m = {mass} kg (no
        rotational inertia) is tied to a fixed point at the origin [0, 0, 0] by a linear
        spring-damper that acts along the line between the fixed point and the mass, with stiffness
        k = {stiffness} N/m, damping coefficient d = {damping} N*s/m (force proportional to the rate
        of change of its length) and unstretched length L = {length} m. At the start the mass is at
        rest at [{length}, 0, 0] m, where the spring is unstretched. From the start on, a force
        along the x-axis with the value F(t) = F0*sin(omega*t) N acts on the mass, with amplitude
        F0 = {force_amplitude} N, angular frequency omega = {omega} rad/s and t the time in s since
        the start (positive values push in the positive x-direction). Gravity is neglected.
    """,
    params=(
        Param("mass", 0.5, 2.0, "kg"),
        Param("stiffness", 500.0, 2000.0, "N/m"),
        Param("damping", 5.0, 20.0, "N*s/m"),
        Param("length", 0.5, 1.0, "m"),
        Param("force_amplitude", 1.0, 5.0, "N"),
        Param("omega", 5.0, 50.0, "rad/s"),
    ),
    components=("Ground", "MassPoint", "SpringDamper", "Force", "LoadUserFunction"),
    model_code="""
        def UFforce(mbs, t, loadVector):
            return [force_amplitude * np.sin(omega * t), 0, 0]

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[length, 0, 0], mass=mass)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=stiffness, damping=damping)
        mbs.CreateForce(itemNumber=oMass, loadVector=[force_amplitude, 0, 0], loadVectorUserFunction=UFforce)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
