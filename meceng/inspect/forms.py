"""A rigid body's shape as its inertia says it: the homogeneous sphere, disc (cylinder) or box with
the body's mass and principal moments.

Three equal moments: a sphere (I = 2/5 m r²). Two equal and the third larger: a disc or short
cylinder about the odd axis (I_axial = m r²/2, I_across = m (3 r² + h²)/12). Anything else: the box
(the snapshot's shape before). A square bar and a slender cylinder have the same moments; both are
drawn as the box, and a square plate as a disc: the inertia cannot tell them apart.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from meceng.inspect.system import Body, BodyState
from meceng.inspect.words import num, vec

_EQUAL = 1e-3  # relative difference of moments taken as equal
_RIM = 24  # points on each rim circle of a drawn disc


@dataclass(frozen=True)
class Form:
    kind: str  # sphere, disc, box
    sizes: tuple[float, ...]  # sphere: (radius,), disc: (radius, width), box: half edge lengths (principal axes)
    axis: int = 2  # disc: which principal axis is its axle


def box_half_sizes(body: Body) -> np.ndarray | None:
    """Half edge lengths of the homogeneous box with the body's mass and principal moments."""
    if body.principal_inertia is None or body.mass is None or body.mass <= 0 or len(body.principal_inertia) != 3:
        return None
    i1, i2, i3 = body.principal_inertia
    squares = 6.0 / body.mass * np.array([i2 + i3 - i1, i1 + i3 - i2, i1 + i2 - i3])
    return 0.5 * np.sqrt(np.clip(squares, 0.0, None))


def _same(a: float, b: float) -> bool:
    return abs(a - b) <= _EQUAL * max(abs(a), abs(b), 1e-300)


def form(body: Body) -> Form | None:
    half = box_half_sizes(body)
    if half is None or body.principal_inertia is None or body.mass is None:
        return None
    i1, i2, i3 = body.principal_inertia  # ascending
    m = body.mass
    if _same(i1, i3):
        return Form("sphere", (float(np.sqrt(2.5 * i3 / m)),))
    if _same(i1, i2) and i3 > i2:  # the odd moment the largest: a disc about the third principal axis
        radius = float(np.sqrt(2.0 * i3 / m))
        width = float(np.sqrt(max(12.0 * i1 / m - 3.0 * radius**2, 0.0)))
        return Form("disc", (radius, width), 2)
    return Form("box", tuple(float(h) for h in half))


def outline_points(body: Body, state: BodyState) -> tuple[str, np.ndarray, float] | None:
    """What to draw: ('circle', centre, radius) for a sphere, ('solid', points, 0) for a disc (its two
    rims; the picture takes their outline) or a box (its eight corners), in global coordinates."""
    shape = form(body)
    if shape is None or state.rotation is None or body.principal_axes is None:
        return None
    centre = np.asarray(state.position[:3], dtype=float)
    if shape.kind == "sphere":
        return "circle", centre[None, :], shape.sizes[0]
    to_global = state.rotation @ body.principal_axes  # principal axes in global terms (columns)
    if shape.kind == "disc":
        radius, width = shape.sizes
        angles = np.linspace(0.0, 2 * np.pi, _RIM, endpoint=False)
        u, v, a = (to_global[:, (shape.axis + k) % 3] for k in (1, 2, 0))
        rim = np.cos(angles)[:, None] * u + np.sin(angles)[:, None] * v
        points = np.vstack([centre + radius * rim + s * 0.5 * width * a for s in (-1.0, 1.0)])
        return "solid", points, 0.0
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    return "solid", centre + (signs * np.asarray(shape.sizes)) @ to_global.T, 0.0


def form_words(body: Body, state: BodyState) -> str:
    """The drawn shape in words (the picture for models without images)."""
    shape = form(body)
    if shape is None or state.rotation is None or body.principal_axes is None:
        return "a point"
    if shape.kind == "sphere":
        return f"a sphere of radius {num(shape.sizes[0])} m"
    if shape.kind == "disc":
        axle = state.rotation @ body.principal_axes[:, shape.axis]
        return f"a disc of radius {num(shape.sizes[0])} m and width {num(shape.sizes[1])} m, axle along {vec(axle)}"
    half = np.asarray(shape.sizes)
    long_axis = state.rotation @ body.principal_axes[:, int(np.argmax(half))]
    return f"a box {' x '.join(num(2 * h) for h in half)} m, longest edge along {vec(long_axis)}"
