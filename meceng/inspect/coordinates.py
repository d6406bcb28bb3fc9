"""Coordinate connectors in words: which coordinate of which body each end acts on, and what a
CoordinateConstraint holds it at.

A CoordinateConstraint's markers name a node and the index of one of its coordinates; written by hand
the other end is often a ground node that belongs to no body. Said as "a node coordinate — #1
MassPoint", four constraints on one slider read as four identical lines; a model needs to read which
coordinate each locks (``#1 MassPoint's y``) and at what value, in Exudyn's own equation
``factor1*q1 - q0 = offset`` with q the displacement from the node's reference coordinate.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

#: The coordinates of a node type, in order (a rigid node: its position, then its rotation parameters).
NODE_COORDINATES: dict[str, tuple[str, ...]] = {
    "Point": ("x", "y", "z"),
    "Point2D": ("x", "y"),
    "RigidBody2D": ("x", "y", "phi (rotation about z)"),
    "RigidBodyEP": ("x", "y", "z", "Euler parameter 0", "Euler parameter 1", "Euler parameter 2",
                    "Euler parameter 3"),
    "RigidBodyRxyz": ("x", "y", "z", "angle rx", "angle ry", "angle rz"),
    "RigidBodyRotVecLG": ("x", "y", "z", "rotation vector x", "rotation vector y", "rotation vector z"),
    "RigidBodyRotVec": ("x", "y", "z", "rotation vector x", "rotation vector y", "rotation vector z"),
}
#: Exudyn connectors whose markers are coordinates.
COORDINATE_TYPES = frozenset({"ConnectorCoordinate", "ConnectorCoordinateSpringDamper", "ContactCoordinate"})


@dataclass(frozen=True)
class Coordinate:
    """One end of a coordinate connector: a body's (or a bare node's) coordinate, or the ground."""

    node: int | None
    body: int | None  # the object whose node it is; None: a node of no body (a ground node)
    name: str  # "y", "angle rz", "coordinate 4"
    reference: float | None  # the node's reference value of this coordinate
    ground: bool  # a ground node: its coordinate is always 0


def read_coordinate(marker: dict[str, Any], nodes: list[dict[str, Any]], node_body: dict[int, int]
                    ) -> Coordinate | None:
    """The coordinate a NodeCoordinate (or NodeRotationCoordinate) marker names; None for another marker."""
    if "nodeNumber" not in marker or not ("coordinate" in marker or "rotationCoordinate" in marker):
        return None
    node = int(marker["nodeNumber"])
    item = nodes[node] if 0 <= node < len(nodes) else {}
    node_type = str(item.get("nodeType", ""))
    if "rotationCoordinate" in marker:
        k = int(marker["rotationCoordinate"])
        return Coordinate(node, node_body.get(node), f"rotation about local {'xyz'[k % 3]}", None,
                          "Ground" in node_type)
    k = int(marker["coordinate"])
    names = NODE_COORDINATES.get(node_type, ())
    name = names[k] if 0 <= k < len(names) else f"coordinate {k}"
    reference = item.get("referenceCoordinates")
    try:
        value = float(list(reference)[k]) if reference is not None else None
    except (IndexError, TypeError, ValueError):
        value = None
    return Coordinate(node, node_body.get(node), name, value, "Ground" in node_type)


def end_words(coordinate: Coordinate | None, label: Callable[[int], str]) -> str:
    """``#1 MassPoint's y``, ``ground``, or ``node 4's coordinate 2`` (a node of no body)."""
    if coordinate is None:
        return "?"
    if coordinate.ground:
        return "ground"
    owner = label(coordinate.body) if coordinate.body is not None else f"node {coordinate.node}"
    return f"{owner}'s {coordinate.name}"


#: Parameters the relation below says; not listed again.
SAID = frozenset({"offset", "factor1", "velocityLevel"})


def constraint_words(ends: tuple[Coordinate | None, ...], parameters: dict[str, Any], user_offset: bool,
                     label: Callable[[int], str], num: Callable[[float], str]) -> str:
    """What a CoordinateConstraint holds, from Exudyn's equation factor1*q1 - q0 = offset (q: the
    displacement of each end's coordinate from its reference value; a ground's is 0)."""
    if len(ends) != 2 or ends[0] is None or ends[1] is None:
        return ""
    offset = float(parameters.get("offset", 0.0) or 0.0)
    factor = float(parameters.get("factor1", 1.0) if parameters.get("factor1") is not None else 1.0)
    rate = "the velocity of " if parameters.get("velocityLevel") else ""
    if user_offset:
        return f"keeps {rate}factor1·q1 − q0 at an offset given by a user function (a prescribed motion)"
    first, second = ends
    if first.ground and second.ground:
        return "holds nothing (both ends are ground)"
    if first.ground or second.ground:
        held = second if first.ground else first
        if first.ground and factor == 0:
            return "holds nothing: factor1 is 0"
        shift = offset / factor if first.ground else -offset
        if second.ground:
            why = f"minus offset {num(offset)}"
        else:
            why = f"plus offset/factor1 = {num(offset)}/{num(factor)}" if factor != 1 else f"plus offset {num(offset)}"
        if rate or held.reference is None:
            return f"holds {rate}its displacement in {held.name} at {num(shift)} (0 {why})"
        value = held.reference + shift
        why = "its reference value" if offset == 0 else f"its reference {num(held.reference)} {why}"
        return f"holds it at {held.name} = {num(value)} ({why})"
    name0, name1 = end_words(first, label), end_words(second, label)
    scale = "" if factor == 1 else f"{num(factor)}·"
    return (f"keeps {rate}{scale}Δ({name1}) − Δ({name0}) = {num(offset)} (Δ: the displacement from the "
            "reference value; Exudyn's factor1·q1 − q0 = offset)")
