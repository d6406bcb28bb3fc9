"""Task 34 (level 2): rigid rotor unbalanced — a cylinder rotor with an unbalance mass on two rigid
bearings, driven by a constant torque under gravity.

The unbalance is part of the rotor's rigid-body inertia (cylinder + point mass at the surface), so
the body's reference point stays on the axis and its center of mass is offset. Bearing A is a
spherical joint, bearing B a generic joint fixing only the two lateral translations: one degree of
freedom (rotation about x), no redundant constraints. The unbalance starts at the top with a
positive spin and a positive drive torque, so the kinetic energy 0.5*J*omega0^2 + m_u*g*r*(1 - cos)
+ T*angle never vanishes: the rotor turns monotonically with a non-uniform rate and never comes to
rest near the unstable top position, so the solution is insensitive to re-ordering round-off.

Physics check: the rotation angle follows J*theta'' = T + m_u*g*r*sin(theta) with
J = m*r^2/2 + m_u*r^2 (integrated independently); the rotor axis stays fixed.
"""

from meceng.tasks.base import Param, SimSettings, TaskModel

TASK = TaskModel(
    id=34,
    name="rigid rotor unbalanced",
    level="2",
    description="""
        A rigid rotor with an unbalance on two bearings. The rotor is a homogeneous solid cylinder
        with density rho = {density} kg/m^3, length L = {length} m and radius r = {radius} m, with its
        axis along the global x-axis, carrying an unbalance mass m_u = {unbalance_mass} kg (a point
        mass) on its surface in the middle of its length. The unbalance is included in the rotor's
        rigid-body inertia: inertia = InertiaCylinder(density=rho, length=L, outerRadius=r, axis=0)
        + InertiaMassPoint(mass=m_u).Translated([0, 0, r]), i.e. the point mass sits at the local
        position [0, 0, r], and the body's reference point is the cylinder's center on the rotor
        axis (its center of mass is shifted towards the unbalance). The rotor's reference position
        is [0, 0, 0] and its reference rotation is the identity, so the unbalance starts at the top.
        Bearing A at [-L/2, 0, 0] is a spherical joint between ground and rotor (all three
        translations constrained); bearing B at [L/2, 0, 0] is a generic joint between ground and
        rotor with identity axes that constrains only the translations in global y- and z-direction
        (constrainedAxes = [0, 1, 1, 0, 0, 0]). The rotor starts with the initial angular velocity
        [{omega0}, 0, 0] rad/s (zero initial translational velocity) and is driven by a constant
        torque [{torque}, 0, 0] N*m about the global x-axis applied to the rotor. Gravity
        g = {gravity} m/s^2 acts in the negative z-direction on the rotor (including the unbalance).
        No friction. Create the ground, the rotor, bearing A, bearing B and then the torque.
    """,
    open_description="""
        A rigid rotor with an unbalance on two bearings. The rotor is a homogeneous solid cylinder
        of density {density} kg/m^3, length L = {length} m and radius r = {radius} m, whose axis
        lies along the global x-axis with the cylinder's centre at the origin [0, 0, 0]; its end
        faces are at x = -L/2 and x = L/2. An unbalance mass m_u = {unbalance_mass} kg, taken as a
        point mass, is rigidly fixed to the rotor's surface in the middle of its length; at the
        start it sits at the top, at [0, 0, r]. Cylinder and unbalance form one rigid body, whose
        centre of mass is therefore slightly off the axis towards the unbalance. The rotor is held
        by two frictionless bearings at the centres of its end faces: bearing A at [-L/2, 0, 0] is
        a fixed bearing that holds that point in all three directions but lets the rotor turn
        freely about any axis through it; bearing B at [L/2, 0, 0] is a floating bearing that holds
        that point only in the global y- and z-directions (free to slide along x and to turn).
        Together they leave the rotor free only to turn about its geometric axis (the x-axis). A
        constant torque of {torque} N*m about the global +x axis drives the rotor, and gravity
        g = {gravity} m/s^2 acts in the negative z-direction on the cylinder and the unbalance. At
        the start the axis is at rest and the rotor spins about the +x axis with the angular
        velocity {omega0} rad/s.
    """,
    params=(
        Param("density", 7000.0, 8000.0, "kg/m^3"),
        Param("length", 0.2, 0.4, "m"),
        Param("radius", 0.06, 0.1, "m"),
        Param("unbalance_mass", 0.02, 0.2, "kg"),
        Param("omega0", 2.0, 10.0, "rad/s"),
        Param("torque", 0.02, 0.2, "N*m"),
        Param("gravity", 9.78, 9.83, "m/s^2", digits=4),
    ),
    components=("Ground", "RigidBody", "InertiaCylinder", "SphericalJoint", "GenericJoint", "Torque"),
    model_code="""
        inertia = (InertiaCylinder(density=density, length=length, outerRadius=radius, axis=0)
                   + InertiaMassPoint(mass=unbalance_mass).Translated([0, 0, radius]))
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oRotor = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialAngularVelocity=[omega0, 0, 0],
                                     inertia=inertia,
                                     gravity=[0, 0, -gravity])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oRotor], position=[-0.5 * length, 0, 0])
        mbs.CreateGenericJoint(itemNumbers=[oGround, oRotor], position=[0.5 * length, 0, 0],
                               constrainedAxes=[0, 1, 1, 0, 0, 0])
        mbs.CreateTorque(itemNumber=oRotor, loadVector=[torque, 0, 0])
    """,
    sim=SimSettings(end_time=2.0, steps=2000),
)
