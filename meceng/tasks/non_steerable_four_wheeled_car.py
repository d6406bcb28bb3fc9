"""Task 47 (level 2): non-steerable four-wheeled car — a chassis on four wheels with ideal rolling,
driven by torques on the rear wheels.

The chassis (a cuboid rigid body) carries four wheels (cylinder rigid bodies) on revolute joints;
each wheel rolls on the plane z = 0 with the ideal rolling-disc constraint. With all rolling
directions constrained the system is over-constrained: the lateral constraints of the two wheels on
one axle are identical, and four normal contacts hold a rigid chassis with only three degrees of
freedom (height, roll, pitch). The lateral constraint is therefore dropped at both right wheels and
the normal constraint at the rear-right wheel (constrainedAxes [0, 1, 1] and [0, 1, 0]): 5 x 7
coordinates, 5 Euler parameter conditions, 20 joint and 9 rolling constraints leave one degree of
freedom (rolling along x), with no redundant constraints. Straight-line motion under constant drive
torques has constant acceleration and is not sensitive to round-off.

Physics checks: x(t) = v0*t + a*t^2/2 with a = 2*T/(r*(m_chassis + 4*m_wheel + 4*J/r^2)),
J = m_wheel*r^2/2; all wheels spin with omega = v/r (rolling without slipping); the chassis stays at
the axle height without pitch, roll or yaw.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=47,
    name="non-steerable four-wheeled car",
    level="2",
    description="""
        A non-steerable four-wheeled car rolls along the x-axis on the ground plane z = 0 (gravity
        g = {gravity} m/s^2 in the negative z-direction). It consists of five rigid bodies: the
        chassis and four wheels. The chassis is a homogeneous cuboid with density
        rho_c = {chassis_density} kg/m^3 and side lengths [L, B, h] = [{wheelbase}, {track},
        {chassis_height}] m (inertia InertiaCuboid), with its center at [0, 0, r], where
        r = {wheel_radius} m is the wheel radius, L = {wheelbase} m the wheelbase and
        B = {track} m the track width. The wheel centers are: front-left [L/2, B/2, r], front-right
        [L/2, -B/2, r], rear-left [-L/2, B/2, r] and rear-right [-L/2, -B/2, r]. All wheels are
        homogeneous discs with density rho_w = {wheel_density} kg/m^3, radius r and width
        w = {wheel_width} m, with inertia InertiaCylinder(density=rho_w, length=w, outerRadius=r,
        axis=1), i.e. the wheel axis is the local y-axis. All bodies have the identity reference
        rotation. Each wheel is connected to the chassis by a revolute joint at the wheel center
        with the axis [0, 1, 0], both given in global coordinates (chassis first, wheel second).
        Each wheel rolls on the ground with a rolling disc joint between the ground (created at
        [0, 0, 0]) and the wheel, with axisPosition = [0, 0, 0] and axisVector = [0, 1, 0] in the
        wheel's local coordinates, the disc radius r, and the ground plane through [0, 0, 0] with
        normal [0, 0, 1]. To avoid redundant constraints, the rolling disc joints of the left
        wheels constrain all three directions (constrainedAxes = [1, 1, 1]: lateral, longitudinal,
        normal), that of the front-right wheel only the longitudinal and normal directions
        (constrainedAxes = [0, 1, 1]) and that of the rear-right wheel only the longitudinal
        direction (constrainedAxes = [0, 1, 0]). Initially the car moves with the speed
        v0 = {velocity} m/s in the positive x-direction: all five bodies have the initial velocity
        [v0, 0, 0], and all wheels have the initial angular velocity [0, v0/r, 0] (rolling without
        slipping). Each rear wheel is driven by a constant torque [0, {torque}, 0] N*m (global)
        applied to the wheel (the reaction on the chassis is neglected). Create the ground, the
        chassis, the wheels in the order front-left, front-right, rear-left, rear-right, then the
        revolute joints and the rolling disc joints (each in the same wheel order), then the torques
        on the rear-left and the rear-right wheel.
    """,
    open_description="""
        A non-steerable four-wheeled car rolls straight ahead along the x-axis on the horizontal
        ground plane z = 0; gravity g = {gravity} m/s^2 acts in the negative z-direction. It has
        five rigid bodies: a chassis and four wheels. The chassis is a homogeneous box of density
        {chassis_density} kg/m^3 with the side lengths L = {wheelbase} m along x, B = {track} m
        along y and h = {chassis_height} m along z; its centre is at [0, 0, r], where
        r = {wheel_radius} m is the wheel radius, L is also the wheelbase and B the track width. The
        wheel centres are: front-left [L/2, B/2, r], front-right [L/2, -B/2, r], rear-left
        [-L/2, B/2, r] and rear-right [-L/2, -B/2, r]. Each wheel is a homogeneous solid disc of
        density {wheel_density} kg/m^3, radius r and width w = {wheel_width} m, with its axle along
        the global y-axis, and turns on the chassis in a frictionless hinge at its centre whose axis
        is the wheel's axle. Each wheel rolls ideally on the ground: at its contact point it slips
        neither in the rolling direction nor sideways, and its rim stays on the ground (it neither
        lifts off nor sinks in). (For a rigid chassis on four such wheels these conditions are
        partly redundant: the two wheels of an axle share their sideways condition, and four ground
        contacts hold a chassis that has only three degrees of freedom in height, roll and pitch.)
        Initially the car moves at v0 = {velocity} m/s in the positive x-direction: all five bodies
        have the velocity [v0, 0, 0], the chassis does not rotate, and all wheels spin with the
        angular velocity [0, v0/r, 0] (rolling without slipping). Each rear wheel is driven by a
        constant torque of {torque} N*m about the positive y-axis; it acts on that wheel alone (its
        reaction on the chassis is left out).
    """,
    params=(
        Param("wheelbase", 1.5, 3.0, "m"),
        Param("track", 1.0, 1.6, "m"),
        Param("chassis_height", 0.2, 0.5, "m"),
        Param("chassis_density", 100.0, 300.0, "kg/m^3"),
        Param("wheel_radius", 0.25, 0.4, "m"),
        Param("wheel_width", 0.1, 0.25, "m"),
        Param("wheel_density", 500.0, 1500.0, "kg/m^3"),
        Param("velocity", 1.0, 10.0, "m/s"),
        Param("torque", 10.0, 100.0, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "InertiaCylinder", "RevoluteJoint", "RollingDisc",
                "Torque"),
    model_code="""
        r = wheel_radius
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oChassis = mbs.CreateRigidBody(referencePosition=[0, 0, r],
                                       referenceRotationMatrix=np.eye(3),
                                       initialVelocity=[velocity, 0, 0],
                                       inertia=InertiaCuboid(density=chassis_density,
                                                             sideLengths=[wheelbase, track, chassis_height]),
                                       gravity=[0, 0, -gravity])
        centers = [[0.5 * wheelbase, 0.5 * track, r], [0.5 * wheelbase, -0.5 * track, r],
                   [-0.5 * wheelbase, 0.5 * track, r], [-0.5 * wheelbase, -0.5 * track, r]]
        wheels = []
        for p in centers:
            wheels.append(mbs.CreateRigidBody(referencePosition=p,
                                              referenceRotationMatrix=np.eye(3),
                                              initialVelocity=[velocity, 0, 0],
                                              initialAngularVelocity=[0, velocity / r, 0],
                                              inertia=InertiaCylinder(density=wheel_density, length=wheel_width,
                                                                      outerRadius=r, axis=1),
                                              gravity=[0, 0, -gravity]))
        for oWheel, p in zip(wheels, centers):
            mbs.CreateRevoluteJoint(itemNumbers=[oChassis, oWheel], position=p, axis=[0, 1, 0])
        for oWheel, axes in zip(wheels, [[1, 1, 1], [0, 1, 1], [1, 1, 1], [0, 1, 0]]):
            mbs.CreateRollingDisc(bodyNumbers=[oGround, oWheel], axisPosition=[0, 0, 0], axisVector=[0, 1, 0],
                                  discRadius=r, planePosition=[0, 0, 0], planeNormal=[0, 0, 1],
                                  constrainedAxes=axes)
        mbs.CreateTorque(itemNumber=wheels[2], loadVector=[0, torque, 0])
        mbs.CreateTorque(itemNumber=wheels[3], loadVector=[0, torque, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
