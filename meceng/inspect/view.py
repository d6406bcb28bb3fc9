"""What a program built, in the description's terms: bodies, connectors, loads and their states.

Built from one execution of the program alone (its captured items, the inspector's states and its
trajectory), never from a ground truth. Everything is in the global frame and SI units; a body's
position is its centre of mass; orientation is said as ``orientation.py`` says it.
"""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from meceng.catalog.names import BODY_KINDS, load_name, object_name
from meceng.inspect.acting import sort_contact
from meceng.inspect.coordinates import COORDINATE_TYPES, read_coordinate
from meceng.inspect.geometry import rolling_disc, sphere_triangle
from meceng.inspect.orientation import spins
from meceng.inspect.system import (
    Body,
    BodyState,
    Connector,
    CoordinateRange,
    Load,
    Spin,
    SystemView,
    direction,
)

#: Item keys that are bookkeeping, not physics; left out of a connector's parameters.
_NOT_PARAMETERS = frozenset({"objectType", "name", "markerNumbers", "activeConnector", "nodeNumber", "nodeNumbers",
                             "rotationMarker0", "rotationMarker1", "visualization"})
_AUTO_NAME = re.compile(r"^(object|load|marker|node|sensor)\d+$")
_E = np.eye(3)


def _tuple(value: Any) -> tuple[float, ...] | None:
    try:
        array = np.asarray(value, dtype=float).ravel()
    except (TypeError, ValueError):
        return None
    return tuple(float(x) for x in array) if array.size and np.all(np.isfinite(array)) else None


def _name(item: dict[str, Any]) -> str | None:
    name = str(item.get("name", ""))
    return None if not name or _AUTO_NAME.match(name) else name


def _principal_inertia(item: dict[str, Any]) -> tuple[tuple[float, ...] | None, np.ndarray | None,
                                                      np.ndarray | None]:
    """Exudyn keeps a rigid body's inertia about its reference point: moved to the centre of mass,
    its principal values (ascending), axes (columns, body coordinates) and the tensor in body axes."""
    inertia = _tuple(item.get("inertia"))
    mass = item.get("mass")
    if inertia is None or not isinstance(mass, int | float):
        return None, None, None
    if len(inertia) == 1:  # RigidBody2D: one moment about z
        return inertia, None, None
    if len(inertia) == 9:  # a flexible body's 3x3 matrix, also about its frame's origin
        tensor = np.asarray(inertia).reshape(3, 3)
    elif len(inertia) == 6:
        xx, yy, zz, yz, xz, xy = inertia
        tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    else:
        return None, None, None
    c = np.asarray(_tuple(item.get("centerOfMass")) or (0.0, 0.0, 0.0))[:3]
    tensor = tensor - float(mass) * (float(c @ c) * _E - np.outer(c, c))
    values, axes = np.linalg.eigh(tensor)
    return tuple(float(v) for v in values), axes, tensor


def _rotation(value: Any) -> np.ndarray | None:
    flat = _tuple(value)
    if flat is None or len(flat) != 9:
        return None
    return np.asarray(flat).reshape(3, 3)


def _states(index: int, inspection: dict[str, Any], frame_to_centre: tuple[float, ...] | None = None
            ) -> tuple[BodyState, ...]:
    """The body's sampled states; ``frame_to_centre`` (body coordinates) moves a state read at a
    flexible body's floating frame to its centre of mass."""
    out = []
    for sample in inspection.get("states", []):
        raw = sample.get("bodies", {}).get(str(index))
        if not raw or _tuple(raw.get("p")) is None:
            continue
        position, rotation = np.asarray(_tuple(raw["p"])), _rotation(raw.get("R"))
        velocity, omega = _tuple(raw.get("v")), _tuple(raw.get("w"))
        if frame_to_centre is not None and rotation is not None and len(position) == 3:
            arm = rotation @ np.asarray(frame_to_centre)
            position = position + arm
            if velocity is not None and omega is not None:
                velocity = tuple(float(x) for x in np.asarray(velocity) + np.cross(omega, arm))
        out.append(BodyState(float(sample["t"]), tuple(float(x) for x in position), rotation, velocity, omega))
    return tuple(out)


def _markers_at(inspection: dict[str, Any], k: int) -> dict[int, dict[str, Any]]:
    states = inspection.get("states", [])
    return {int(m): v for m, v in states[k].get("markers", {}).items()} if k < len(states) else {}


def _connector(index: int, item: dict[str, Any], markers: list[dict[str, Any]], node_body: dict[int, int],
               marker_t0: dict[int, dict[str, Any]], nodes: list[dict[str, Any]], inspection: dict[str, Any]
               ) -> Connector:
    exudyn_type = str(item.get("objectType", ""))
    if "trianglePoints" in item:  # Exudyn reports a sphere-triangle contact as ContactSphereSphere
        exudyn_type = "ContactSphereTriangle"
    numbers = [int(m) for m in item.get("markerNumbers") or [] if isinstance(m, int | float)]
    bodies: list[int | None] = []
    for m in numbers:
        marker = markers[m] if 0 <= m < len(markers) else {}
        if "bodyNumber" in marker:
            bodies.append(int(marker["bodyNumber"]))
        elif "nodeNumber" in marker:
            bodies.append(node_body.get(int(marker["nodeNumber"])))
        else:
            bodies.append(None)
    points = tuple(_tuple(marker_t0.get(m, {}).get("p")) for m in numbers)
    frame = None
    if numbers and marker_t0.get(numbers[0], {}).get("R") is not None:
        frame = _rotation(marker_t0[numbers[0]]["R"])
        local = item.get("rotationMarker0")
        if frame is not None and local is not None:
            frame = frame @ np.asarray(local, dtype=float).reshape(3, 3)
    candidates = {k: v for k, v in item.items() if k not in _NOT_PARAMETERS and "UserFunction" not in k and _small(v)}
    sorted_out = sort_contact(exudyn_type, candidates, _ALWAYS_SHOWN)  # a contact: what acts, what was set idle
    parameters, idle = sorted_out or ({k: v for k, v in candidates.items() if k in _ALWAYS_SHOWN or _nonzero(v)}, {})
    axis, free, locked, derived = _semantics(exudyn_type, item, frame, points)
    shape: dict[str, Any] = {}
    if exudyn_type == "ContactSphereTriangle" and len(numbers) == 2:
        shape = sphere_triangle(item, points[0], points[1], _rotation(marker_t0.get(numbers[1], {}).get("R")))
    if exudyn_type == "JointRollingDisc" and len(numbers) == 2:
        shape = rolling_disc(item, points[0], frame)
        shape["disc_rotation"] = _rotation(marker_t0.get(numbers[1], {}).get("R"))
    if exudyn_type in COORDINATE_TYPES:  # which coordinate of which body each end is
        shape = {"coordinates": tuple(read_coordinate(markers[m] if 0 <= m < len(markers) else {}, nodes, node_body)
                                      for m in numbers),
                 "user_offset": item.get("offsetUserFunction", 0) not in (0, None)}
    user = next((k for k, v in item.items() if k.endswith("UserFunction") and "offset" not in k
                 and v not in (0, None, "")), "")
    return Connector(index, object_name(exudyn_type), exudyn_type, _name(item), tuple(bodies), points, axis,
                     free, locked, parameters, derived, tuple(numbers), shape, idle, user,
                     _connector_values(index, inspection) if user else ())


#: Parameters a model must see even at zero (a spring without damping is a fact, not a default).
_ALWAYS_SHOWN = frozenset({"stiffness", "damping", "referenceLength", "distance", "contactStiffness",
                           "contactDamping", "spheresRadii", "discRadius", "offset", "constrainedAxes"})


def _nonzero(value: Any) -> bool:
    if isinstance(value, bool):
        return value
    return bool(np.any(np.asarray(value, dtype=float) != 0))


def _small(value: Any) -> bool:
    if isinstance(value, bool | int | float | str):
        return not isinstance(value, str) or len(value) < 40
    if isinstance(value, list):
        flat = np.ravel(np.asarray(value, dtype=object))
        return len(flat) <= 9 and all(isinstance(x, int | float) for x in flat)
    return False


def _direction(frame: np.ndarray | None, axis: int) -> tuple[float, ...] | None:
    return None if frame is None else tuple(float(x) for x in frame[:, axis])


def _semantics(exudyn_type: str, item: dict[str, Any], frame: np.ndarray | None,
               points: tuple[tuple[float, ...] | None, ...]) -> tuple[tuple[float, ...] | None, str, str,
                                                                      dict[str, float]]:
    """Axis, free and locked directions in global terms, and derived numbers (initial length, gap)."""
    derived: dict[str, float] = {}
    if exudyn_type in _LENGTH_TYPES and len(points) == 2 and points[0] is not None and points[1] is not None:
        derived["initial_length"] = float(np.linalg.norm(np.subtract(points[1], points[0])))
    if exudyn_type == "JointRevoluteZ":
        axis = _direction(frame, 2)
        return axis, f"rotation about {direction(axis)}", "all translations and the other rotations", derived
    if exudyn_type == "JointPrismaticX":
        axis = _direction(frame, 0)
        return axis, f"translation along {direction(axis)}", "the other translations and all rotations", derived
    if exudyn_type == "ConnectorTorsionalSpringDamper":
        return _direction(frame, 2), "", "", derived
    if exudyn_type in ("JointSpherical", "JointGeneric"):
        flags = [int(x) for x in np.ravel(item.get("constrainedAxes") or [])]
        groups: dict[tuple[bool, bool], list[str]] = {}
        for k, flag in enumerate(flags[:6]):
            axis = _direction(frame, k % 3) if frame is not None else tuple(float(x) for x in _E[k % 3])
            groups.setdefault((bool(flag), k < 3), []).append(direction(axis))

        def said(flag: bool) -> list[str]:
            return [f"{'translation along' if along else 'rotation about'} {', '.join(groups[(flag, along)])}"
                    for along in (True, False) if groups.get((flag, along))]

        free = said(False) + (["all rotations"] if exudyn_type == "JointSpherical" else [])
        return None, "; ".join(free) or "nothing", "; ".join(said(True)) or "nothing", derived
    if exudyn_type == "ContactSphereSphere" and "initial_length" in derived:
        radii = _tuple(item.get("spheresRadii")) or (0.0, 0.0)
        derived["initial_gap"] = derived["initial_length"] - sum(radii[:2])
    return None, "", "", derived


_LENGTH_TYPES = frozenset({"ConnectorSpringDamper", "ConnectorDistance", "ContactSphereSphere",
                          "ConnectorCartesianSpringDamper"})


_NODE_COORDINATES = {
    "Point": ("x", "y", "z"), "Point2D": ("x", "y"), "RigidBody2D": ("x", "y", "phi"),
    "RigidBodyRxyz": ("x", "y", "z"), "RigidBodyEP": ("x", "y", "z"),
    "RigidBodyRotVecLG": ("x", "y", "z"), "RigidBodyRotVec": ("x", "y", "z"),
}


def _ranges(bodies: tuple[Body, ...], nodes: list[dict[str, Any]], ode2: dict[str, int],
            trajectory: np.ndarray | None, spins: dict[int, Spin]) -> tuple[CoordinateRange, ...]:
    """Per body coordinate, its range over the whole run (reference point; a 3D rotation as the
    rotation accumulated about the body axis it turns about most)."""
    if trajectory is None or not len(trajectory):
        return ()
    out = []
    for body in bodies:
        if body.node is None or str(body.node) not in ode2 or body.node >= len(nodes):
            continue
        start = ode2[str(body.node)]
        node_type = str(nodes[body.node].get("nodeType", ""))
        names = _NODE_COORDINATES.get(node_type, ())
        for k, name in enumerate(names):
            if start + k < trajectory.shape[1]:
                column = trajectory[:, start + k]
                out.append(CoordinateRange(body.index, name, float(column.min()), float(column.max())))
        if body.index in spins and np.ptp(spins[body.index].angles) > 1e-9:
            angles = spins[body.index].angles
            out.append(CoordinateRange(body.index, f"turned about {spins[body.index].name}", float(angles.min()),
                                       float(angles.max())))
    return tuple(out)


def build_view(items: dict[str, list[dict[str, Any]]], system: dict[str, Any],
               inspection: dict[str, Any] | None, trajectory: np.ndarray | None = None,
               times: np.ndarray | None = None) -> SystemView:
    """The program's system as the inspector shows it and the snapshot draws it."""
    inspection = inspection or {}
    objects = items.get("objects", [])
    markers = items.get("markers", [])
    nodes = items.get("nodes", [])
    marker_t0 = _markers_at(inspection, 0)
    node_body: dict[int, int] = {}
    bodies: list[Body] = []
    connectors: list[Connector] = []
    for index, item in enumerate(objects):
        kind = object_name(str(item.get("objectType", "")))
        if kind in BODY_KINDS:
            node = item.get("nodeNumber")
            if node is None and item.get("nodeNumbers"):
                node = item["nodeNumbers"][0]
            if isinstance(node, int | float):
                node_body.setdefault(int(node), index)
            mass = item.get("mass", item.get("physicsMass"))
            principal, axes, tensor = _principal_inertia(item)
            to_centre = _tuple(item.get("centerOfMass")) if kind == "FlexibleBody" else None
            bodies.append(Body(
                index, kind, str(item.get("objectType")), _name(item),
                float(mass) if isinstance(mass, int | float) else None,
                (_tuple(item.get("centerOfMass")) or (0.0, 0.0, 0.0))[:3], principal,
                int(node) if isinstance(node, int | float) else None, principal_axes=axes, inertia_local=tensor,
                states=_states(index, inspection, to_centre)))
    for index, item in enumerate(objects):
        if object_name(str(item.get("objectType", ""))) not in BODY_KINDS and item.get("markerNumbers") is not None:
            connectors.append(_connector(index, item, markers, node_body, marker_t0, nodes, inspection))
    loads = []
    for index, item in enumerate(items.get("loads", [])):
        marker = markers[int(item["markerNumber"])] if 0 <= int(item.get("markerNumber", -1)) < len(markers) else {}
        body = marker.get("bodyNumber")
        if body is None and "nodeNumber" in marker:
            body = node_body.get(int(marker["nodeNumber"]))
        user = item.get("loadVectorUserFunction", 0) not in (0, None) or any(
            k.endswith("UserFunction") and v not in (0, None) for k, v in item.items())
        vector = None if user else _tuple(item.get("loadVector", item.get("load")))
        point = _tuple(marker_t0.get(int(item.get("markerNumber", -1)), {}).get("p"))
        loads.append(Load(index, load_name(str(item.get("loadType", "")), user), body, point, vector,
                          bool(item.get("bodyFixed", False)), _load_values(index, inspection) if user else ()))
    states = inspection.get("states", [])
    marker_states = tuple({int(m): _tuple(v.get("p")) or () for m, v in s.get("markers", {}).items()}
                          for s in states)
    marker_rotations = tuple({int(m): r for m, v in s.get("markers", {}).items()
                              if (r := _rotation(v.get("R"))) is not None} for s in states)
    view_bodies = tuple(bodies)
    ode2 = inspection.get("ode2", {})
    turns = spins(view_bodies, nodes, ode2, trajectory, times)
    return SystemView(view_bodies, tuple(connectors), tuple(loads), tuple(float(s["t"]) for s in states),
                      _ranges(view_bodies, nodes, ode2, trajectory, turns),
                      _int(system.get("degreeOfFreedom")), _int(system.get("redundantConstraints")), marker_states,
                      marker_rotations, turns,
                      tuple(tuple(float(a) for a in s.get("asked") or ()) for s in states),
                      tuple(float(s["step"]) if isinstance(s.get("step"), int | float) else None for s in states),
                      float(times[-1]) if times is not None and len(times) else None)


def _load_values(index: int, inspection: dict[str, Any]) -> tuple[tuple[float, tuple[float, ...] | str], ...]:
    """A user-function load's values at the sampled times, as the sandbox evaluated them."""
    out: list[tuple[float, tuple[float, ...] | str]] = []
    for sample in inspection.get("states", []):
        value = sample.get("loads", {}).get(str(index))
        if isinstance(value, dict):
            out.append((float(sample["t"]), f"raised {value.get('error', 'an error')}"))
        elif (vector := _tuple(value)) is not None:
            out.append((float(sample["t"]), vector))
    return tuple(out)


def _connector_values(index: int, inspection: dict[str, Any]) -> tuple[tuple[float, dict[str, Any]], ...]:
    """A user-function connector's force or torque at the sampled times, as the sandbox read it."""
    return tuple((float(sample["t"]), value) for sample in inspection.get("states", [])
                 if isinstance(value := sample.get("connectors", {}).get(str(index)), dict))


def _int(value: Any) -> int | None:
    return int(value) if isinstance(value, int | float) and math.isfinite(value) else None
