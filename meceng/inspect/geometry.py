"""Contact geometry in global terms: a sphere-triangle contact's triangle, normal and gap, and where
a rolling disc touches its plane and which directions it locks there.

Exudyn keeps a triangle in the coordinates of its body's marker and a rolling disc's axis in the
disc's body coordinates; a model reads both in the description's global terms, so they are turned
here with the markers' states (``SystemView.marker_rotations``).
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def triangle_points(value: Any) -> np.ndarray | None:
    """The three corners an item holds (a list, or the text Exudyn's ``Vector3DList`` becomes)."""
    if isinstance(value, str):
        numbers = [float(x) for x in _NUMBER.findall(value.replace("array", ""))]
    else:
        try:
            numbers = [float(x) for x in np.ravel(np.asarray(value, dtype=float))]
        except (TypeError, ValueError):
            return None
    if len(numbers) != 9 or not np.all(np.isfinite(numbers)):
        return None
    return np.asarray(numbers).reshape(3, 3)


def placed(local: np.ndarray, origin: Any, rotation: np.ndarray | None) -> np.ndarray:
    """Points given in a marker's frame, in global coordinates."""
    turned = local if rotation is None else local @ np.asarray(rotation).T
    return turned + np.asarray(origin, dtype=float)[:3]


def triangle_normal(corners: np.ndarray) -> np.ndarray:
    """Unit normal by the right-hand rule over the corners in their order."""
    n = np.cross(corners[1] - corners[0], corners[2] - corners[0])
    return n / (np.linalg.norm(n) or 1.0)


def distance_to_triangle(point: np.ndarray, corners: np.ndarray) -> float:
    """Distance from a point to a (filled) triangle: to its plane where the foot lies inside,
    else to the nearest edge."""
    a, b, c = corners
    n = triangle_normal(corners)
    foot = point - float((point - a) @ n) * n
    inside = all(float(np.cross(q - p, foot - p) @ n) >= -1e-12 for p, q in ((a, b), (b, c), (c, a)))
    if inside:
        return abs(float((point - a) @ n))

    def to_segment(p: np.ndarray, q: np.ndarray) -> float:
        d = q - p
        s = float(np.clip((point - p) @ d / max(float(d @ d), 1e-300), 0.0, 1.0))
        return float(np.linalg.norm(point - (p + s * d)))

    return min(to_segment(a, b), to_segment(b, c), to_segment(c, a))


def sphere_triangle(item: dict[str, Any], centre: Any, triangle_origin: Any, triangle_rotation: np.ndarray | None
                    ) -> dict[str, Any]:
    """Corners (global), normal, the side the sphere is on and the gap (centre to triangle minus radius)."""
    local = triangle_points(item.get("trianglePoints"))
    if local is None or centre is None or triangle_origin is None:
        return {}
    corners = placed(local, triangle_origin, triangle_rotation)
    normal = triangle_normal(corners)
    centre = np.asarray(centre, dtype=float)[:3]
    radius = float(item.get("sphereRadius") or 0.0)
    side = float((centre - corners[0]) @ normal)
    edges = item.get("includeEdges", 7)
    return {"triangle_local": local, "corners": corners, "normal": normal, "radius": radius,
            "side": 1.0 if side >= 0 else -1.0, "gap": distance_to_triangle(centre, corners) - radius,
            "edges": int(edges) if isinstance(edges, int | float) else 7}


def edges_words(flags: int) -> str:
    """Exudyn's includeEdges in words: bit 1 the edge from corner 1 to 2, bit 2 from 2 to 3, bit 4 from 3 to 1."""
    named = [name for bit, name in ((1, "1–2"), (2, "2–3"), (4, "3–1")) if flags & bit]
    if len(named) == 3:
        return "its face and all three edges"
    if not named:
        return f"its face only, no edge (includeEdges {flags})"
    return f"its face and the edge{'s' if len(named) > 1 else ''} from corner {', '.join(named)} (includeEdges {flags})"


_ROLLING = ("lateral", "longitudinal", "normal")


def rolling_frame(geometry: dict[str, Any], centre: Any, disc_rotation: np.ndarray | None) -> dict[str, Any]:
    """Where a rolling disc touches its plane, and the three directions there: longitudinal (the
    rolling direction, axle × normal), lateral (in the plane, across it) and the plane's normal."""
    if centre is None or len(centre) < 3:
        return {}
    axis = np.asarray(geometry["axis_local"], dtype=float)
    axis = axis if disc_rotation is None else np.asarray(disc_rotation) @ axis
    axis = axis / (np.linalg.norm(axis) or 1.0)
    normal = np.asarray(geometry["normal"], dtype=float)
    down = -(normal - float(normal @ axis) * axis)  # in the disc's plane, towards the rolling plane
    down = down / (np.linalg.norm(down) or 1.0)
    contact = np.asarray(centre, dtype=float)[:3] + geometry["radius"] * down
    longitudinal = np.cross(axis, normal)
    longitudinal = longitudinal / (np.linalg.norm(longitudinal) or 1.0)
    lateral = np.cross(normal, longitudinal)
    return {"contact": contact, "axis": axis, "directions": (lateral, longitudinal, normal),
            "height": float((contact - np.asarray(geometry["plane_point"], dtype=float)) @ normal)}


def rolling_disc(item: dict[str, Any], plane_origin: Any, plane_rotation: np.ndarray | None) -> dict[str, Any]:
    """A rolling disc's plane (global), axle (disc axes), radius and which directions it locks."""
    normal = np.asarray(item.get("planeNormal") or (0.0, 0.0, 1.0), dtype=float)
    normal = normal if plane_rotation is None else np.asarray(plane_rotation) @ normal
    flags = [int(x) for x in np.ravel(item.get("constrainedAxes") or (1, 1, 1))][:3]
    return {"axis_local": tuple(float(x) for x in np.ravel(item.get("discAxis") or (1.0, 0.0, 0.0))),
            "normal": normal / (np.linalg.norm(normal) or 1.0), "radius": float(item.get("discRadius") or 0.0),
            "plane_point": np.asarray(plane_origin if plane_origin is not None else (0.0, 0.0, 0.0), dtype=float),
            "locked": tuple(bool(f) for f in flags)}


def rolling_words(geometry: dict[str, Any], frame: dict[str, Any], vec: Any, direction: Any) -> list[str]:
    """The disc's contact in words: point, plane, axle, and what is locked and free there."""
    if not frame:
        return []
    said = [f"{name} {direction(_unit(d))}" for name, d in zip(_ROLLING, frame["directions"], strict=True)]
    locked = [s for s, flag in zip(said, geometry["locked"], strict=True) if flag]
    free = [s for s, flag in zip(said, geometry["locked"], strict=True) if not flag]
    words = [f"contact point {vec(frame['contact'])} (height {vec([frame['height']])[1:-1]} above the plane through "
             f"{vec(geometry['plane_point'])}, normal {direction(_unit(geometry['normal']))}), "
             f"axle {direction(_unit(frame['axis']))}, radius {vec([geometry['radius']])[1:-1]}",
             "locked there: " + (", ".join(locked) or "nothing"),
             "free: all rotations" + ("; translation " + ", ".join(free) if free else "")]
    return words


def _unit(v: Any) -> tuple[float, ...]:
    v = np.where(np.abs(np.asarray(v, dtype=float)) < 1e-12, 0.0, np.asarray(v, dtype=float))
    return tuple(float(x) + 0.0 for x in v / (np.linalg.norm(v) or 1.0))
