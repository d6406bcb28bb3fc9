"""Task 35 (level 2): slider crank / rigid bodies — crank, connecting rod and slider in the x-y plane.

Crank (revolute to ground), connecting rod (revolute to the crank) and slider (prismatic to ground
along x) are cuboid rigid bodies. A revolute joint between rod and slider would close the loop with
three redundant constraints in 3D, so the rod is attached to the slider by a spherical joint that
constrains only the global x- and y-translations: 18 coordinates, 17 independent constraints, one
degree of freedom, no redundant constraints. The rod is always longer than the crank, so there is no
kinematic singularity. The crank is driven from rest by a constant torque under gravity; the
mechanism has one degree of freedom and is not chaotic.

Physics checks: kinetic + potential energy minus the work T*(theta - theta0) of the drive torque
stays zero; the slider stays on the x-axis without rotating.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=35,
    name="slider crank / rigid bodies",
    level="2",
    description="""
        A slider-crank mechanism moving in the x-y plane, consisting of three rigid bodies: a crank,
        a connecting rod and a slider, all homogeneous with density rho = {density} kg/m^3 and with
        inertias computed with InertiaCuboid (so each body's reference point is its center of mass).
        The crank has length r = {crank_length} m and the connecting rod length l = {rod_length} m;
        both have a square cross-section of side w = {width} m, i.e. side lengths [r, w, w] and
        [l, w, w] along their local x-, y- and z-axes, with the local x-axis along the link. The
        slider is a cube with side length s = {slider_size} m (side lengths [s, s, s]). The crank
        rotates about ground point O = [0, 0, 0]; initially it is at the angle
        theta0 = {crank_angle_deg} degrees measured counter-clockwise from the positive x-axis
        (converted to radians), so the crank pin is at B = [r*cos(theta0), r*sin(theta0), 0]. The
        slider's center is at C = [xC, 0, 0] on the x-axis with
        xC = r*cos(theta0) + sqrt(l^2 - r^2*sin(theta0)^2). Reference configuration (all bodies
        start from rest): the crank's reference position is B/2 with reference rotation matrix
        RotationMatrixZ(theta0); the rod's reference position is (B + C)/2 with reference rotation
        matrix RotationMatrixZ(beta0), beta0 = -arcsin(r*sin(theta0)/l), so its local x-axis points
        from B to C; the slider's reference position is C with the identity rotation. Joints, all
        given in global coordinates: a revolute joint between ground and crank at O with axis
        [0, 0, 1]; a revolute joint between crank and rod at B with axis [0, 0, 1]; a spherical
        joint between rod and slider at C that constrains only the x- and y-translations
        (constrainedAxes = [1, 1, 0]), since a fully constrained joint would be redundant; and a
        prismatic joint between ground and slider at C with sliding axis [1, 0, 0]. The crank is
        driven by a constant torque [0, 0, {torque}] N*m applied to the crank. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on all three bodies. No friction or
        damping. Create the ground, the crank, the rod and the slider, then the joints in the order
        given, then the torque.
    """,
    open_description="""
        A slider-crank mechanism moving in the x-y plane, made of three homogeneous rigid bodies of
        density {density} kg/m^3: a crank, a connecting rod and a slider. The crank is a bar of
        length r = {crank_length} m and the connecting rod a bar of length l = {rod_length} m, both
        with a square cross-section of side w = {width} m; the slider is a cube of side
        s = {slider_size} m. The crank is pinned at one end to the fixed world at O = [0, 0, 0] by
        a frictionless hinge about the global z-axis. Its other end, the crank pin B, is joined to
        one end of the connecting rod by a frictionless hinge about the z-axis; the rod's other end
        is pinned, also frictionlessly about the z-axis, to the centre C of the slider. The slider
        is guided without friction along the global x-axis: its centre stays on the x-axis and it
        does not rotate. At the start the crank points from O at the angle
        theta0 = {crank_angle_deg} degrees, measured counter-clockwise from the positive x-axis, so
        B = [r*cos(theta0), r*sin(theta0), 0]; C is the point on the x-axis at distance l from B
        to the right of B (larger x), C = [r*cos(theta0) + sqrt(l^2 - r^2*sin(theta0)^2), 0, 0];
        each bar spans the straight segment between its two joint points (crank from O to B, rod
        from B to C).
        All bodies start from rest. A constant torque of {torque} N*m about the global +z axis
        (counter-clockwise) drives the crank, and gravity g = {gravity} m/s^2 acts in the negative
        y-direction on all three bodies. There is no friction and no damping.
    """,
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("crank_length", 0.1, 0.25, "m"),
        Param("rod_length", 0.35, 0.6, "m"),
        Param("width", 0.02, 0.04, "m"),
        Param("slider_size", 0.04, 0.08, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("torque", 0.05, 0.5, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=(
        "Ground",
        "RigidBody",
        "InertiaCuboid",
        "RevoluteJoint",
        "SphericalJoint",
        "PrismaticJoint",
        "Torque",
    ),
    model_code="""
        theta0 = crank_angle_deg * np.pi / 180
        pB = np.array([crank_length * np.cos(theta0), crank_length * np.sin(theta0), 0])
        xC = crank_length * np.cos(theta0) + np.sqrt(rod_length**2 - (crank_length * np.sin(theta0))**2)
        pC = np.array([xC, 0, 0])
        beta0 = -np.arcsin(crank_length * np.sin(theta0) / rod_length)

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oCrank = mbs.CreateRigidBody(referencePosition=0.5 * pB,
                                     referenceRotationMatrix=RotationMatrixZ(theta0),
                                     inertia=InertiaCuboid(density=density,
                                                           sideLengths=[crank_length, width, width]),
                                     gravity=[0, -gravity, 0])
        oRod = mbs.CreateRigidBody(referencePosition=0.5 * (pB + pC),
                                   referenceRotationMatrix=RotationMatrixZ(beta0),
                                   inertia=InertiaCuboid(density=density,
                                                         sideLengths=[rod_length, width, width]),
                                   gravity=[0, -gravity, 0])
        oSlider = mbs.CreateRigidBody(referencePosition=pC,
                                      referenceRotationMatrix=np.eye(3),
                                      inertia=InertiaCuboid(density=density,
                                                            sideLengths=[slider_size] * 3),
                                      gravity=[0, -gravity, 0])

        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oCrank], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oCrank, oRod], position=pB, axis=[0, 0, 1])
        mbs.CreateSphericalJoint(itemNumbers=[oRod, oSlider], position=pC, constrainedAxes=[1, 1, 0])
        mbs.CreatePrismaticJoint(itemNumbers=[oGround, oSlider], position=pC, axis=[1, 0, 0])
        mbs.CreateTorque(itemNumber=oCrank, loadVector=[0, 0, torque])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
