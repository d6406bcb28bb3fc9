"""Task 36 (level 2): four-bar mechanism / rigid bodies — crank, coupler and rocker as cuboid rigid
bodies in the x-y plane, released from rest under gravity.

Joints: revolute ground-crank at A, revolute crank-coupler at B, revolute ground-rocker at D (all
about the global z-axis) and, at C, a spherical joint between coupler and rocker that constrains
only the global x- and y-translations (constrainedAxes = [1, 1, 0]). Four revolute joints would
over-constrain the closed planar loop in 3D (three redundant constraints); with the reduced
spherical joint there are 21 coordinates, 20 independent constraints, one degree of freedom and
no redundant constraints. The link lengths are drawn from a Grashof crank-rocker range with a
margin of at least 0.05 m in every collinearity condition, so the joints never become collinear
(no change point, no loss of rank) and the crank can turn fully. No drive torque: with a constant
torque the crank either spins up to rates the time step does not resolve or, for some draws, nearly
stops at the top of the tilted potential, where re-ordering round-off decides the direction. A
conservative one-degree-of-freedom system released from rest is not chaotic; 2 s are safe.
The density scales all masses alike and therefore does not change the motion.

Physics checks: the simulated crank angle satisfies the one-degree-of-freedom equation of motion
M(theta)*theta'' + M'(theta)/2*theta'^2 + V'(theta) = 0 of the linkage (M from the link masses and
inertias, V from gravity, recomputed from the parameters); the joint points of the links coincide
and the bodies stay in the plane.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=36,
    name="four-bar mechanism / rigid bodies",
    level="2",
    description="""
        A planar four-bar mechanism moving in the x-y plane, consisting of three rigid bodies: a
        crank, a coupler and a rocker, all homogeneous with density rho = {density} kg/m^3 and with
        inertias computed with InertiaCuboid (so each body's reference point is its center of mass).
        The ground pivots are A = [0, 0, 0] (crank) and D = [{ground_length}, 0, 0] (rocker). The
        crank has length a = {crank_length} m, the coupler length b = {coupler_length} m and the
        rocker length c = {rocker_length} m; all three have a square cross-section of side
        w = {width} m, i.e. side lengths [length, w, w] along their local x-, y- and z-axes, with the
        local x-axis along the link. Initially the crank is at the angle theta0 = {crank_angle_deg}
        degrees, measured counter-clockwise from the positive x-axis (converted to radians), so the
        crank-coupler joint is at B = [a*cos(theta0), a*sin(theta0), 0]. The coupler-rocker joint C
        is the intersection of the circles of radius b about B and radius c about D on the left of
        the direction from B to D: with e = D - B, f = |e|, s = (b^2 - c^2 + f^2)/(2*f) and
        h = sqrt(b^2 - s^2), C = B + (s/f)*e + (h/f)*[-e_y, e_x, 0]. Reference configuration (all
        bodies start from rest): the crank's reference position is (A + B)/2 with reference rotation
        matrix RotationMatrixZ(theta0); the coupler's reference position is (B + C)/2 with
        RotationMatrixZ(beta0), beta0 = atan2(C_y - B_y, C_x - B_x), so its local x-axis points from
        B to C; the rocker's reference position is (D + C)/2 with RotationMatrixZ(gamma0),
        gamma0 = atan2(C_y - D_y, C_x - D_x), so its local x-axis points from D to C. Joints, all
        given in global coordinates: a revolute joint between ground and crank at A, a revolute
        joint between crank and coupler at B and a revolute joint between ground and rocker at D,
        all with axis [0, 0, 1]; the loop is closed at C by a spherical joint between coupler and
        rocker that constrains only the x- and y-translations (constrainedAxes = [1, 1, 0]), since a
        fourth revolute joint would be redundant. Gravity g = {gravity} m/s^2 acts in the negative
        y-direction on all three bodies. No drive, friction or damping. Create the ground, the crank,
        the coupler and the rocker, then the joints in the order given.
    """,
    open_description="""
        A planar four-bar linkage moving in the x-y plane, made of three homogeneous rigid bars of
        density {density} kg/m^3 with a square cross-section of side w = {width} m: a crank of
        length a = {crank_length} m, a coupler of length b = {coupler_length} m and a rocker of
        length c = {rocker_length} m. The fixed pivots are A = [0, 0, 0] and
        D = [{ground_length}, 0, 0]. The crank is pinned at one end to the fixed world at A, the
        rocker at one end to the fixed world at D; the crank's other end is pinned to one end of
        the coupler at B, and the coupler's other end to the rocker's free end at C. All four pins
        are frictionless hinges about the global z-axis. At the start the crank points from A at
        the angle theta0 = {crank_angle_deg} degrees, measured counter-clockwise from the positive
        x-axis, so B = [a*cos(theta0), a*sin(theta0), 0]; C is the point at distance b from B and
        c from D that lies on the left-hand side of the line from B towards D (above that line).
        Each bar spans the straight segment between its two joint points (crank from A to B,
        coupler from B to C, rocker from D to C). All bodies start from rest. Gravity
        g = {gravity} m/s^2 acts in the negative y-direction on all three bars; there is no drive,
        no friction and no damping.
    """,
    params=(
        Param("density", 2000.0, 8000.0, "kg/m^3"),
        Param("ground_length", 0.4, 0.5, "m"),
        Param("crank_length", 0.08, 0.15, "m"),
        Param("coupler_length", 0.4, 0.5, "m"),
        Param("rocker_length", 0.3, 0.4, "m"),
        Param("width", 0.015, 0.03, "m"),
        Param("crank_angle_deg", 0.0, 350.0, "deg"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "RevoluteJoint", "SphericalJoint"),
    model_code="""
        theta0 = crank_angle_deg * np.pi / 180
        pA = np.array([0, 0, 0])
        pB = np.array([crank_length * np.cos(theta0), crank_length * np.sin(theta0), 0])
        pD = np.array([ground_length, 0, 0])
        e = pD - pB
        f = np.linalg.norm(e)
        s = (coupler_length**2 - rocker_length**2 + f**2) / (2 * f)
        h = np.sqrt(coupler_length**2 - s**2)
        pC = pB + (s / f) * e + (h / f) * np.array([-e[1], e[0], 0])
        beta0 = np.arctan2(pC[1] - pB[1], pC[0] - pB[0])
        gamma0 = np.arctan2(pC[1] - pD[1], pC[0] - pD[0])

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oCrank = mbs.CreateRigidBody(referencePosition=0.5 * (pA + pB),
                                     referenceRotationMatrix=RotationMatrixZ(theta0),
                                     inertia=InertiaCuboid(density=density,
                                                           sideLengths=[crank_length, width, width]),
                                     gravity=[0, -gravity, 0])
        oCoupler = mbs.CreateRigidBody(referencePosition=0.5 * (pB + pC),
                                       referenceRotationMatrix=RotationMatrixZ(beta0),
                                       inertia=InertiaCuboid(density=density,
                                                             sideLengths=[coupler_length, width, width]),
                                       gravity=[0, -gravity, 0])
        oRocker = mbs.CreateRigidBody(referencePosition=0.5 * (pD + pC),
                                      referenceRotationMatrix=RotationMatrixZ(gamma0),
                                      inertia=InertiaCuboid(density=density,
                                                            sideLengths=[rocker_length, width, width]),
                                      gravity=[0, -gravity, 0])

        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oCrank], position=pA, axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oCrank, oCoupler], position=pB, axis=[0, 0, 1])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oRocker], position=pD, axis=[0, 0, 1])
        mbs.CreateSphericalJoint(itemNumbers=[oCoupler, oRocker], position=pC, constrainedAxes=[1, 1, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
