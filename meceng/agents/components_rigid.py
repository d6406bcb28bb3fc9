"""Level 1-2 components: mass points, rigid bodies, springs, joints, loads, contacts and sensors.

Each component teaches one Exudyn 1.13 building block the way the ground truths in
``meceng.tasks`` are written: the high-level ``mbs.Create*`` functions with ``itemNumbers=``,
``mass=``, ``inertia=`` and ``gravity=``. Every example is a complete program (the standard
preamble, the model, ``mbs.Assemble()`` and the standard simulation block) that runs in well under
a second and writes no file; ``tests/test_catalog.py`` runs them all.
"""

from __future__ import annotations

import textwrap

from meceng.agents.catalog import Component
from meceng.tasks.base import PREAMBLE, SimSettings


def _text(text: str) -> str:
    return textwrap.dedent(text).strip()


def _example(model: str, end_time: float = 1.0, steps: int = 1000, extra: tuple[str, ...] = ()) -> str:
    """A complete program: preamble, model, assemble, and the same simulation block as the ground truths."""
    sim = SimSettings(end_time=end_time, steps=steps, extra=extra)
    return f"{PREAMBLE}\n{_text(model)}\n\nmbs.Assemble()\n\n{sim.block()}"


GROUND = Component(
    name="Ground",
    description=(
        "fixed ground (the inertial frame); the fixed end of every spring, joint, constraint or contact "
        "that is attached to the environment, a wall, a ceiling or a fixed point"
    ),
    context=_text("""
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        - Returns an ObjectIndex that is used like a body in itemNumbers=[oGround, oBody] of springs, joints
          and constraints (conventionally the ground comes first).
        - Create ONE ground object at [0, 0, 0] and reuse it for all attachments. A fixed point on ground is
          given by localPosition0=[x, y, z] of springs and distance constraints (local to the ground, i.e.
          global coordinates when the ground is at [0, 0, 0]) or by the global position= of joints.
        - The ground has no coordinates: no mass, no gravity, no loads.
        - Do not create a ground object for a system that is attached to nothing (e.g. a free flying body).
        - Coordinate connectors (CoordinateSpringDamper, CoordinateConstraint) need a ground NODE instead
          (NodePointGround), see there.
    """),
    example=_example("""
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
    context=_text("""
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
          (use RigidBody for that).
    """),
    example=_example("""
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
    context=_text("""
        oBody = mbs.CreateRigidBody(referencePosition=[x, y, z], referenceRotationMatrix=np.eye(3),
                                    initialVelocity=[0, 0, 0], initialAngularVelocity=[0, 0, 0],
                                    inertia=InertiaCuboid(density=rho, sideLengths=[a, b, c]),
                                    gravity=[0, -9.81, 0])
        - inertia: a RigidBodyInertia object that gives mass AND inertia tensor: InertiaCuboid, InertiaCylinder,
          InertiaSphere, InertiaRodX(mass, length), InertiaMassPoint(mass); there is no mass= argument.
          With these helpers the center of mass is the body's reference point, so referencePosition is the
          global position of the center of mass.
        - referenceRotationMatrix: rotation from local body axes to global axes in the reference configuration,
          e.g. RotationMatrixZ(phi) with phi in rad (also RotationMatrixX/Y), or np.eye(3) for no rotation.
        - initialVelocity [m/s] and initialAngularVelocity [rad/s] are global vectors.
        - gravity: gravity acceleration vector [m/s^2] for this body (its weight); add no extra force for it.
        - Joints, springs and constraints are defined in the reference configuration, so put the body at
          its start pose with referencePosition/referenceRotationMatrix.
        - Returns the body's ObjectIndex; its node is mbs.GetObject(oBody)['nodeNumber'].
    """),
    example=_example("""
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
    context=_text("""
        inertia = InertiaCuboid(density=rho, sideLengths=[a, b, c])
        - density [kg/m^3]; sideLengths [m] along the body's LOCAL x-, y- and z-axes; mass = rho*a*b*c.
        - The center of mass is the body's reference point (referencePosition of CreateRigidBody).
        - If a mass m is given instead of a density, use density=m/(a*b*c).
        - Orient the local axes with referenceRotationMatrix, e.g. a link with its long side a along local x
          that is rotated by phi in the x-y plane: referenceRotationMatrix=RotationMatrixZ(phi).
        - Pass the object as inertia= to CreateRigidBody; inertia.Mass() returns the mass.
    """),
    example=_example("""
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
    context=_text("""
        inertia = InertiaCylinder(density=rho, length=L, outerRadius=r, axis=0, innerRadius=0)
        - axis: the cylinder axis as an integer index of the LOCAL body axes: 0 = x, 1 = y, 2 = z (not a vector).
        - density [kg/m^3], length and radii [m]; innerRadius > 0 gives a hollow cylinder (tube, ring).
        - mass = rho*pi*(r^2 - ri^2)*L; solid: J_axis = m*r^2/2. If a mass m is given, density=m/(pi*r^2*L).
        - The center of mass is the body's reference point; a thin disc or wheel is a short cylinder.
    """),
    example=_example("""
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
    context=_text("""
        inertia = InertiaSphere(mass=m, radius=r)          # or InertiaSphere(density=rho, radius=r)
        - Give either mass [kg] or density [kg/m^3], not both; radius [m]; J = 2/5*m*r^2 about every axis.
        - The center of mass (sphere center) is the body's reference point.
        - A sphere that only translates (no friction, no rolling) can also be a MassPoint.
    """),
    example=_example("""
        # a spinning ball flying under gravity
        oBall = mbs.CreateRigidBody(referencePosition=[0, 0, 1.0],
                                    initialVelocity=[2.0, 0, 0],
                                    initialAngularVelocity=[0, 10.0, 0],
                                    inertia=InertiaSphere(mass=0.45, radius=0.11),
                                    gravity=[0, 0, -9.81])
    """),
    dependencies=("RigidBody",),
)

SPRING_DAMPER = Component(
    name="SpringDamper",
    description=(
        "linear spring-damper acting along the line between two points (mass points, rigid bodies or "
        "ground); for mass-spring(-damper) oscillators, suspensions, elastic ropes"
    ),
    context=_text("""
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], localPosition0=[0, 0, 0], localPosition1=[0, 0, 0],
                               stiffness=k, damping=d)
        - stiffness k [N/m], damping d [N*s/m]; force = k*(L - referenceLength) + d*dL/dt along the line between
          the two attachment points.
        - referenceLength (relaxed length) defaults to the distance of the two attachment points in the
          reference configuration (referencePosition of the bodies; initialDisplacement is NOT included).
          Set referenceLength= only if the relaxed length differs from that distance.
        - So: place the masses at their relaxed (reference) positions and give the initial deflection with
          initialDisplacement of CreateMassPoint.
        - localPosition0/1: attachment points in body-local coordinates (for a ground at [0, 0, 0] the global
          point; for a mass point keep [0, 0, 0]); itemNumbers may also be two bodies.
        - For a spring acting on one coordinate only use CoordinateSpringDamper; for separate x, y, z stiffness
          CartesianSpringDamper.
    """),
    example=_example("""
        # two masses in a chain: ground -- spring 1 -- mass 1 -- spring 2 -- mass 2, along x
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass1 = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], mass=1.0)
        oMass2 = mbs.CreateMassPoint(referencePosition=[2.0, 0, 0],
                                     initialDisplacement=[0.1, 0, 0], mass=0.5)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass1], stiffness=1000.0, damping=2.0)
        mbs.CreateSpringDamper(itemNumbers=[oMass1, oMass2], stiffness=500.0, damping=1.0)
    """),
    dependencies=("Ground",),
)

CARTESIAN_SPRING_DAMPER = Component(
    name="CartesianSpringDamper",
    description=(
        "spring-damper with separate stiffness and damping in the global x-, y- and z-directions between two "
        "points; for elastic supports and bushings with direction-dependent stiffness"
    ),
    context=_text("""
        mbs.CreateCartesianSpringDamper(itemNumbers=[oGround, oMass], localPosition0=[x, y, z],
                                        localPosition1=[0, 0, 0], stiffness=[kx, ky, kz],
                                        damping=[dx, dy, dz], offset=[0, 0, 0])
        - force component i = k_i*(p1_i - p0_i - offset_i) + d_i*(v1_i - v0_i) in global x, y, z;
          stiffness [N/m], damping [N*s/m] are 3-vectors; a 0 leaves that direction free.
        - The offset is NOT computed automatically: the spring is relaxed when p1 - p0 = offset. Attach it on
          ground at the body's reference position (then offset=[0, 0, 0]), or set offset = p1 - p0 of the
          reference configuration.
    """),
    example=_example("""
        # a mass point elastically held at the ground point [1, 0, 0], stiffer in y than in x
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], initialVelocity=[0.5, 0.5, 0],
                                    mass=1.0, gravity=[0, -9.81, 0])
        mbs.CreateCartesianSpringDamper(itemNumbers=[oGround, oMass], localPosition0=[1.0, 0, 0],
                                        stiffness=[200.0, 2000.0, 500.0], damping=[1.0, 5.0, 1.0])
    """),
    dependencies=("Ground",),
)

TORSIONAL_SPRING_DAMPER = Component(
    name="TorsionalSpringDamper",
    description=(
        "rotational spring-damper about one axis between two rigid bodies or a rigid body and ground, torque "
        "proportional to the relative rotation; for torsional oscillators and springs at hinges"
    ),
    context=_text("""
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oBody], position=[x, y, z], axis=[0, 0, 1],
                                        stiffness=k, damping=d, offset=0)
        - position and axis are GLOBAL, in the reference configuration; stiffness [N*m/rad], damping
          [N*m*s/rad]; torque = k*(phi - offset) + d*dphi/dt, phi = relative rotation about the axis measured
          from the reference configuration (relaxed there for offset=0).
        - It constrains nothing: combine it with a RevoluteJoint at the same position and axis, which guides
          the rotation.
        - Only rigid bodies and ground (no mass points).
    """),
    example=_example("""
        # a disc on a revolute joint about global z with a torsional spring to ground
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    initialAngularVelocity=[0, 0, 2.0],
                                    inertia=InertiaCylinder(density=7850, length=0.02,
                                                            outerRadius=0.1, axis=2))
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1],
                                        stiffness=50.0, damping=0.1)
    """),
    dependencies=("Ground", "RigidBody"),
)

RIGID_BODY_SPRING_DAMPER = Component(
    name="RigidBodySpringDamper",
    description=(
        "six-dimensional spring-damper (3 translational and 3 rotational stiffnesses and dampings) between two "
        "rigid bodies or a rigid body and ground; for elastic mounts, bushings, flexible supports"
    ),
    context=_text("""
        mbs.CreateRigidBodySpringDamper(itemNumbers=[oGround, oBody], localPosition0=[x, y, z],
                                        localPosition1=[0, 0, 0],
                                        stiffness=np.diag([kx, ky, kz, krx, kry, krz]),
                                        damping=np.diag([dx, dy, dz, drx, dry, drz]))
        - stiffness and damping are 6x6 matrices (np.diag for uncoupled springs): entries 0-2 translational
          [N/m], [N*s/m], entries 3-5 rotational about x, y, z [N*m/rad], [N*m*s/rad]; with the default
          rotationMatrixJoint=np.eye(3) the directions are the global axes of the reference configuration.
        - Relaxed in the reference configuration when the two attachment points coincide there: put the point
          on ground (localPosition0) at the body's attachment point (localPosition1, local to the body).
        - Only rigid bodies and ground (no mass points).
    """),
    example=_example("""
        # a block elastically mounted to ground at its center of mass [0, 0, 0.5]
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBlock = mbs.CreateRigidBody(referencePosition=[0, 0, 0.5],
                                     initialAngularVelocity=[0.5, 0, 0],
                                     inertia=InertiaCuboid(density=1000, sideLengths=[0.2, 0.2, 0.2]),
                                     gravity=[0, 0, -9.81])
        mbs.CreateRigidBodySpringDamper(itemNumbers=[oGround, oBlock], localPosition0=[0, 0, 0.5],
                                        localPosition1=[0, 0, 0],
                                        stiffness=np.diag([1e4, 1e4, 1e4, 100, 100, 100]),
                                        damping=np.diag([10, 10, 10, 0.1, 0.1, 0.1]))
    """),
    dependencies=("Ground", "RigidBody"),
)

DISTANCE_CONSTRAINT = Component(
    name="DistanceConstraint",
    description=(
        "keeps the distance between two points constant (ideal massless rigid rod or taut string); for "
        "mass-point pendulums, double pendulums, Newton's cradle, linkages of mass points"
    ),
    context=_text("""
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], localPosition0=[0, 0, 0],
                                     localPosition1=[0, 0, 0], distance=L)
        - distance [m]: the constrained length; None (default) = the distance of the two points in the reference
          configuration. The initial positions must satisfy it: compute them from the length and angle,
          e.g. p0 = [L*sin(phi0), -L*cos(phi0), 0] for a pendulum hanging from [0, 0, 0] in the x-y plane.
        - localPosition0/1: attachment points in body-local coordinates (for a ground at [0, 0, 0] the global
          suspension point; for a mass point keep [0, 0, 0]).
        - Works with mass points and rigid bodies; it constrains only the distance, no rotation.
    """),
    example=_example("""
        # a mathematical pendulum: mass point on a massless rod of length 0.8 m, 20 degrees deflected
        length = 0.8
        phi0 = 20 * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[length * np.sin(phi0), -length * np.cos(phi0), 0],
                                    mass=1.0, gravity=[0, -9.81, 0])
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], distance=length)
    """),
    dependencies=("Ground",),
)

COORDINATE_SPRING_DAMPER = Component(
    name="CoordinateSpringDamper",
    description=(
        "spring-damper acting on one single coordinate (e.g. only the x-displacement of a mass point) "
        "against ground or another coordinate; for one-dimensional oscillators written in coordinates"
    ),
    context=_text("""
        There is no mbs.Create... helper; use a coordinate marker for each side and the connector:
        nMass = mbs.GetObject(oMass)['nodeNumber']
        nGround = mbs.AddNode(NodePointGround())
        mGround = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nGround, coordinate=0))
        mMassX = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nMass, coordinate=0))
        mbs.AddObject(CoordinateSpringDamper(markerNumbers=[mGround, mMassX], stiffness=k, damping=d, offset=0))
        - coordinate: index of the node coordinate: 0 = x, 1 = y, 2 = z displacement of a mass point.
        - force = k*(q1 - q0 - offset) + d*(dq1 - dq0) with q the DISPLACEMENT coordinates (from the reference
          position, reference values are not included): the spring is relaxed at the reference position for
          offset=0, whatever the referencePosition is.
        - The ground side needs a ground NODE (NodePointGround), not CreateGround: an object has no coordinates.
        - It acts only in that one direction; the other directions stay free.
    """),
    example=_example("""
        # a mass point with a spring-damper on its x-coordinate only, released displaced by 0.1 m
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], initialDisplacement=[0.1, 0, 0], mass=2.0)
        nMass = mbs.GetObject(oMass)['nodeNumber']
        nGround = mbs.AddNode(NodePointGround())
        mGround = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nGround, coordinate=0))
        mMassX = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nMass, coordinate=0))
        mbs.AddObject(CoordinateSpringDamper(markerNumbers=[mGround, mMassX], stiffness=800.0, damping=2.0))
    """),
)

COORDINATE_CONSTRAINT = Component(
    name="CoordinateConstraint",
    description=(
        "fixes one single coordinate of a mass point or body (e.g. locks its y-displacement) or couples two "
        "coordinates; for guiding a mass along a line or plane"
    ),
    context=_text("""
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oMass], coordinates=[None, 1], offset=0)
        - Constrains factor1*q1 - q0 = offset, q0 and q1 the coordinates of itemNumbers[0] and [1]; None in
          itemNumbers with coordinate None is the ground (q = 0), so the example keeps the y-coordinate at 0.
        - coordinates: index of the coordinate: of a mass point 0 = x, 1 = y, 2 = z; of a body counted over its
          node's coordinates; of a node (NodeIndex in itemNumbers) its coordinate index.
        - q are DISPLACEMENT coordinates (from the reference position): offset=0 keeps the coordinate at its
          reference value.
        - The function creates a ground node, two MarkerNodeCoordinate markers and a CoordinateConstraint; it
          is equivalent to nGround = mbs.AddNode(NodePointGround()) + markers
          MarkerNodeCoordinate(nodeNumber=..., coordinate=...) + mbs.AddObject(CoordinateConstraint(
          markerNumbers=[mGround, mMass])); prefer the one-line function.
    """),
    example=_example("""
        # a mass point thrown along x while gravity acts in -y: its y-coordinate is locked
        oMass = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[1.0, 0, 0.5],
                                    mass=2.0, gravity=[0, -9.81, 0])
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oMass], coordinates=[None, 1])
    """),
)

REVOLUTE_JOINT = Component(
    name="RevoluteJoint",
    description=(
        "ideal hinge between two rigid bodies or a rigid body and ground, allowing only the rotation about "
        "one axis; for physical pendulums, cranks, links of mechanisms, doors, wheels on axles"
    ),
    context=_text("""
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oBody], position=[x, y, z], axis=[0, 0, 1])
        - position: GLOBAL joint point, axis: GLOBAL rotation axis, both for the reference configuration
          (referencePosition/referenceRotationMatrix of the bodies); the joint point is usually not the
          center of mass (e.g. the upper end of a pendulum link).
        - Only rigid bodies and ground; for a mass point on a massless rod use DistanceConstraint.
        - In 3D a closed loop of revolute joints (four-bar, slider-crank) is over-constrained: close the loop
          with a SphericalJoint with constrainedAxes=[1, 1, 0] (planar x-y mechanism) instead.
    """),
    example=_example("""
        # a physical pendulum: cuboid link hinged at its upper end [0, 0, 0], swinging in the x-y plane
        length = 0.6
        phi0 = 30 * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink = mbs.CreateRigidBody(referencePosition=[0.5 * length * np.sin(phi0),
                                                       -0.5 * length * np.cos(phi0), 0],
                                    referenceRotationMatrix=RotationMatrixZ(phi0),
                                    inertia=InertiaCuboid(density=2700, sideLengths=[0.05, length, 0.02]),
                                    gravity=[0, -9.81, 0])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1])
    """),
    dependencies=("Ground", "RigidBody"),
)

PRISMATIC_JOINT = Component(
    name="PrismaticJoint",
    description=(
        "ideal sliding joint between two rigid bodies or a rigid body and ground, allowing only the "
        "translation along one axis; for sliders, pistons, carts on rails, blocks on guides"
    ),
    context=_text("""
        mbs.CreatePrismaticJoint(itemNumbers=[oGround, oSlider], position=[x, y, z], axis=[1, 0, 0])
        - axis: GLOBAL sliding direction, position: GLOBAL joint point (usually the slider's reference
          position), both for the reference configuration; all rotations and the other two translations are
          locked.
        - Only rigid bodies and ground (no mass points).
    """),
    example=_example("""
        # a block sliding without friction down a guide inclined by 30 degrees in the x-y plane
        alpha = 30 * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBlock = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                     referenceRotationMatrix=RotationMatrixZ(-alpha),
                                     inertia=InertiaCuboid(density=1000, sideLengths=[0.2, 0.1, 0.1]),
                                     gravity=[0, -9.81, 0])
        mbs.CreatePrismaticJoint(itemNumbers=[oGround, oBlock], position=[0, 0, 0],
                                 axis=[np.cos(alpha), -np.sin(alpha), 0])
    """),
    dependencies=("Ground", "RigidBody"),
)

SPHERICAL_JOINT = Component(
    name="SphericalJoint",
    description=(
        "ideal ball joint: two bodies (or a body and ground) share one point, all rotations free; for "
        "spherical pendulums, ball joints, and to close planar loops without redundant constraints"
    ),
    context=_text("""
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oBody], position=[x, y, z], constrainedAxes=[1, 1, 1])
        - position: GLOBAL joint point in the reference configuration.
        - constrainedAxes: which GLOBAL translations are locked (1) or free (0); e.g. [1, 1, 0] fixes only x and
          y, to close a planar x-y loop (slider-crank, four-bar) without redundant constraints.
        - Works with rigid bodies, mass points and ground.
    """),
    example=_example("""
        # a rod (long side along local z) hanging from the ground point [0, 0, 0] by a ball joint,
        # deflected by 20 degrees towards +x and released from rest
        length = 0.5
        phi0 = 20 * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oRod = mbs.CreateRigidBody(referencePosition=[0.5 * length * np.sin(phi0), 0,
                                                      -0.5 * length * np.cos(phi0)],
                                   referenceRotationMatrix=RotationMatrixY(-phi0),
                                   inertia=InertiaCuboid(density=7850, sideLengths=[0.02, 0.02, length]),
                                   gravity=[0, 0, -9.81])
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oRod], position=[0, 0, 0])
    """),
    dependencies=("Ground", "RigidBody"),
)

GENERIC_JOINT = Component(
    name="GenericJoint",
    description=(
        "joint that locks any chosen subset of the three relative translations and three relative rotations "
        "(e.g. a rigid weld, or a bearing that only fixes lateral directions); for joints that are not "
        "revolute, prismatic or spherical"
    ),
    context=_text("""
        mbs.CreateGenericJoint(itemNumbers=[oGround, oBody], position=[x, y, z], rotationMatrixAxes=np.eye(3),
                               constrainedAxes=[1, 1, 1, 1, 1, 1])
        - constrainedAxes: 6 flags [x, y, z, rot x, rot y, rot z] of the joint frame, 1 = locked, 0 = free;
          [1, 1, 1, 1, 1, 1] = rigid connection (weld), [1, 1, 1, 1, 1, 0] = revolute about the joint z-axis,
          [0, 1, 1, 0, 0, 0] = only the y and z translations locked (a floating bearing along x).
        - position: GLOBAL joint point; rotationMatrixAxes: GLOBAL orientation of the joint frame (its columns
          are the joint x, y, z axes), both for the reference configuration; np.eye(3) = global axes.
        - Only rigid bodies and ground. Avoid locking a direction twice (redundant constraints), e.g. when a
          second bearing supports a shaft that is already held by a spherical joint.
    """),
    example=_example("""
        # a flap (plate) hinged at its upper edge: the generic joint locks everything except the rotation
        # about the global x-axis; released 40 degrees from the vertical, gravity in negative z-direction
        height = 0.3
        phi0 = 40 * np.pi / 180
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oFlap = mbs.CreateRigidBody(referencePosition=[0, 0.5 * height * np.sin(phi0),
                                                       -0.5 * height * np.cos(phi0)],
                                    referenceRotationMatrix=RotationMatrixX(phi0),
                                    inertia=InertiaCuboid(density=2700, sideLengths=[0.4, 0.01, height]),
                                    gravity=[0, 0, -9.81])
        mbs.CreateGenericJoint(itemNumbers=[oGround, oFlap], position=[0, 0, 0],
                               rotationMatrixAxes=np.eye(3), constrainedAxes=[1, 1, 1, 0, 1, 1])
    """),
    dependencies=("Ground", "RigidBody"),
)

ROLLING_DISC = Component(
    name="RollingDisc",
    description=(
        "ideal rolling without slipping of a rigid disc or wheel on a flat ground plane (non-holonomic "
        "constraint); for rolling wheels, coins, discs rolling on the floor"
    ),
    context=_text("""
        mbs.CreateRollingDisc(bodyNumbers=[oGround, oWheel], axisPosition=[0, 0, 0], axisVector=[1, 0, 0],
                              discRadius=r, planePosition=[0, 0, 0], planeNormal=[0, 0, 1])
        - This function takes bodyNumbers= (not itemNumbers=): ground first, then the wheel (a rigid body).
        - axisPosition (disc center) and axisVector (disc axis) are in LOCAL wheel coordinates: [0, 0, 0] and
          the cylinder axis, e.g. [1, 0, 0] for InertiaCylinder(..., axis=0); planePosition and planeNormal
          are in ground coordinates (the floor z = 0 with normal [0, 0, 1]).
        - The wheel must touch the plane initially: its center at height r above it, e.g.
          referencePosition=[x, y, r], disc axis parallel to the plane.
        - Start consistently with rolling: axis x, rolling with speed v in +y needs initialVelocity=[0, v, 0]
          and initialAngularVelocity=[-v/r, 0, 0] (the contact point has zero velocity).
        - The constraint is ideal: no slip, no rolling resistance; the wheel is a rigid body with gravity= as usual.
        - constrainedAxes=[lateral, longitudinal, normal] (default [1, 1, 1]) switches single directions of the
          contact constraint off, e.g. to avoid redundant constraints when several wheels share one chassis.
    """),
    example=_example("""
        # an upright wheel (axis along x) rolling in +y direction on the floor z = 0
        r = 0.2
        v = 1.0
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oWheel = mbs.CreateRigidBody(referencePosition=[0, 0, r],
                                     initialVelocity=[0, v, 0],
                                     initialAngularVelocity=[-v / r, 0, 0],
                                     inertia=InertiaCylinder(density=7850, length=0.02, outerRadius=r, axis=0),
                                     gravity=[0, 0, -9.81])
        mbs.CreateRollingDisc(bodyNumbers=[oGround, oWheel], axisPosition=[0, 0, 0], axisVector=[1, 0, 0],
                              discRadius=r, planePosition=[0, 0, 0], planeNormal=[0, 0, 1])
    """),
    dependencies=("Ground", "RigidBody"),
)

FORCE = Component(
    name="Force",
    description=(
        "constant force vector applied to a mass point or a rigid body (optionally at a point of the body); "
        "for applied external loads, not for gravity"
    ),
    context=_text("""
        mbs.CreateForce(itemNumber=oBody, loadVector=[Fx, Fy, Fz], localPosition=[0, 0, 0], bodyFixed=False)
        - itemNumber (singular) is the body (mass point or rigid body); returns a LoadIndex.
        - loadVector [N] in GLOBAL coordinates; bodyFixed=True: in body-local coordinates, rotating with the
          body (follower force).
        - localPosition: point of application in body-local coordinates (rigid bodies; off the center of mass
          it also creates a moment); keep [0, 0, 0] for mass points.
        - Gravity is NOT a force load: give it with gravity= of CreateMassPoint/CreateRigidBody.
        - A time-dependent force uses loadVectorUserFunction, see LoadUserFunction.
    """),
    example=_example("""
        # a mass point on a spring to ground, pulled by a constant force of 20 N in x-direction
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], mass=1.0)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=1000.0, damping=5.0)
        mbs.CreateForce(itemNumber=oMass, loadVector=[20.0, 0, 0])
    """),
)

TORQUE = Component(
    name="Torque",
    description=(
        "constant torque (moment) vector applied to a rigid body; for drive torques of cranks, rotors, "
        "motors and external moments"
    ),
    context=_text("""
        mbs.CreateTorque(itemNumber=oBody, loadVector=[Tx, Ty, Tz], bodyFixed=False)
        - loadVector: torque [N*m] in GLOBAL coordinates (bodyFixed=True: body-local, rotating with the body);
          e.g. a drive about the global z-axis: [0, 0, T].
        - Rigid bodies only (a mass point has no rotation); itemNumber (singular) is the body.
        - A time-dependent torque uses loadVectorUserFunction, see LoadUserFunction.
    """),
    example=_example("""
        # a disc on a revolute joint about global z, driven from rest by a constant torque of 0.5 N*m
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oDisc = mbs.CreateRigidBody(referencePosition=[0, 0, 0],
                                    inertia=InertiaCylinder(density=7850, length=0.02,
                                                            outerRadius=0.1, axis=2))
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorque(itemNumber=oDisc, loadVector=[0, 0, 0.5])
    """),
    dependencies=("RigidBody",),
)

LOAD_USER_FUNCTION = Component(
    name="LoadUserFunction",
    description=(
        "time-dependent force or torque given by a Python function of time (harmonic excitation, ramps, "
        "pulses, switched loads)"
    ),
    context=_text("""
        def UFforce(mbs, t, loadVector):
            return [F0 * np.sin(omega * t), 0, 0]
        mbs.CreateForce(itemNumber=oMass, loadVector=[F0, 0, 0], loadVectorUserFunction=UFforce)
        - Signature (mbs, t, loadVector) -> list of 3 floats: t is the simulation time [s]; loadVector is the
          constant loadVector given to CreateForce (a list); the returned vector replaces it in every step.
        - The same works for mbs.CreateTorque(itemNumber=oBody, loadVector=..., loadVectorUserFunction=UFtorque).
        - Define the function before the Create call; use np.sin, np.cos, if/else on t; return a plain list.
        - Do not print or write files inside the function: it is called many times per time step.
    """),
    example=_example("""
        # a mass-spring oscillator excited by the harmonic force F0*sin(omega*t) in x-direction
        F0 = 10.0
        omega = 2 * np.pi * 3.0

        def UFforce(mbs, t, loadVector):
            return [F0 * np.sin(omega * t), 0, 0]

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[1.0, 0, 0], mass=1.0)
        mbs.CreateSpringDamper(itemNumbers=[oGround, oMass], stiffness=400.0, damping=2.0)
        mbs.CreateForce(itemNumber=oMass, loadVector=[F0, 0, 0], loadVectorUserFunction=UFforce)
    """),
    dependencies=("Force",),
)

SPHERE_SPHERE_CONTACT = Component(
    name="SphereSphereContact",
    description=(
        "penalty contact (impact) between two spheres attached to mass points or rigid bodies, with contact "
        "stiffness, damping and restitution coefficient; for colliding balls, Newton's cradle"
    ),
    context=_text("""
        mbs.CreateSphereSphereContact(itemNumbers=[oBall0, oBall1], spheresRadii=[r0, r1], contactStiffness=k,
                                      contactDamping=0, impactModel=2, restitutionCoefficient=e)
        - The sphere centers are the items' reference points (mass point or rigid body center); spheresRadii [m],
          contactStiffness [N/m], contactDamping [N*s/m]. localPosition0/localPosition1 shift a sphere center
          in the item's frame, e.g. a ground sphere centered below the floor: itemNumbers=[oGround, oBall],
          localPosition0=[0, 0, -R].
        - restitutionCoefficient is only used with impactModel=2 (or 1); with the default impactModel=0 it is
          ignored and only the linear contactDamping acts. For a given e use impactModel=2 and
          contactDamping=0.
        - One contact object per pair of spheres that can touch (e.g. neighbours 0-1, 1-2, 2-3).
        - dynamicFriction > 0 needs rigid bodies; without friction mass points are enough.
        - Contact needs small time steps (about 1e-4 s); the solver may also need
          simulationSettings.timeIntegration.discontinuous.iterationTolerance = 1e-3.
    """),
    example=_example(
        """
        # two balls (mass points) colliding head-on along x, restitution coefficient 0.8
        r = 0.05
        oBall0 = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[1.0, 0, 0], mass=0.2)
        oBall1 = mbs.CreateMassPoint(referencePosition=[0.15, 0, 0], mass=0.2)
        mbs.CreateSphereSphereContact(itemNumbers=[oBall0, oBall1], spheresRadii=[r, r],
                                      contactStiffness=1e5, contactDamping=0,
                                      impactModel=2, restitutionCoefficient=0.8)
        """,
        end_time=0.2,
        steps=2000,
    ),
)

SPHERE_TRIANGLE_CONTACT = Component(
    name="SphereTriangleContact",
    description=(
        "penalty contact between a rigid sphere and a triangle fixed to ground or to a body, with stiffness, "
        "damping and restitution; for a ball bouncing or rolling on a flat (triangular) surface"
    ),
    context=_text("""
        mbs.CreateSphereTriangleContact(itemNumbers=[oBall, oGround], sphereRadius=r,
                                        trianglePoints=exu.Vector3DList([[0, 0, 0], [1, 0, 0], [0, 1, 0]]),
                                        contactStiffness=k, contactDamping=0, impactModel=2,
                                        restitutionCoefficient=e)
        - itemNumbers[0] is the sphere and must be a RIGID BODY (e.g. with InertiaSphere); a mass point fails
          in mbs.Assemble(). itemNumbers[1] carries the triangle (usually the ground object).
        - trianglePoints: exactly 3 points in the LOCAL coordinates of itemNumbers[1], wrapped in
          exu.Vector3DList([...]); a plain list or numpy array is rejected with a type error.
        - Make the triangle large enough to cover where the sphere touches; includeEdges=7 (default) also
          gives contact with the three edges.
        - restitutionCoefficient needs impactModel=2 (with contactDamping=0); dynamicFriction [-] is optional.
        - Use small time steps (about 1e-4 s) for impacts.
    """),
    example=_example(
        """
        # a ball dropped from 0.2 m onto a triangle in the floor plane z = 0, restitution 0.7
        r = 0.05
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oBall = mbs.CreateRigidBody(referencePosition=[0.2, 0.2, 0.2],
                                    inertia=InertiaSphere(mass=0.5, radius=r),
                                    gravity=[0, 0, -9.81])
        mbs.CreateSphereTriangleContact(itemNumbers=[oBall, oGround], sphereRadius=r,
                                        trianglePoints=exu.Vector3DList([[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]),
                                        contactStiffness=1e5, contactDamping=0,
                                        impactModel=2, restitutionCoefficient=0.7)
        """,
        end_time=0.5,
        steps=5000,
    ),
    dependencies=("Ground", "RigidBody"),
)

SENSOR = Component(
    name="Sensor",
    description=(
        "records a body or node quantity (position, displacement, velocity, rotation, angular velocity, ...) "
        "or a connector force over time in memory; when a result has to be measured or evaluated"
    ),
    context=_text("""
        sPos = mbs.AddSensor(SensorBody(bodyNumber=oBody, localPosition=[0, 0, 0], storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Position))
        sVel = mbs.AddSensor(SensorNode(nodeNumber=nMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Velocity))
        - Add sensors before mbs.Assemble(); after mbs.SolveDynamic(...) read them with
          data = mbs.GetSensorStoredData(sPos): a numpy array with columns [t, x, y, z], one row every
          simulationSettings.solution.sensors.writePeriod (default 0.01 s).
        - Always storeInternal=True and no fileName: the program must not write files (no sensor files, no
          plots, no prints needed).
        - OutputVariableType for bodies and nodes: Position, Displacement, Velocity, Acceleration; rigid bodies
          also Rotation, RotationMatrix, AngularVelocity. SensorBody measures at localPosition (body-local).
        - Connector or joint forces: SensorObject(objectNumber=oJoint, storeInternal=True,
          outputVariableType=exu.OutputVariableType.Force).
    """),
    example=_example("""
        # a mass point pendulum with sensors for the position, the node velocity and the rod force
        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oMass = mbs.CreateMassPoint(referencePosition=[0.5, 0, 0], mass=1.0, gravity=[0, -9.81, 0])
        oRod = mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass])
        nMass = mbs.GetObject(oMass)['nodeNumber']
        sPos = mbs.AddSensor(SensorBody(bodyNumber=oMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Position))
        sVel = mbs.AddSensor(SensorNode(nodeNumber=nMass, storeInternal=True,
                                        outputVariableType=exu.OutputVariableType.Velocity))
        sForce = mbs.AddSensor(SensorObject(objectNumber=oRod, storeInternal=True,
                                            outputVariableType=exu.OutputVariableType.Force))
    """),
)


JOINT_PD_CONTROL = Component(
    name="JointPDControl",
    description=(
        "PD-controlled joint drive that makes the angle of a revolute joint follow a prescribed trajectory "
        "q_d(t) (torsional spring-damper with a torque user function); for robot joints, servo drives, "
        "prescribed joint motion"
    ),
    context=_text("""
        def UFjoint(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
            qd, vd = JointTrajectory(t)        # desired joint angle [rad] and rate [rad/s] at time t
            return stiffness * (rotation - qd) + damping * (angularVelocity - vd)
        mbs.CreateRevoluteJoint(itemNumbers=[oParent, oChild], position=p, axis=a)
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oParent, oChild], position=p, axis=a,
                                        stiffness=kP, damping=kD, springTorqueUserFunction=UFjoint)
        - The torsional spring-damper measures the joint angle itself: rotation [rad] is the rotation of
          itemNumbers[1] relative to itemNumbers[0] about the GLOBAL axis a (right-hand rule), zero in the reference
          configuration and counted over several turns; angularVelocity [rad/s] is its rate.
        - The returned value replaces the connector torque k*(rotation - offset) + d*angularVelocity; it acts on
          both items (drive and reaction), so the function above is the PD control torque
          tau = kP*(qd - q) + kD*(vd - q') with the gains passed as stiffness and damping.
        - The joint angle is measured from the reference configuration: build the bodies in the start pose and
          give qd relative to it (subtract the start angle if the trajectory is given in absolute angles).
        - Signature exactly (mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset) -> float;
          one revolute joint + one torsional spring-damper (same items, position and axis) per driven joint, each
          with its own function (e.g. created by a factory function with the joint's trajectory data).
        - The connector enters the solver's Jacobian, so also stiff gains converge without special solver settings.
    """),
    example=_example("""
        # a link (long side along local x) on a revolute joint about global z, moved from 0 to 60 degrees by
        # a cosine trajectory in 0.8 s and then held; gravity in -z is carried by the joint
        qEnd = 60 * np.pi / 180
        duration = 0.8

        def JointTrajectory(t):
            if t < duration:
                return (qEnd * (1 - np.cos(np.pi * t / duration)) / 2,
                        qEnd * np.pi / (2 * duration) * np.sin(np.pi * t / duration))
            return qEnd, 0.0

        def UFjoint(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset):
            qd, vd = JointTrajectory(t)
            return stiffness * (rotation - qd) + damping * (angularVelocity - vd)

        oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
        oLink = mbs.CreateRigidBody(referencePosition=[0.25, 0, 0],
                                    inertia=InertiaCuboid(density=2700, sideLengths=[0.5, 0.05, 0.05]),
                                    gravity=[0, 0, -9.81])
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1])
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oLink], position=[0, 0, 0], axis=[0, 0, 1],
                                        stiffness=200.0, damping=10.0, springTorqueUserFunction=UFjoint)
    """),
    dependencies=("RevoluteJoint", "TorsionalSpringDamper"),
)


COMPONENTS: tuple[Component, ...] = (
    GROUND,
    MASS_POINT,
    RIGID_BODY,
    INERTIA_CUBOID,
    INERTIA_CYLINDER,
    INERTIA_SPHERE,
    SPRING_DAMPER,
    CARTESIAN_SPRING_DAMPER,
    TORSIONAL_SPRING_DAMPER,
    RIGID_BODY_SPRING_DAMPER,
    DISTANCE_CONSTRAINT,
    COORDINATE_SPRING_DAMPER,
    COORDINATE_CONSTRAINT,
    REVOLUTE_JOINT,
    PRISMATIC_JOINT,
    SPHERICAL_JOINT,
    GENERIC_JOINT,
    ROLLING_DISC,
    FORCE,
    TORQUE,
    LOAD_USER_FUNCTION,
    SPHERE_SPHERE_CONTACT,
    SPHERE_TRIANGLE_CONTACT,
    SENSOR,
    JOINT_PD_CONTROL,
)
