"""A system view at one time as drawable 3D shapes, and the projections every picture uses.

One scene, two renderers: the agent's snapshot (a PNG drawn with matplotlib) and the viewer's
task pages (inline SVG, milliseconds per record). Both project the same shapes with the same
views, so what a model saw and what a reader sees are the same picture.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from meceng.inspect.forms import outline_points
from meceng.inspect.geometry import placed, rolling_frame
from meceng.inspect.system import Connector, SystemView

Point = tuple[float, float, float]

#: role -> colour, shared by the renderers
COLOURS = {"body": "#4a7fc1", "ground": "#666666", "joint": "#d62728", "spherical": "#d62728", "spring": "#2ca02c",
           "distance": "#9467bd", "contact": "#ff7f0e", "load": "#8c564b"}
LEGEND = ("blue: bodies as the shape their inertia gives (sphere, disc, else box), mass points as dots; grey: ground "
          "(square) and planes discs roll on; red: joints (circle) with their axes, spherical joints (diamond: all "
          "translations locked, rotations free), rolling contact points; green: springs; purple: distance "
          "constraints; orange: contact geometry (spheres as circles, triangles filled); brown arrows: forces")

_ROLES = {"SpringDamper": "spring", "CartesianSpringDamper": "spring", "TorsionalSpringDamper": "spring",
          "RigidBodySpringDamper": "spring", "CoordinateSpringDamper": "spring", "DistanceConstraint": "distance",
          "SphereSphereContact": "contact", "SphereTriangleContact": "contact"}
JOINTS = frozenset({"RevoluteJoint", "PrismaticJoint", "SphericalJoint", "GenericJoint", "RollingDisc"})


@dataclass(frozen=True)
class Shape:
    """``box`` (8 corners), ``line`` (2 points), ``point``, ``circle`` (centre, radius), ``arrow``
    (tail, head) or ``label`` (anchor, text)."""

    kind: str
    role: str
    points: tuple[Point, ...]
    radius: float = 0.0
    text: str = ""

    def to_json(self) -> list[Any]:
        return [self.kind, self.role, [[round(c, 6) for c in p] for p in self.points], round(self.radius, 6),
                self.text]

    @classmethod
    def from_json(cls, data: list[Any]) -> Shape:
        kind, role, points, radius, text = data
        return cls(kind, role, tuple((float(p[0]), float(p[1]), float(p[2])) for p in points), float(radius), text)


@dataclass(frozen=True)
class Projection:
    """An orthographic view: screen x and y as two unit vectors of the global frame."""

    name: str
    right: Point
    up: Point

    def apply(self, points: np.ndarray) -> np.ndarray:
        return np.asarray(points, dtype=float).reshape(-1, 3) @ np.array([self.right, self.up]).T


def _iso() -> Projection:
    azimuth, elevation = math.radians(-60.0), math.radians(30.0)
    right = (-math.sin(azimuth), math.cos(azimuth), 0.0)
    up = (-math.sin(elevation) * math.cos(azimuth), -math.sin(elevation) * math.sin(azimuth), math.cos(elevation))
    return Projection("isometric", right, up)


#: three orthogonal views and an isometric one
VIEWS = (Projection("top: x right, y up (looking down z)", (1, 0, 0), (0, 1, 0)),
         Projection("front: x right, z up (looking along +y)", (1, 0, 0), (0, 0, 1)),
         Projection("side: y right, z up (looking along -x)", (0, 1, 0), (0, 0, 1)),
         _iso())


def sample_index(view: SystemView, t: float) -> int:
    return int(np.argmin([abs(s - t) for s in view.times])) if view.times else 0


def _p(values: Any) -> Point:
    return (float(values[0]), float(values[1]), float(values[2]))


def extent(view: SystemView) -> float:
    """The size of the system: arrows and joint axes are drawn in proportion to it. The initial
    configuration counts, and a tenth of how far it travels (a rolling vehicle stays readable)."""
    def spread(k: int | None) -> float:
        points = [s.position[:3] for b in view.bodies for s in b.states
                  if len(s.position) >= 3 and (k is None or abs(s.t - view.times[k]) < 1e-12)]
        markers = view.marker_states if k is None else view.marker_states[k:k + 1]
        points += [p[:3] for m in markers for p in m.values() if len(p) >= 3]
        return float(np.ptp(np.asarray(points, dtype=float), axis=0).max()) if points else 0.0

    first = spread(0) if view.times else 0.0
    return max(first, 0.1 * spread(None), 1e-3)


def connector_points(view: SystemView, c: Connector, k: int) -> list[Point]:
    """A connector's marker positions at sample ``k`` (the snapshot's picture and its words)."""
    markers = view.marker_states[k] if k < len(view.marker_states) else {}
    return [_p(markers[m]) for m in c.markers if m in markers and len(markers[m]) >= 3]


def build_scene(view: SystemView, t: float) -> tuple[Shape, ...]:
    """Everything the picture at time ``t`` (the nearest sampled state) shows."""
    k = sample_index(view, t)
    at = view.times[k] if view.times else 0.0
    size = extent(view)
    shapes: list[Shape] = []
    for c in view.connectors:
        points = connector_points(view, c, k)
        if "axis_local" in c.geometry and len(points) == 2:
            shapes += _rolling_shapes(view, c, k, points[1])
        elif c.kind == "SphericalJoint" and points:
            shapes.append(Shape("point", "spherical", (points[0],)))
        elif c.kind in JOINTS and points:
            shapes.append(Shape("point", "joint", (points[0],)))
            axis = joint_axis(view, c, k)
            if axis is not None:
                a = axis * 0.12 * size
                shapes.append(Shape("line", "joint", (_p(points[0] - a), _p(points[0] + a))))
        elif len(points) == 2:
            role = _ROLES.get(c.kind, "spring")
            if role != "contact" and not np.allclose(points[0], points[1]):  # a contact is no link
                shapes.append(Shape("line", role, (points[0], points[1])))
            if role == "contact":
                shapes += _contact_shapes(view, c, k, points)
    for body in view.bodies:
        state = body.state_at(at)
        if state is None or len(state.position) < 3:
            continue
        position = _p(state.position)
        drawn = None if body.is_ground else outline_points(body, state)
        if body.is_ground:
            shapes.append(Shape("point", "ground", (position,)))
        elif drawn is not None:
            kind, points, radius = drawn
            shapes.append(Shape("circle" if kind == "circle" else "box", "body", tuple(_p(c) for c in points),
                                radius))
        else:
            shapes.append(Shape("point", "body", (position,)))
        shapes.append(Shape("label", "body", (position,), text=f"#{body.index}"))
    for load in view.loads:
        body = view.body(load.body) if load.body is not None else None
        state = body.state_at(at) if body is not None else None
        if load.vector is None or len(load.vector) < 3 or state is None or "Gravity" in load.kind:
            continue
        norm = float(np.linalg.norm(load.vector[:3])) or 1.0
        tail = np.asarray(state.position[:3])
        shapes.append(Shape("arrow", "load", (_p(tail), _p(tail + np.asarray(load.vector[:3]) / norm * 0.15 * size))))
    return tuple(shapes)


def joint_axis(view: SystemView, c: Connector, k: int) -> np.ndarray | None:
    """A joint's axis at sample ``k``: its axis at t = 0 turned with its first marker since then."""
    if c.axis is None or len(c.axis) < 3:
        return None
    axis = np.asarray(c.axis[:3], dtype=float)
    if k == 0 or not c.markers or k >= len(view.marker_rotations) or not view.marker_rotations:
        return axis
    start, now = view.marker_rotations[0].get(c.markers[0]), view.marker_rotations[k].get(c.markers[0])
    return axis if start is None or now is None else now @ (start.T @ axis)


def _rolling_shapes(view: SystemView, c: Connector, k: int, centre: Point) -> list[Shape]:
    """A rolling disc: its contact point, the axle through the centre, a patch of the plane it rolls on."""
    rotation = (view.marker_rotations[k] if k < len(view.marker_rotations) else {}).get(c.markers[1])
    frame = rolling_frame(c.geometry, centre, rotation)
    if not frame:
        return []
    contact, r = frame["contact"], 1.3 * c.geometry["radius"]
    lateral, longitudinal, _ = frame["directions"]
    patch = [contact + r * (a * longitudinal + b * lateral) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    axle = frame["axis"] * 0.6 * c.geometry["radius"]
    return [Shape("box", "ground", tuple(_p(p) for p in patch)), Shape("point", "joint", (_p(contact),)),
            Shape("line", "joint", (_p(np.asarray(centre) - axle), _p(np.asarray(centre) + axle)))]


def _contact_shapes(view: SystemView, c: Connector, k: int, points: list[Point]) -> list[Shape]:
    """A contact's own geometry: its spheres as circles, a triangle as a filled triangle."""
    radii = list(c.parameters.get("spheresRadii") or [])
    if "triangle_local" in c.geometry:
        radii = [c.geometry["radius"]]
        marker = c.markers[1]
        origin = (view.marker_states[k] if k < len(view.marker_states) else {}).get(marker)
        rotation = (view.marker_rotations[k] if k < len(view.marker_rotations) else {}).get(marker)
        if origin is not None and len(origin) >= 3:
            corners = placed(c.geometry["triangle_local"], origin, rotation)
            out = [Shape("box", "contact", tuple(_p(p) for p in corners))]
            # its edges too: a wall seen edge-on is a line, which a filled outline hardly shows
            out += [Shape("line", "contact", (_p(corners[i]), _p(corners[(i + 1) % 3]))) for i in range(3)]
        else:
            out = []
    else:
        out = []
    return out + [Shape("circle", "contact", (point,), float(radius))
                  for point, radius in zip(points, radii, strict=False)]


def bounds(scenes: list[tuple[Shape, ...]], projection: Projection) -> tuple[np.ndarray, np.ndarray]:
    """Screen-space bounds of several scenes in one view (so two pictures share their scale)."""
    chunks = []
    for scene in scenes:
        for shape in scene:
            xy = projection.apply(np.asarray(shape.points))
            chunks.append(xy - shape.radius)
            chunks.append(xy + shape.radius)
    if not chunks:
        return np.array([-1.0, -1.0]), np.array([1.0, 1.0])
    every = np.vstack(chunks)
    low, high = every.min(axis=0), every.max(axis=0)
    pad = max(float((high - low).max()) * 0.08, 1e-3)
    return low - pad, high + pad


def hull(points: np.ndarray) -> np.ndarray:
    """Convex hull of 2D points (monotone chain): the outline of a projected box."""
    pts = sorted({(round(float(x), 12), round(float(y), 12)) for x, y in points})
    if len(pts) < 3:
        return np.asarray(pts)

    def cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[tuple[float, float]] = []
    upper: list[tuple[float, float]] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.asarray(lower[:-1] + upper[:-1])
