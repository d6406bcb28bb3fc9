"""Level 1-2 components: springs, dampers and the constraints that act like them."""

from __future__ import annotations

from meceng.catalog.common import rigid_example
from meceng.catalog.component import Component, text_block

SPRING_DAMPER = Component(
    name="SpringDamper",
    description=(
        "linear spring-damper acting along the line between two points (mass points, rigid bodies or "
        "ground); for mass-spring(-damper) oscillators, suspensions, elastic ropes"
    ),
    context=text_block("""
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
        - For a spring acting on one coordinate only use CoordinateSpringDamper (on two MarkerNodeCoordinate
          markers: mbs.AddObject(CoordinateSpringDamper(markerNumbers=[mGround, mMassX], stiffness=k,
          damping=d))); for separate x, y, z stiffness use CartesianSpringDamper
          (mbs.CreateCartesianSpringDamper(itemNumbers=[oGround, oMass], stiffness=[kx, ky, kz],
          damping=[dx, dy, dz])).
        - A nonlinear spring law: springForceUserFunction=UFspring, with
          def UFspring(mbs, t, itemNumber, deltaL, deltaL_t, stiffness, damping, force): return the force
          along the line (deltaL = L - referenceLength, deltaL_t its rate; stiffness, damping, force are the
          values given to CreateSpringDamper); it replaces the linear law, e.g.
          return stiffness*deltaL + k3*deltaL**3 + damping*deltaL_t for a hardening spring.
    """),
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreateCartesianSpringDamper(itemNumbers=[oGround, oMass], localPosition0=[x, y, z],
                                        localPosition1=[0, 0, 0], stiffness=[kx, ky, kz],
                                        damping=[dx, dy, dz], offset=[0, 0, 0])
        - force component i = k_i*(p1_i - p0_i - offset_i) + d_i*(v1_i - v0_i) in global x, y, z;
          stiffness [N/m], damping [N*s/m] are 3-vectors; a 0 leaves that direction free.
        - The offset is NOT computed automatically: the spring is relaxed when p1 - p0 = offset. Attach it on
          ground at the body's reference position (then offset=[0, 0, 0]), or set offset = p1 - p0 of the
          reference configuration.
    """),
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreateTorsionalSpringDamper(itemNumbers=[oGround, oBody], position=[x, y, z], axis=[0, 0, 1],
                                        stiffness=k, damping=d, offset=0)
        - position and axis are GLOBAL, in the reference configuration; stiffness [N*m/rad], damping
          [N*m*s/rad]; torque = k*(phi - offset) + d*dphi/dt, phi = relative rotation about the axis measured
          from the reference configuration (relaxed there for offset=0).
        - It constrains nothing: combine it with a RevoluteJoint at the same position and axis, which guides
          the rotation: mbs.CreateRevoluteJoint(itemNumbers=[oGround, oBody], position=[x, y, z], axis=[0, 0, 1]).
        - Only rigid bodies and ground (no mass points).
        - A nonlinear torque law: springTorqueUserFunction=UFtorque, with
          def UFtorque(mbs, t, itemNumber, rotation, angularVelocity, stiffness, damping, offset): return the
          torque (rotation = phi, angularVelocity its rate; stiffness, damping, offset as given); it replaces
          the linear law, e.g. return stiffness*rotation + k3*rotation**3 + damping*angularVelocity.
    """),
    example=rigid_example("""
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
    context=text_block("""
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
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], localPosition0=[0, 0, 0],
                                     localPosition1=[0, 0, 0], distance=L)
        - distance [m]: the constrained length; None (default) = the distance of the two points in the reference
          configuration. The initial positions must satisfy it: compute them from the length and angle,
          e.g. p0 = [L*sin(phi0), -L*cos(phi0), 0] for a pendulum hanging from [0, 0, 0] in the x-y plane.
        - localPosition0/1: attachment points in body-local coordinates (for a ground at [0, 0, 0] the global
          suspension point; for a mass point keep [0, 0, 0]).
        - Works with mass points and rigid bodies; it constrains only the distance, no rotation.
    """),
    example=rigid_example("""
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
    context=text_block("""
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
    example=rigid_example("""
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
    context=text_block("""
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
          markerNumbers=[mGround, mMass])); prefer the one-line function. Every constraint has its own ground
          node: written by hand, do not share one NodePointGround between constraints (the items of the
          model would differ from those of the one-line function).
    """),
    example=rigid_example("""
        # a mass point thrown along x while gravity acts in -y: its y-coordinate is locked
        oMass = mbs.CreateMassPoint(referencePosition=[0, 0, 0], initialVelocity=[1.0, 0, 0.5],
                                    mass=2.0, gravity=[0, -9.81, 0])
        mbs.CreateCoordinateConstraint(itemNumbers=[None, oMass], coordinates=[None, 1])
    """),
)
