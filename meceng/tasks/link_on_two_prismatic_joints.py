"""Task 22 (level 1): link on two prismatic joints — an elliptic trammel: two sliders (mass points)
on perpendicular guides joined by a massless rigid link, with a spring on the horizontal slider.

Slider 1 moves only along the x-axis and slider 2 only along the z-axis (each held by a spherical
joint that constrains the two other translations, as in the paper's model); the link is a distance
constraint. 6 coordinates, 2 + 2 + 1 independent constraints: one degree of freedom and no redundant
constraints; (x1, z2) moves on a circle, which has no kinematic singularity. Gravity along -z pulls
slider 2 down and slider 1 outwards against a spring to the ground point at the origin. The spring
is stiff enough (0.5*k*x0^2 > 2*m2*g*(z0 + L) for all draws) that slider 1 never reaches the origin,
where the spring would have zero length. One degree of freedom: regular motion.

Physics checks: the trajectory agrees with an independent RK4 integration of the one-degree-of-
freedom equation of motion in the link angle; the link length and the guides are kept.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=22,
    name="link on two prismatic joints",
    level="1",
    description="""
        A massless rigid link whose two ends slide on two perpendicular guides, modeled with two mass
        points. Slider 1 is a mass point with mass m1 = {mass1} kg, initially located at
        [{x0}, 0, 0]; it can move only along the x-axis: a spherical joint between ground and
        slider 1 at [{x0}, 0, 0] constrains its y- and z-translations (constrainedAxes = [0, 1, 1]).
        Slider 2 is a mass point with mass m2 = {mass2} kg, initially located at [0, 0, {z0}]; it
        can move only along the z-axis: a spherical joint between ground and slider 2 at
        [0, 0, {z0}] constrains its x- and y-translations (constrainedAxes = [1, 1, 0]). The link is
        a distance constraint between slider 1 and slider 2 whose length is the initial distance of
        the two sliders, L = sqrt({x0}^2 + {z0}^2) m. A spring-damper with stiffness
        k = {stiffness} N/m and damping d = {damping} N*s/m connects the ground point [0, 0, 0] with
        slider 1; it is relaxed in the initial configuration (reference length {x0} m). Both
        sliders start from rest at the given positions (their reference positions). Gravity
        g = {gravity} m/s^2 acts in the negative z-direction on both mass points. Create the ground,
        slider 1, slider 2, the spherical joint of slider 1, that of slider 2, the distance
        constraint and then the spring-damper.
    """,
    open_description="""
        An elliptic trammel: a massless rigid link whose two ends are point-mass sliders on two
        perpendicular straight guides, without friction. Slider 1, a point mass of m1 = {mass1}
        kg, starts at [{x0}, 0, 0] and can move only along the global x-axis (its y- and
        z-coordinates stay zero). Slider 2, a point mass of m2 = {mass2} kg, starts at [0, 0,
        {z0}] and can move only along the global z-axis (its x- and y-coordinates stay zero). The
        link is pinned without friction to both sliders and keeps their distance at its starting
        value L = sqrt({x0}^2 + {z0}^2) m. A massless linear spring-damper with stiffness k =
        {stiffness} N/m and damping coefficient d = {damping} N*s/m joins the fixed point at the
        origin [0, 0, 0] to slider 1; it acts along the line between its ends (force k times its
        stretch plus d times the rate of change of its length) and is unstretched at the start
        (unstretched length {x0} m). Both sliders start at rest. Gravity g = {gravity} m/s^2 acts
        in the negative z-direction on both sliders.
    """,
    params=(
        Param("mass1", 1.0, 5.0, "kg"),
        Param("mass2", 0.5, 2.0, "kg"),
        Param("x0", 0.8, 1.2, "m"),
        Param("z0", 0.3, 0.8, "m"),
        Param("stiffness", 300.0, 1200.0, "N/m"),
        Param("damping", 0.0, 5.0, "N*s/m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "MassPoint", "SphericalJoint", "DistanceConstraint", "SpringDamper"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oSlider1 = mbs.CreateMassPoint(referencePosition=[x0, 0, 0], mass=mass1, gravity=[0, 0, -gravity])
        oSlider2 = mbs.CreateMassPoint(referencePosition=[0, 0, z0], mass=mass2, gravity=[0, 0, -gravity])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oSlider1], position=[x0, 0, 0], constrainedAxes=[0, 1, 1])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oSlider2], position=[0, 0, z0], constrainedAxes=[1, 1, 0])
        mbs.CreateDistanceConstraint(itemNumbers=[oSlider1, oSlider2])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oSlider1], stiffness=stiffness, damping=damping)
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
