"""Task 17 (level 1): double pendulum elastic spring — two mass points on two elastic strings
(spring-dampers) in the x-y plane under gravity, released from rest with relaxed springs.

Like the rigid double pendulum this system is chaotic at large amplitudes; the initial angles are
limited to 30 degrees and the springs are stiff (sqrt(k/m) >= 18 rad/s, several times the pendulum
frequencies), so the motion is regular over the simulated 2 s and a re-ordered but correct model
stays within the 1e-5 solution tolerance (checked also at the corners of the parameter ranges).

Physics checks: mechanical energy (kinetic + gravity + both springs) minus the work dissipated by
both dampers stays equal to the initial energy; the start state; planar motion.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=17,
    name="double pendulum elastic spring",
    level="1",
    description="""
        A double pendulum with elastic springs moving in the x-y plane, consisting of two mass
        points. Mass point 1 with mass m1 = {mass1} kg hangs from a fixed support (ground) at
        [0, 0, 0] on spring-damper 1 (between ground and mass point 1) with stiffness
        k1 = {stiffness1} N/m; mass point 2 with mass m2 = {mass2} kg hangs from mass point 1 on
        spring-damper 2 (between mass point 1 and mass point 2) with stiffness k2 = {stiffness2} N/m.
        Both spring-dampers have the damping coefficient d = {damping} N*s/m. The relaxed lengths
        of the springs are L1 = {length1} m and L2 = {length2} m. Initially spring 1 is deflected
        by phi1 = {angle1_deg} degrees and spring 2 by phi2 = {angle2_deg} degrees from the
        downward vertical (both angles absolute, measured from the vertical; a positive angle
        deflects towards positive x), i.e. the mass points are at
        p1 = [L1*sin(phi1), -L1*cos(phi1), 0] and p2 = p1 + [L2*sin(phi2), -L2*cos(phi2), 0];
        define the mass points' reference positions as p1 and p2, so both springs are relaxed in
        the reference configuration. Both mass points start from rest. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on both mass points. Create the
        ground, mass point 1, mass point 2, then spring-damper 1 and then spring-damper 2.
    """,
    open_description="""
        A double pendulum with elastic strings in the x-y plane, made of two point masses. Point
        mass 1, of mass m1 = {mass1} kg, hangs from a fixed pivot at the origin [0, 0, 0] on
        massless linear spring-damper 1 with stiffness k1 = {stiffness1} N/m and unstretched
        length L1 = {length1} m; point mass 2, of mass m2 = {mass2} kg, hangs from point mass 1 on
        massless linear spring-damper 2 with stiffness k2 = {stiffness2} N/m and unstretched
        length L2 = {length2} m. Both spring-dampers have the damping coefficient d = {damping}
        N*s/m; each pulls or pushes along the line between its two ends with the force k times its
        stretch plus d times the rate of change of its length. Gravity g = {gravity} m/s^2 acts in
        the negative y-direction on both point masses. At the start both point masses are at rest
        and both springs are unstretched; spring 1 is turned phi1 = {angle1_deg} degrees and
        spring 2 phi2 = {angle2_deg} degrees from the downward vertical, both angles absolute
        (measured from the vertical, not from the other spring) and positive towards positive x:
        point mass 1 is at p1 = [L1*sin(phi1), -L1*cos(phi1), 0] and point mass 2 at p2 = p1 +
        [L2*sin(phi2), -L2*cos(phi2), 0].
    """,
    params=(
        Param("mass1", 0.5, 3.0, "kg"),
        Param("mass2", 0.5, 3.0, "kg"),
        Param("length1", 0.3, 1.0, "m"),
        Param("length2", 0.3, 1.0, "m"),
        Param("stiffness1", 2000.0, 8000.0, "N/m"),
        Param("stiffness2", 1000.0, 5000.0, "N/m"),
        Param("damping", 0.0, 2.0, "N*s/m"),
        Param("angle1_deg", 5.0, 30.0, "deg", digits=2),
        Param("angle2_deg", -30.0, 30.0, "deg", digits=2),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SpringDamper"),
    model_code="""
        phi1 = angle1_deg * np.pi / 180
        phi2 = angle2_deg * np.pi / 180
        p1 = [length1 * np.sin(phi1), -length1 * np.cos(phi1), 0]
        p2 = [p1[0] + length2 * np.sin(phi2), p1[1] - length2 * np.cos(phi2), 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass1 = mbs.CreateMassPoint(referencePosition=p1, mass=mass1, gravity=[0, -gravity, 0])
        oMass2 = mbs.CreateMassPoint(referencePosition=p2, mass=mass2, gravity=[0, -gravity, 0])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass1], stiffness=stiffness1, damping=damping)
        mbs.CreateSpringDamper(itemNumbers=[oMass1, oMass2], stiffness=stiffness2, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
