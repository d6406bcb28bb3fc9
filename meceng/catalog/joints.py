"""Level 1-2 components: joints between bodies and rolling contact."""

from __future__ import annotations

from meceng.catalog.common import rigid_example
from meceng.catalog.component import Component, text_block

REVOLUTE_JOINT = Component(
    name="RevoluteJoint",
    description=(
        "ideal hinge between two rigid bodies or a rigid body and ground, allowing only the rotation about "
        "one axis; for physical pendulums, cranks, links of mechanisms, doors, wheels on axles"
    ),
    context=text_block("""
        mbs.CreateRevoluteJoint(itemNumbers=[oGround, oBody], position=[x, y, z], axis=[0, 0, 1])
        - position: GLOBAL joint point, axis: GLOBAL rotation axis, both for the reference configuration
          (referencePosition/referenceRotationMatrix of the bodies); the joint point is usually not the
          center of mass (e.g. the upper end of a pendulum link).
        - Only rigid bodies and ground; for a mass point on a massless rod use DistanceConstraint
          (mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass], distance=L)); a joint at a flexible
          part's interface is an InterfaceJoint.
        - In 3D a closed loop of revolute joints (four-bar, slider-crank) is over-constrained: close the loop
          with a SphericalJoint with constrainedAxes=[1, 1, 0] (planar x-y mechanism) instead of its last
          revolute joint: mbs.CreateSphericalJoint(itemNumbers=[oCoupler, oRocker], position=[x, y, z],
          constrainedAxes=[1, 1, 0]) (x and y locked, z free: the loop's out-of-plane direction).
    """),
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreatePrismaticJoint(itemNumbers=[oGround, oSlider], position=[x, y, z], axis=[1, 0, 0])
        - axis: GLOBAL sliding direction, position: GLOBAL joint point (usually the slider's reference
          position), both for the reference configuration; all rotations and the other two translations are
          locked.
        - Only rigid bodies and ground (no mass points); a joint at a flexible part's interface is an
          InterfaceJoint.
    """),
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreateSphericalJoint(itemNumbers=[oGround, oBody], position=[x, y, z], constrainedAxes=[1, 1, 1])
        - position: GLOBAL joint point in the reference configuration.
        - constrainedAxes: which GLOBAL translations are locked (1) or free (0); e.g. [1, 1, 0] fixes only x and
          y, to close a planar x-y loop (slider-crank, four-bar) without redundant constraints.
        - Works with rigid bodies, mass points and ground.
    """),
    example=rigid_example("""
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
    context=text_block("""
        mbs.CreateGenericJoint(itemNumbers=[oGround, oBody], position=[x, y, z], rotationMatrixAxes=np.eye(3),
                               constrainedAxes=[1, 1, 1, 1, 1, 1])
        - constrainedAxes: 6 flags [x, y, z, rot x, rot y, rot z] of the joint frame, 1 = locked, 0 = free;
          [1, 1, 1, 1, 1, 1] = rigid connection (weld), [1, 1, 1, 1, 1, 0] = revolute about the joint z-axis,
          [0, 1, 1, 0, 0, 0] = only the y and z translations locked (a floating bearing along x).
        - position: GLOBAL joint point; rotationMatrixAxes: GLOBAL orientation of the joint frame (its columns
          are the joint x, y, z axes), both for the reference configuration; np.eye(3) = global axes.
        - CreateGenericJoint takes rigid bodies and ground. A flexible part's interface markers are joined with
          the GenericJoint object itself, mbs.AddObject(GenericJoint(markerNumbers=[m0, m1], ...)): see
          InterfaceJoint.
        - Avoid locking a direction twice (redundant constraints), e.g. when a second bearing supports a shaft
          that is already held by a spherical joint.
    """),
    example=rigid_example("""
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
    context=text_block("""
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
    example=rigid_example("""
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
