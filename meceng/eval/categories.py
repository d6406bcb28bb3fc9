"""The paper's seven error categories for annotation mismatches (section 3.2).

A difference is classified by the kind of item and the parameter name. Counted once per task per
category in the statistics.
"""

from __future__ import annotations

CATEGORIES = (
    "kinematics/marker",
    "rigid body configuration",
    "initial velocities",
    "inertia and mass",
    "gravity and load",
    "connector/constraint",
    "other",
)

_VELOCITY_KEYS = ("initialVelocities", "initialCoordinates_t", "initialAngularVelocity", "initialVelocity")
_CONFIGURATION_KEYS = ("referenceCoordinates", "initialCoordinates", "initialDisplacement",
                       "referencePosition", "referenceRotation", "referenceHT", "initialRotation")
_INERTIA_KEYS = ("mass", "inertia", "centerOfMass", "physicsMass", "physicsInertia", "physicsCenterOfMass",
                 "physicsDensity")


def categorize(item_type: str, key: str) -> str:
    """Category of a differing annotation; ``item_type`` is 'kind:Type', e.g. 'object:RigidBody'."""
    kind, _, type_name = item_type.partition(":")
    if kind == "load":
        return "gravity and load"
    if kind == "marker":
        return "kinematics/marker"
    if kind == "node":
        if key in _VELOCITY_KEYS:
            return "initial velocities"
        if key in _CONFIGURATION_KEYS:
            return "rigid body configuration"
        return "other"
    if kind == "object":
        if key in _INERTIA_KEYS:
            return "inertia and mass"
        if key in _VELOCITY_KEYS:
            return "initial velocities"
        if type_name.startswith(("Connector", "Joint", "Contact")) or "Constraint" in type_name:
            return "connector/constraint"
        if type_name == "Ground" and key in _CONFIGURATION_KEYS:
            return "kinematics/marker"
        if key in _CONFIGURATION_KEYS:
            return "rigid body configuration"
    return "other"
