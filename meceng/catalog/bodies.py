"""Level 1-2 components: the ground, mass points, rigid bodies and their inertia helpers."""

from __future__ import annotations

from meceng.catalog.common import rigid_example
from meceng.catalog.component import Component, text_block

GROUND = Component(
    name="Ground",
    description=(
        "fixed ground (the inertial frame); the fixed end of every spring, joint, constraint or contact "
        "that is attached to the environment, a wall, a ceiling or a fixed point"
    ),
    context=text_block("""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        - Returns an ObjectIndex that is used like a body in itemNumbers=[oGround, oBody] of springs, joints
          and constraints: list the two items in the order the description names them, the ground first where
          it gives no order.
        - Create ONE ground object at [0, 0, 0] and reuse it for all attachments. A fixed point on ground is
          given by localPosition0=[x, y, z] of springs and distance constraints (local to the ground, i.e.
          global coordinates when the ground is at [0, 0, 0]) or by the global position= of joints.
        - The ground has no coordinates: no mass, no gravity, no loads.
        - Do not create a ground object for a system that is attached to nothing (e.g. a free flying body).
        - Coordinate connectors (CoordinateSpringDamper, CoordinateConstraint) need a ground NODE instead
          (NodePointGround), see there.
    """),
    example=rigid_example("""
        # a mass point hanging on a spring from the ground point [0, 0, 0]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[0, -0.5, 0], mass=1.0, gravity=[0, -9.81, 0])
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=500.0, damping=1.0)
    """),
)

MASS_POINT = Component(
    name="MassPoint",
    description=(
        "point mass with three translational degrees of freedom and no rotation; for particles, "
        "oscillator masses, pendulum bobs on massless rods, balls that only translate"
    ),
    context=text_block("""
        oMass = mbs.CreateMassPoint(referencePosition=[x, y, z], initialDisplacement=[0, 0, 0],
                                    initialVelocity=[0, 0, 0], mass=m, gravity=[0, 0, -9.81])
        - referencePosition: global position [m] in the reference configuration; springs (referenceLength) and
          distance constraints (distance) compute their default lengths from it.
        - initialDisplacement: start offset [m] from referencePosition (start position = referencePosition +
          initialDisplacement); use it for "initially displaced by ... from its reference position".
        - initialVelocity: global [m/s]; mass: [kg].
        - gravity: gravity acceleration vector [m/s^2] acting on this mass, e.g. [0, -9.81, 0] when gravity
          acts in negative y-direction; it is the weight, so add no extra force for it; leave it out if
          gravity is neglected.
        - Returns the body's ObjectIndex for itemNumbers/itemNumber; its node is
          nMass = mbs.GetObject(oMass)['nodeNumber'] (needed for coordinate markers and node sensors).
        - A mass point has no orientation: no revolute/prismatic/generic joints and no torques on it
          (use RigidBody for that: mbs.CreateRigidBody(referencePosition=[x, y, z],
          inertia=InertiaSphere(mass=m, radius=r), gravity=[0, -9.81, 0])).
    """),
    example=rigid_example("""
        # a mass point thrown from 2 m height under gravity in negative z-direction
        oMass = mbs.CreateMassPoint(referencePosition=[0, 0, 2.0],
                                    initialVelocity=[1.0, 0, 3.0],
                                    mass=0.5, gravity=[0, 0, -9.81])
    """),
)

RIGID_BODY = Component(
    name="RigidBody",
    description=(
        "rigid body with six degrees of freedom (position and orientation), mass and inertia tensor; for "
        "links, cranks, rods with mass, rotors, wheels, blocks; needed for joints with rotation and torques"
    ),
    context=text_block("""
        oBody = mbs.CreateRigidBody(referencePosition=[x, y, z], referenceRotationMatrix=np.eye(3),
                                    initialVelocity=[0, 0, 0], initialAngularVelocity=[0, 0, 0],
                                    inertia=InertiaCuboid(density=rho, sideLengths=[a, b, c]),
                                    gravity=[0, -9.81, 0])
        - inertia: a RigidBodyInertia object that gives mass AND inertia tensor: InertiaCuboid, InertiaCylinder,
          InertiaSphere, InertiaRodX(mass, length), InertiaMassPoint(mass); there is no mass= argument.
          One helper alone puts the center of mass at the body's reference point, so referencePosition is the
          global position of the center of mass. Inertias add up: InertiaCylinder(...) +
          InertiaMassPoint(mass=mu).Translated([0, 0, r]) is a cylinder with a point mass at the local point
          [0, 0, r]; the reference point stays at the cylinder's center and the center of mass moves towards
          the point mass (an unbalance); referencePosition is then the reference point's global position.
        - referenceRotationMatrix: rotation from local body axes to global axes in the reference configuration,
          e.g. RotationMatrixZ(phi) with phi in rad (also RotationMatrixX/Y), or np.eye(3) for no rotation.
        - initialVelocity [m/s] and initialAngularVelocity [rad/s] are global vectors.
        - gravity: gravity acceleration vector [m/s^2] for this body (its weight); add no extra force for it.
        - Joints, springs and constraints are defined in the reference configuration, so put the body at
          its start pose with referencePosition/referenceRotationMatrix.
        - Returns the body's ObjectIndex; its node is mbs.GetObject(oBody)['nodeNumber'].
    """),
    example=rigid_example("""
        # a free cuboid thrown upwards with spin; gravity in negative z-direction
        oBody = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    referenceRotationMatrix=np.eye(3),
                                    initialVelocity=[1.0, 0, 4.0],
                                    initialAngularVelocity=[0, 0.5, 8.0],
                                    inertia=InertiaCuboid(density=1000, sideLengths=[0.4, 0.2, 0.05]),
                                    gravity=[0, 0, -9.81])
    """),
)

INERTIA_CUBOID = Component(
    name="InertiaCuboid",
    description=(
        "mass and inertia tensor of a homogeneous box (cuboid) from density and side lengths; for links, "
        "bars, beams, blocks, plates and sliders modeled as rigid bodies"
    ),
    context=text_block("""
        inertia = InertiaCuboid(density=rho, sideLengths=[a, b, c])
        - density [kg/m^3]; sideLengths [m] along the body's LOCAL x-, y- and z-axes; mass = rho*a*b*c.
        - Alone it puts the center of mass at the body's reference point (referencePosition of CreateRigidBody).
        - If a mass m is given instead of a density, use density=m/(a*b*c).
        - Orient the local axes with referenceRotationMatrix, e.g. a link with its long side a along local x
          that is rotated by phi in the x-y plane: referenceRotationMatrix=RotationMatrixZ(phi).
        - Pass the object as inertia= to CreateRigidBody; inertia.Mass() returns the mass.
    """),
    example=rigid_example("""
        # a bar (long side along local x) rotated by 30 degrees about z, falling with spin
        density = 2700
        a, b, c = 0.5, 0.04, 0.02
        phi0 = 30 * np.pi / 180
        oBar = mbs.CreateRigidBody(referencePosition=[0, 0, 1.0],
                                   referenceRotationMatrix=RotationMatrixZ(phi0),
                                   initialAngularVelocity=[0, 0, 2.0],
                                   inertia=InertiaCuboid(density=density, sideLengths=[a, b, c]),
                                   gravity=[0, 0, -9.81])
    """),
    dependencies=("RigidBody",),
)

INERTIA_CYLINDER = Component(
    name="InertiaCylinder",
    description=(
        "mass and inertia tensor of a homogeneous solid or hollow cylinder; for shafts, rotors, wheels, "
        "discs, drums and tubes modeled as rigid bodies"
    ),
    context=text_block("""
        inertia = InertiaCylinder(density=rho, length=L, outerRadius=r, axis=0, innerRadius=0)
        - axis: the cylinder axis as an integer index of the LOCAL body axes: 0 = x, 1 = y, 2 = z (not a vector).
        - density [kg/m^3], length and radii [m]; innerRadius > 0 gives a hollow cylinder (tube, ring).
        - mass = rho*pi*(r^2 - ri^2)*L; solid: J_axis = m*r^2/2. If a mass m is given, density=m/(pi*r^2*L).
        - Alone it puts the center of mass at the body's reference point (an added, translated point mass
          moves it, see RigidBody); a thin disc or wheel is a short cylinder.
    """),
    example=rigid_example("""
        # a solid steel rotor with its axis along global x, spinning freely (no gravity)
        oRotor = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                     referenceRotationMatrix=np.eye(3),
                                     initialAngularVelocity=[20.0, 0, 0.5],
                                     inertia=InertiaCylinder(density=7850, length=0.3,
                                                             outerRadius=0.05, axis=0))
    """),
    dependencies=("RigidBody",),
)

INERTIA_SPHERE = Component(
    name="InertiaSphere",
    description=(
        "mass and inertia tensor of a homogeneous solid sphere; for balls that rotate or roll, e.g. a "
        "sphere in contact with a surface"
    ),
    context=text_block("""
        inertia = InertiaSphere(mass=m, radius=r)          # or InertiaSphere(density=rho, radius=r)
        - Give either mass [kg] or density [kg/m^3], not both; radius [m]; J = 2/5*m*r^2 about every axis.
        - Alone it puts the center of mass (sphere center) at the body's reference point.
        - A sphere that only translates (no friction, no rolling) can also be a MassPoint.
    """),
    example=rigid_example("""
        # a spinning ball flying under gravity
        oBall = mbs.CreateRigidBody(referencePosition=[0, 0, 1.0],
                                    initialVelocity=[2.0, 0, 0],
                                    initialAngularVelocity=[0, 10.0, 0],
                                    inertia=InertiaSphere(mass=0.45, radius=0.11),
                                    gravity=[0, 0, -9.81])
    """),
    dependencies=("RigidBody",),
)
