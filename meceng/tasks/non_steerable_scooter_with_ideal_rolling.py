"""Task 46 (level 2): non-steerable scooter with ideal rolling — a frame on two in-line wheels,
driven by a torque on the rear wheel.

The frame (a cuboid rigid body) carries the front and the rear wheel (cylinder rigid bodies) on
revolute joints; each wheel rolls on the plane z = 0 with the ideal rolling-disc constraint, all
three of its directions constrained (lateral, longitudinal, normal): 3 x 7 coordinates, 3 Euler
parameter conditions, 10 joint and 6 rolling constraints leave two degrees of freedom (rolling
forward and leaning sideways), with no redundant constraints. The scooter is upright and symmetric
to the x-z plane, so it rolls straight along x and does not lean (the lean equilibrium is unstable,
but the symmetric motion is computed without any lateral perturbation). The rear wheel is driven by
a constant torque about its axle, so the forward acceleration is constant.

Physics checks: the forward motion is x(t) = v0*t + a*t^2/2 with
a = T/(r*(m_frame + 2*m_wheel + 2*J/r^2)), J = m_wheel*r^2/2; both wheels spin with omega = v/r
(rolling without slipping); the frame stays at the axle height without pitch, yaw or lean.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=46,
    name="non-steerable scooter with ideal rolling",
    level="2",
    description="""
        A non-steerable scooter rolls along the x-axis on the ground plane z = 0 (gravity
        g = {gravity} m/s^2 in the negative z-direction). It consists of three rigid bodies: the
        frame and two wheels. The frame is a homogeneous cuboid with density
        rho_f = {frame_density} kg/m^3 and side lengths [L, b, h] = [{wheelbase}, {frame_width},
        {frame_height}] m (inertia InertiaCuboid), with its center at [0, 0, r], where
        r = {wheel_radius} m is the wheel radius and L = {wheelbase} m the wheelbase. The front
        wheel has its center at [L/2, 0, r] and the rear wheel at [-L/2, 0, r]; both are
        homogeneous discs with density rho_w = {wheel_density} kg/m^3, radius r and width
        w = {wheel_width} m, with inertia InertiaCylinder(density=rho_w, length=w, outerRadius=r,
        axis=1), i.e. the wheel axis is the local y-axis. All bodies have the identity reference
        rotation. Each wheel is connected to the frame by a revolute joint at the wheel center with
        the axis [0, 1, 0], both given in global coordinates (frame first, wheel second). Each wheel rolls on the ground with a rolling disc joint between the
        ground (created at [0, 0, 0]) and the wheel, with axisPosition = [0, 0, 0] and axisVector =
        [0, 1, 0] in the wheel's local coordinates, the disc radius r, and the ground plane through
        [0, 0, 0] with normal [0, 0, 1] (all three directions constrained). Initially the scooter
        moves with the speed v0 = {velocity} m/s in the positive x-direction: all three bodies have
        the initial velocity [v0, 0, 0], and both wheels have the initial angular velocity
        [0, v0/r, 0] (rolling without slipping). The rear wheel is driven by a constant torque
        [0, {torque}, 0] N*m (global) applied to the rear wheel (the reaction on the frame is
        neglected). Create the ground, the frame, the front wheel, the rear wheel, then the
        revolute joints (front, rear), the rolling disc joints (front, rear) and the torque.
    """,
    open_description="""
        A non-steerable scooter rolls straight ahead along the x-axis on the horizontal ground plane
        z = 0; gravity g = {gravity} m/s^2 acts in the negative z-direction. It has three rigid
        bodies: a frame and two wheels. The frame is a homogeneous box of density {frame_density}
        kg/m^3 with the side lengths L = {wheelbase} m along x, b = {frame_width} m along y and
        h = {frame_height} m along z; its centre is at [0, 0, r], where r = {wheel_radius} m is the
        wheel radius (L is also the wheelbase). The front wheel's centre is at [L/2, 0, r], the rear
        wheel's at [-L/2, 0, r]; each wheel is a homogeneous solid disc of density {wheel_density}
        kg/m^3, radius r and width w = {wheel_width} m, with its axle along the global y-axis. Each
        wheel turns on the frame in a frictionless hinge at its centre whose axis is the wheel's
        axle. Each wheel rolls ideally on the ground: at its contact point it slips neither in the
        rolling direction nor sideways, and its rim stays on the ground (it neither lifts off nor
        sinks in). Initially the scooter moves at v0 = {velocity} m/s in the positive x-direction:
        all three bodies have the velocity [v0, 0, 0], the frame does not rotate, and both wheels
        spin with the angular velocity [0, v0/r, 0] (rolling without slipping). A constant torque of
        {torque} N*m about the positive y-axis drives the rear wheel; it acts on the rear wheel
        alone (its reaction on the frame is left out).
    """,
    params=(
        Param("wheelbase", 0.5, 1.0, "m"),
        Param("frame_width", 0.1, 0.2, "m"),
        Param("frame_height", 0.02, 0.05, "m"),
        Param("frame_density", 500.0, 1500.0, "kg/m^3"),
        Param("wheel_radius", 0.05, 0.15, "m"),
        Param("wheel_width", 0.02, 0.05, "m"),
        Param("wheel_density", 1000.0, 3000.0, "kg/m^3"),
        Param("velocity", 1.0, 4.0, "m/s"),
        Param("torque", 0.1, 1.0, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCuboid", "InertiaCylinder", "RevoluteJoint", "RollingDisc",
                "Torque"),
    model_code="""
        r = wheel_radius
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oFrame = mbs.CreateRigidBody(referencePosition=[0, 0, r],
                                     referenceRotationMatrix=np.eye(3),
                                     initialVelocity=[velocity, 0, 0],
                                     inertia=InertiaCuboid(density=frame_density,
                                                           sideLengths=[wheelbase, frame_width, frame_height]),
                                     gravity=[0, 0, -gravity])
        wheels = []
        for x in [0.5 * wheelbase, -0.5 * wheelbase]:
            wheels.append(mbs.CreateRigidBody(referencePosition=[x, 0, r],
                                              referenceRotationMatrix=np.eye(3),
                                              initialVelocity=[velocity, 0, 0],
                                              initialAngularVelocity=[0, velocity / r, 0],
                                              inertia=InertiaCylinder(density=wheel_density, length=wheel_width,
                                                                      outerRadius=r, axis=1),
                                              gravity=[0, 0, -gravity]))
        for oWheel, x in zip(wheels, [0.5 * wheelbase, -0.5 * wheelbase]):
            mbs.CreateRevoluteJoint(itemNumbers=[oFrame, oWheel], position=[x, 0, r], axis=[0, 1, 0])
        for oWheel in wheels:
            mbs.CreateRollingDisc(bodyNumbers=[oGround, oWheel], axisPosition=[0, 0, 0], axisVector=[0, 1, 0],
                                  discRadius=r, planePosition=[0, 0, 0], planeNormal=[0, 0, 1])
        mbs.CreateTorque(itemNumber=wheels[1], loadVector=[0, torque, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
