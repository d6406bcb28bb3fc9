"""Exudyn's item types in the words of the component catalog and the task descriptions."""

from __future__ import annotations

#: Exudyn object type -> catalog component name.
OBJECT_NAMES: dict[str, str] = {
    "Ground": "Ground",
    "MassPoint": "MassPoint",
    "MassPoint2D": "MassPoint",
    "RigidBody": "RigidBody",
    "RigidBody2D": "RigidBody",
    "FFRFreducedOrder": "FlexibleBody",
    "ObjectFFRFreducedOrder": "FlexibleBody",
    "ConnectorSpringDamper": "SpringDamper",
    "ConnectorCartesianSpringDamper": "CartesianSpringDamper",
    "ConnectorTorsionalSpringDamper": "TorsionalSpringDamper",
    "ConnectorRigidBodySpringDamper": "RigidBodySpringDamper",
    "ConnectorDistance": "DistanceConstraint",
    "ConnectorCoordinateSpringDamper": "CoordinateSpringDamper",
    "ConnectorCoordinate": "CoordinateConstraint",
    "JointRevoluteZ": "RevoluteJoint",
    "JointPrismaticX": "PrismaticJoint",
    "JointSpherical": "SphericalJoint",
    "JointGeneric": "GenericJoint",
    "JointRollingDisc": "RollingDisc",
    "ContactSphereSphere": "SphereSphereContact",
    "ContactSphereTriangle": "SphereTriangleContact",
}

#: Exudyn load type -> what the catalog and the descriptions call it.
LOAD_NAMES: dict[str, str] = {
    "ForceVector": "Force",
    "TorqueVector": "Torque",
    "MassProportional": "Gravity (mass-proportional load)",
    "Coordinate": "CoordinateLoad",
}

BODY_KINDS = frozenset({"Ground", "MassPoint", "RigidBody", "FlexibleBody"})


def object_name(exudyn_type: str) -> str:
    """The catalog's name; an item the catalog does not know keeps Exudyn's."""
    return OBJECT_NAMES.get(exudyn_type, exudyn_type)


def load_name(exudyn_type: str, user_function: bool) -> str:
    name = LOAD_NAMES.get(exudyn_type, exudyn_type)
    return f"{name} with a user function (LoadUserFunction)" if user_function else name
