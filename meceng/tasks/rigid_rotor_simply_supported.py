"""Task 29 (level 1): rigid rotor simply supported — a cylinder on two bearings, driven by a torque.

Bearing A is a spherical joint (all three translations fixed), bearing B a generic joint fixing
only the two lateral translations (y, z), so the axial direction is held once and the rotor keeps
exactly one degree of freedom (rotation about x) with no redundant constraints. Gravity only loads
the bearings.

Physics check: the spin rate grows as omega(t) = omega0 + T*t/J with J = m*r^2/2, i.e. the rotation
angle is omega0*t + T*t^2/(2*J); the centre of mass stays at the origin.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=29,
    name="rigid rotor simply supported",
    level="1",
    description="""
        A simply supported rigid rotor. The rotor is a homogeneous solid cylinder with density
        rho = {density} kg/m^3, length L = {length} m and radius r = {radius} m, with its axis
        along the global x-axis; its inertia is computed with
        InertiaCylinder(density=rho, length=L, outerRadius=r, axis=0), so the body's reference point
        is its center of mass. The rotor's reference position is [0, 0, 0] and its reference
        rotation is the identity. It is supported at its two end points by bearings: bearing A at
        [-L/2, 0, 0] is a spherical joint between ground and rotor (all three translations
        constrained); bearing B at [L/2, 0, 0] is a generic joint between ground and rotor with
        identity axes that constrains only the translations in global y- and z-direction
        (constrainedAxes = [0, 1, 1, 0, 0, 0]). The rotor starts with the initial angular velocity
        [{omega0}, 0, 0] rad/s (zero initial translational velocity) and is driven by a constant
        torque [{torque}, 0, 0] N*m about the global x-axis applied to the rotor. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction. Create the ground, the rotor,
        bearing A, bearing B and then the torque.
    """,
    open_description="""
        A simply supported rigid rotor: a homogeneous solid cylinder of density {density} kg/m^3,
        length L = {length} m and radius r = {radius} m, whose axis lies along the global x-axis
        with its centre of mass at the origin [0, 0, 0]; its end faces are at x = -L/2 and x = L/2.
        It is held by two frictionless bearings at the centres of its end faces: bearing A at
        [-L/2, 0, 0] is a fixed bearing that holds that point in all three directions but lets
        the rotor turn freely about any axis through it; bearing B at [L/2, 0, 0] is a floating
        bearing that holds that point only in the global y- and z-directions (free to slide along
        x and to turn). Together they leave the rotor free only to spin about its own axis. A
        constant torque of {torque} N*m about the global +x axis drives the rotor, and gravity
        g = {gravity} m/s^2 acts in the negative z-direction. At the start the centre of mass is
        at rest and the rotor spins about the +x axis with the angular velocity {omega0} rad/s.
    """,
    params=(
        Param("density", 7000.0, 8000.0, "kg/m^3"),
        Param("length", 0.3, 0.8, "m"),
        Param("radius", 0.05, 0.1, "m"),
        Param("omega0", 5.0, 30.0, "rad/s"),
        Param("torque", 0.1, 0.5, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "SphericalJoint", "GenericJoint", "Torque"),
    model_code="""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oRotor = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialAngularVelocity=[omega0, 0, 0],
                                     inertia=InertiaCylinder(density=density, length=length,
                                                             outerRadius=radius, axis=0),
                                     gravity=[0, 0, -gravity])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oRotor], position=[-0.5 * length, 0, 0])
        mbs.CreateGenericJoint(itemNumbers=[oGround, oRotor], position=[0.5 * length, 0, 0],
                               constrainedAxes=[0, 1, 1, 0, 0, 0])
        mbs.CreateTorque(itemNumber=oRotor, loadVector=[torque, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
