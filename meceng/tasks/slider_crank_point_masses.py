"""Task 5 (level 1): slider crank / point masses — crank pin and slider are mass points, crank and
connecting rod are massless rigid links (distance constraints), the slider is pushed by a force.

Six coordinates; two distance constraints and three coordinate constraints (crank mass z, slider
y and z) leave exactly one degree of freedom with no redundant constraint. Unlike a rigid-body
slider-crank there is no singular dead centre: at theta = 0 the crank mass can still move in y.
The constant force pushes the slider away from the crank, so the crank swings like a nonlinear
pendulum between theta0 and -theta0 (potential -F*x_slider, minimum at theta = 0). The rod is always
at least 1.6 times longer than the crank and theta0 stays below 150 degrees, so the motion is
regular and a re-ordered model stays far inside the 1e-5 solution tolerance.

Physics checks: the crank angle follows the reduced one-degree-of-freedom equation of motion
d/dt(M(theta)*theta') - M'(theta)*theta'^2/2 = F*x_C'(theta), M = m1*r^2 + m2*x_C'(theta)^2
(integrated independently with RK4); kinetic energy equals the work of the force; all constraints
hold.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=5,
    name="slider crank / point masses",
    level="1",
    description="""
        A slider-crank mechanism moving in the x-y plane, modeled with two mass points: the crank
        mass (mass point 1, at the crank pin) with mass m1 = {mass_crank} kg and the slider mass
        (mass point 2) with mass m2 = {mass_slider} kg. The crank is a massless rigid link of
        length r = {crank_length} m, modeled as a distance constraint with distance r between
        ground at [0, 0, 0] and the crank mass; the connecting rod is a massless rigid link of
        length l = {rod_length} m, modeled as a distance constraint with distance l between the
        crank mass and the slider mass. Initially the crank is at the angle
        theta0 = {crank_angle_deg} degrees measured counter-clockwise from the positive x-axis
        (converted to radians), so the crank mass is at B = [r*cos(theta0), r*sin(theta0), 0],
        and the slider mass is on the x-axis at C = [xC, 0, 0] with
        xC = r*cos(theta0) + sqrt(l^2 - r^2*sin(theta0)^2). Use B and C as the reference
        positions of the two mass points; both start from rest. The motion is kept in the x-y
        plane and the slider on the x-axis by three coordinate constraints to ground
        (mbs.CreateCoordinateConstraint with itemNumbers=[None, mass point] and offset 0): one on
        the z-coordinate of the crank mass, one on the y-coordinate and one on the z-coordinate
        of the slider mass. A constant force [{force}, 0, 0] N acts on the slider mass (in
        positive x-direction). Gravity is neglected; there is no friction or damping. Create the
        ground, the crank mass, the slider mass, then the crank constraint, the rod constraint,
        the three coordinate constraints in the order given, and then the force.
    """,
    open_description="""
        A slider-crank mechanism in the x-y plane made of two point masses (no rotational inertia)
        and two massless rigid links. The crank is a massless rigid link of length
        r = {crank_length} m that turns about a fixed pivot at the origin [0, 0, 0]; at its other
        end, the crank pin, sits the first point mass m1 = {mass_crank} kg, which can move only in
        the x-y plane. The connecting rod is a massless rigid link of length l = {rod_length} m
        between the crank pin and the slider, the second point mass m2 = {mass_slider} kg, which can
        move only along the x-axis. The links keep the distances r (pivot to crank pin) and l (crank
        pin to slider) exactly; the pivot, the pins and the slider guide are frictionless. At the
        start both masses are at rest; the crank points at the angle
        theta0 = {crank_angle_deg} degrees measured counter-clockwise from the positive x-axis, so
        the crank pin is at [r*cos(theta0), r*sin(theta0), 0], and the slider is on the x-axis on
        the positive-x side of the crank pin, at x = r*cos(theta0) + sqrt(l^2 - r^2*sin(theta0)^2).
        A constant force of {force} N in the positive x-direction acts on the slider. Gravity is
        neglected; there is no friction or damping.
    """,
    params=(
        Param("mass_crank", 0.5, 3.0, "kg"),
        Param("mass_slider", 0.5, 3.0, "kg"),
        Param("crank_length", 0.2, 0.5, "m"),
        Param("rod_length", 0.8, 1.5, "m"),
        Param("crank_angle_deg", 30.0, 150.0, "deg"),
        Param("force", 5.0, 20.0, "N"),
    ),
    components=("Ground", "MassPoint", "DistanceConstraint", "CoordinateConstraint", "Force"),
    model_code="""
        theta0 = crank_angle_deg * np.pi / 180
        pB = [crank_length * np.cos(theta0), crank_length * np.sin(theta0), 0]
        xC = crank_length * np.cos(theta0) + np.sqrt(rod_length**2 - (crank_length * np.sin(theta0))**2)
        pC = [xC, 0, 0]

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oCrank = mbs.CreateMassPoint(referencePosition=pB, mass=mass_crank)
        oSlider = mbs.CreateMassPoint(referencePosition=pC, mass=mass_slider)
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oCrank], distance=crank_length)
        mbs.CreateDistanceConstraint(itemNumbers=[oCrank, oSlider], distance=rod_length)
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oCrank], coordinates=[None, 2], offset=0)
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oSlider], coordinates=[None, 1], offset=0)
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oSlider], coordinates=[None, 2], offset=0)
        mbs.CreateForce(itemNumber=oSlider, loadVector=[force, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
