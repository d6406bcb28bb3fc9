"""Ground-truth programs written another way: the same physical system, built differently.

Each alternative is a few exact edits of a task's ground-truth program of the kinds an engineer
who was not told how would make — another creation order, a joint's two items swapped, the
reference point away from the centre of mass, an equivalent joint or constraint, the local frame
permuted with the rotation that undoes it, a constant load given as a user function. They move
exactly as the ground truth does (up to round-off and time-stepping), so the behaviour verdict
(``eval/behaviour.py``) must pass every one; which of them the paper's verdict fails is a finding
about the paper's grader (docs/behaviour.md). Used by the tests and by
``scripts/behaviour_agreement.py``.
"""

from __future__ import annotations

from dataclasses import dataclass

from meceng.tasks.base import TaskInstance


@dataclass(frozen=True)
class Alternative:
    slug: str
    name: str
    kind: str  # order, markers, reference point, joint, frame, user function
    edits: tuple[tuple[str, str], ...]  # (text, replacement): each text must occur in the program

    @property
    def id(self) -> str:
        return f"{self.slug}/{self.name}"

    def program(self, instance: TaskInstance) -> str:
        program = instance.reference_program
        for old, new in self.edits:
            if old not in program:
                raise ValueError(f"{self.id}: {old!r} is not in the ground truth of {instance.key}")
            program = program.replace(old, new)
        return program


def _swap(first: str, second: str) -> tuple[str, str]:
    """Two adjacent statements in the other order."""
    return first + second, second + first


_DP_LINK1 = """oLink1 = mbs.CreateRigidBody(referencePosition=0.5 * length1 * e,
                             referenceRotationMatrix=RotationMatrixZ(-phi0),
                             inertia=InertiaCuboid(density=density,
                                                   sideLengths=[length1, width, thickness]),
                             gravity=[0, -gravity, 0])
"""
_DP_LINK2 = """oLink2 = mbs.CreateRigidBody(referencePosition=(length1 + 0.5 * length2) * e,
                             referenceRotationMatrix=RotationMatrixZ(-phi0),
                             inertia=InertiaCuboid(density=density,
                                                   sideLengths=[length2, width, thickness]),
                             gravity=[0, -gravity, 0])
"""

ALTERNATIVES: tuple[Alternative, ...] = (
    # level 1
    Alternative("single_pendulum", "distance markers swapped", "markers", (
        ("itemNumbers=[oGround, oMass], distance", "itemNumbers=[oMass, oGround], distance"),)),
    Alternative("single_mass_oscillator", "spring markers swapped", "markers", (
        ("itemNumbers=[oGround, oMass], stiffness", "itemNumbers=[oMass, oGround], stiffness"),)),
    Alternative("single_mass_oscillator_with_gravity", "ground created after the mass", "order", (
        ("oGround = mbs.CreateGround(referencePosition=[0, 0, 0])\n", ""),
        ("mbs.CreateSpringDamper(", "oGround = mbs.CreateGround(referencePosition=[0, 0, 0])\nmbs.CreateSpringDamper("),)),
    Alternative("free_fall_mass_point", "gravity as a user-function force", "user function", (
        ("mass=mass, gravity=[0, 0, -gravity])",
         "mass=mass)\nmbs.CreateForce(itemNumber=oMass, loadVector=[0, 0, 0],\n"
         "               loadVectorUserFunction=lambda mbs, t, load: [0, 0, -mass * gravity])"),)),
    Alternative("double_pendulum", "constraints created in reverse", "order", (
        _swap("mbs.CreateDistanceConstraint(itemNumbers=[oGround, oMass1], distance=length1)\n",
              "mbs.CreateDistanceConstraint(itemNumbers=[oMass1, oMass2], distance=length2)\n"),)),
    Alternative("n_pendulum", "links with their items swapped", "markers", (
        ("itemNumbers=[bodies[i], bodies[i + 1]]", "itemNumbers=[bodies[i + 1], bodies[i]]"),)),
    Alternative("single_pendulum_rigid_body", "reference point at the hinge", "reference point", (
        ("oLink = mbs.CreateRigidBody(referencePosition=p0,", "oLink = mbs.CreateRigidBody(referencePosition=[0, 0, 0],"),
        ("sideLengths=[width, length, thickness]),",
         "sideLengths=[width, length, thickness]).Translated([0, -0.5 * length, 0]),"),)),
    Alternative("flying_rigid_body", "local axes permuted, rotated back", "frame", (
        ("referenceRotationMatrix=np.eye(3),", "referenceRotationMatrix=np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]]),"),
        ("sideLengths=[size_x, size_y, size_z]", "sideLengths=[size_y, size_z, size_x]"),)),
    # level 2
    Alternative("two_mass_points_with_distances", "constraint markers swapped", "markers", (
        ("itemNumbers=[oMass1, oMass2], distance", "itemNumbers=[oMass2, oMass1], distance"),)),
    Alternative("double_pendulum_rigid_bodies", "links created in the other order", "order", (
        _swap(_DP_LINK1, _DP_LINK2),)),
    Alternative("double_pendulum_rigid_bodies", "second joint's items swapped", "markers", (
        ("itemNumbers=[oLink1, oLink2]", "itemNumbers=[oLink2, oLink1]"),)),
    Alternative("slider_crank_rigid_bodies", "crank bearing as a generic joint", "joint", (
        ("mbs.CreateRevoluteJoint(itemNumbers=[oGround, oCrank], position=[0, 0, 0], axis=[0, 0, 1])",
         "mbs.CreateGenericJoint(itemNumbers=[oGround, oCrank], position=[0, 0, 0],\n"
         "                       constrainedAxes=[1, 1, 1, 1, 1, 0])"),)),
    Alternative("gyroscope_on_spherical_joint", "spherical joint as a generic joint", "joint", (
        ("mbs.CreateSphericalJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0])",
         "mbs.CreateGenericJoint(itemNumbers=[oGround, oDisc], position=[0, 0, 0],\n"
         "                       constrainedAxes=[1, 1, 1, 0, 0, 0])"),)),
    Alternative("spinning_disc", "disc axis along local x, rotated back", "frame", (
        ("referenceRotationMatrix=np.eye(3),", "referenceRotationMatrix=RotationMatrixY(-np.pi / 2),"),
        ("outerRadius=radius, axis=2)", "outerRadius=radius, axis=0)"),)),
    Alternative("sphere_sphere_impact", "contact items and radii swapped", "markers", (
        ("itemNumbers=[oSphere0, oSphere1], spheresRadii=[radius0, radius1]",
         "itemNumbers=[oSphere1, oSphere0], spheresRadii=[radius1, radius0]"),)),
    Alternative("newtons_cradle", "contacts with their items swapped", "markers", (
        ("itemNumbers=[spheres[i], spheres[i + 1]]", "itemNumbers=[spheres[i + 1], spheres[i]]"),)),
    Alternative("non_steerable_scooter_with_ideal_rolling", "wheel axes along local z, rotated back", "frame", (
        ("""                                      referenceRotationMatrix=np.eye(3),
                                      initialVelocity=[velocity, 0, 0],
                                      initialAngularVelocity""",
         """                                      referenceRotationMatrix=RotationMatrixX(-np.pi / 2),
                                      initialVelocity=[velocity, 0, 0],
                                      initialAngularVelocity"""),
        ("outerRadius=r, axis=1)", "outerRadius=r, axis=2)"),
        ("axisPosition=[0, 0, 0], axisVector=[0, 1, 0]", "axisPosition=[0, 0, 0], axisVector=[0, 0, 1]"),)),
    # level 3b
    Alternative("flexible_pendulum", "hinge markers swapped", "markers", (
        ("markerNumbers=[mHinge, beam['beam:left']]", "markerNumbers=[beam['beam:left'], mHinge]"),)),
    Alternative("door_hinge", "hinge markers swapped", "markers", (
        ("markerNumbers=[pinLeaf['pin_leaf:pin'], gapLeaf['gap_leaf:bore']]",
         "markerNumbers=[gapLeaf['gap_leaf:bore'], pinLeaf['pin_leaf:pin']]"),)),
)


def alternatives_of(slug: str) -> tuple[Alternative, ...]:
    return tuple(a for a in ALTERNATIVES if a.slug == slug)
