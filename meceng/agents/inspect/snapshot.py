"""A picture of what a program built: its system at t = 0 and at a later time, or its part.

Drawn headless with matplotlib (Agg) from a system view: rigid bodies as inertia-equivalent boxes
(the box with the body's mass and principal moments, turned with the body), mass points as dots,
the ground as a grey square, joints at their points with their axes, springs and distance
constraints as lines, contact spheres as circles, loads as arrows. Three orthogonal views and an
isometric one per row, axes labelled in metres. Text-only models get ``describe`` instead.
"""

from __future__ import annotations

import io
from collections.abc import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle, Polygon
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from meceng.agents.inspect.answer import num, vec
from meceng.agents.inspect.view import Body, BodyState, Connector, SystemView

#: (title, the two global axes shown) of the orthogonal views
VIEWS = (("top: x-y (looking down z)", (0, 1)), ("front: x-z (looking along y)", (0, 2)),
         ("side: y-z (looking along x)", (1, 2)))
_AXIS = "xyz"
_BOX_FACES = ((0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5))
_COLORS = {"SpringDamper": "tab:green", "CartesianSpringDamper": "tab:green", "DistanceConstraint": "tab:purple",
           "SphereSphereContact": "tab:orange", "TorsionalSpringDamper": "tab:green"}
_JOINTS = frozenset({"RevoluteJoint", "PrismaticJoint", "SphericalJoint", "GenericJoint", "RollingDisc"})


def box_half_sizes(body: Body) -> np.ndarray | None:
    """Half edge lengths of the homogeneous box with the body's mass and principal moments."""
    if body.principal_inertia is None or body.mass is None or body.mass <= 0 or len(body.principal_inertia) != 3:
        return None
    i1, i2, i3 = body.principal_inertia
    squares = 6.0 / body.mass * np.array([i2 + i3 - i1, i1 + i3 - i2, i1 + i2 - i3])
    return 0.5 * np.sqrt(np.clip(squares, 0.0, None))


def box_corners(body: Body, state: BodyState) -> np.ndarray | None:
    """The 8 corners of the inertia-equivalent box in global coordinates, or None (no orientation)."""
    half = box_half_sizes(body)
    if half is None or state.rotation is None or body.principal_axes is None:
        return None
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    local = (signs * half) @ body.principal_axes.T
    return np.asarray(state.position) + local @ state.rotation.T


def _sample_index(view: SystemView, t: float) -> int:
    return int(np.argmin([abs(s - t) for s in view.times])) if view.times else 0


def _markers(view: SystemView, k: int) -> dict[int, tuple[float, ...]]:
    return view.marker_states[k] if k < len(view.marker_states) else {}


def _connector_points(c: Connector, markers: dict[int, tuple[float, ...]]) -> list[np.ndarray]:
    return [np.asarray(markers[m][:3]) for m in c.markers if m in markers and len(markers[m]) >= 3]


def _scene_size(view: SystemView) -> float:
    points = [s.position for b in view.bodies for s in b.states if len(s.position) >= 3]
    points += [p for markers in view.marker_states for p in markers.values() if len(p) >= 3]
    if not points:
        return 1.0
    array = np.asarray(points, dtype=float)[:, :3]
    return float(max(np.ptp(array, axis=0).max(), 1e-3))


def _draw_2d(ax: plt.Axes, view: SystemView, k: int, axes: tuple[int, int], size: float) -> None:
    i, j = axes
    t = view.times[k] if view.times else 0.0
    markers = _markers(view, k)
    for c in view.connectors:
        points = _connector_points(c, markers)
        if len(points) == 2 and c.kind not in _JOINTS:
            style = "--" if c.kind == "DistanceConstraint" else "-"
            ax.plot([points[0][i], points[1][i]], [points[0][j], points[1][j]], style,
                    color=_COLORS.get(c.kind, "tab:gray"), lw=1)
            if c.kind == "SphereSphereContact":
                radii = c.parameters.get("spheresRadii") or []
                for point, radius in zip(points, radii, strict=False):
                    ax.add_patch(Circle((point[i], point[j]), float(radius), fill=False, color="tab:orange", lw=0.8))
        elif points and c.kind in _JOINTS:
            p = points[0]
            ax.plot(p[i], p[j], "o", color="tab:red", ms=5, mfc="none")
            if c.axis is not None and k == 0:
                a = np.asarray(c.axis) * 0.12 * size
                ax.plot([p[i] - a[i], p[i] + a[i]], [p[j] - a[j], p[j] + a[j]], color="tab:red", lw=1.5)
    for body in view.bodies:
        state = body.state_at(t)
        if state is None or len(state.position) < 3:
            continue
        corners = box_corners(body, state)
        if body.is_ground:
            ax.plot(state.position[i], state.position[j], "s", color="0.4", ms=8)
        elif corners is not None:
            hull = _hull(corners[:, [i, j]])
            ax.add_patch(Polygon(hull, closed=True, alpha=0.35, color="tab:blue"))
        else:
            ax.plot(state.position[i], state.position[j], "o", color="tab:blue", ms=6)
        ax.annotate(f"#{body.index}", (state.position[i], state.position[j]), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    for load in view.loads:
        if load.vector is None or load.body is None or len(load.vector) < 3:
            continue
        body = view.body(load.body)
        state = body.state_at(t) if body else None
        if state is None or "Gravity" in load.kind:
            continue
        direction = np.asarray(load.vector[:3]) / (np.linalg.norm(load.vector[:3]) or 1.0) * 0.15 * size
        ax.annotate("", (state.position[i] + direction[i], state.position[j] + direction[j]),
                    (state.position[i], state.position[j]), arrowprops={"arrowstyle": "->", "color": "tab:brown"})
    ax.set_xlabel(f"{_AXIS[i]} [m]", fontsize=7)
    ax.set_ylabel(f"{_AXIS[j]} [m]", fontsize=7)
    ax.tick_params(labelsize=6)
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()


def _hull(points: np.ndarray) -> np.ndarray:
    """Convex hull of 2D points (monotone chain): the outline of a projected box."""
    pts = sorted({(round(float(x), 12), round(float(y), 12)) for x, y in points})
    if len(pts) < 3:
        return np.asarray(pts + pts[:1])

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


def _draw_3d(ax: plt.Axes, view: SystemView, k: int, size: float) -> None:
    t = view.times[k] if view.times else 0.0
    markers = _markers(view, k)
    for c in view.connectors:
        points = _connector_points(c, markers)
        if len(points) == 2 and c.kind not in _JOINTS:
            ax.plot(*np.asarray(points).T, "--" if c.kind == "DistanceConstraint" else "-",
                    color=_COLORS.get(c.kind, "tab:gray"), lw=1)
        elif points and c.kind in _JOINTS:
            p = points[0]
            ax.scatter(*p, color="tab:red", s=14)
            if c.axis is not None and k == 0:
                a = np.asarray(c.axis) * 0.12 * size
                ax.plot(*np.asarray([p - a, p + a]).T, color="tab:red", lw=1.5)
    for body in view.bodies:
        state = body.state_at(t)
        if state is None or len(state.position) < 3:
            continue
        corners = box_corners(body, state)
        if body.is_ground:
            ax.scatter(*state.position[:3], color="0.4", marker="s", s=30)
        elif corners is not None:
            ax.add_collection3d(Poly3DCollection([corners[list(f)] for f in _BOX_FACES], alpha=0.3,
                                                 facecolor="tab:blue", edgecolor="navy", linewidths=0.3))
        else:
            ax.scatter(*state.position[:3], color="tab:blue", s=18)
        ax.text(*state.position[:3], f"#{body.index}", fontsize=6)
    ax.set_xlabel("x [m]", fontsize=7)
    ax.set_ylabel("y [m]", fontsize=7)
    ax.set_zlabel("z [m]", fontsize=7)
    ax.tick_params(labelsize=5)
    ax.view_init(elev=30.0, azim=-60.0)
    _equal_3d(ax, view, k)


def _equal_3d(ax: plt.Axes, view: SystemView, k: int) -> None:
    t = view.times[k] if view.times else 0.0
    points = [b.state_at(t).position[:3] for b in view.bodies if b.state_at(t) is not None]
    points += [p[:3] for p in _markers(view, k).values() if len(p) >= 3]
    if not points:
        return
    array = np.asarray(points, dtype=float)
    centre = (array.max(axis=0) + array.min(axis=0)) / 2
    half = max(float(np.ptp(array, axis=0).max()) / 2 * 1.15, 1e-3)
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)


def draw(view: SystemView, times: Sequence[float], title: str = "") -> bytes:
    """PNG bytes: one row per time (three orthogonal views and an isometric one)."""
    size = _scene_size(view)
    rows = [_sample_index(view, t) for t in times] or [0]
    fig = plt.figure(figsize=(13, 3.3 * len(rows)), dpi=80)
    for r, k in enumerate(rows):
        t = view.times[k] if view.times else 0.0
        for c, (name, axes) in enumerate(VIEWS):
            ax = fig.add_subplot(len(rows), 4, r * 4 + c + 1)
            _draw_2d(ax, view, k, axes, size)
            ax.set_title(f"t = {num(t)} s — {name}", fontsize=8)
        ax3 = fig.add_subplot(len(rows), 4, r * 4 + 4, projection="3d")
        _draw_3d(ax3, view, k, size)
        ax3.set_title(f"t = {num(t)} s — isometric", fontsize=8)
    legend = ("blue: bodies (rigid bodies as inertia-equivalent boxes, mass points as dots), grey square: ground, "
              "red: joints and their axes, green: springs, purple dashed: distance constraints, orange: contacts, "
              "brown arrows: forces")
    fig.suptitle((title + "\n" if title else "") + legend, fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    return buffer.getvalue()


def describe(view: SystemView, times: Sequence[float], limit: int = 16) -> str:
    """The picture in words, for models that take no images."""
    lines = []
    for t in times:
        k = _sample_index(view, t)
        at = view.times[k] if view.times else 0.0
        lines.append(f"at t = {num(at)} s:")
        shown = 0
        for body in view.moving_bodies():
            state = body.state_at(at)
            if state is None:
                continue
            shown += 1
            if shown > limit:
                lines.append(f"  … {len(view.moving_bodies()) - limit} more bodies (simulate(code, bodies=[...]))")
                break
            half = box_half_sizes(body)
            shape = "a point"
            if half is not None and state.rotation is not None and body.principal_axes is not None:
                long_axis = state.rotation @ body.principal_axes[:, int(np.argmax(half))]
                shape = (f"a box {' x '.join(num(2 * h) for h in half)} m, longest edge along {vec(long_axis)}")
            lines.append(f"  {body.label} at {vec(state.position)}: {shape}")
        markers = _markers(view, k)
        for c in view.connectors[:limit]:
            points = _connector_points(c, markers)
            axis = f", axis {vec(c.axis)}" if c.axis and k == 0 else ""
            if (c.kind in _JOINTS and points) or (len(points) == 2 and np.allclose(points[0], points[1])):
                lines.append(f"  {c.label} at {vec(points[0])}{axis}")
            elif len(points) == 2:
                lines.append(f"  {c.label} from {vec(points[0])} to {vec(points[1])}")
        if len(view.connectors) > limit:
            lines.append(f"  … {len(view.connectors) - limit} more connectors")
    return "\n".join(lines)


def shaded_surface(vertices: np.ndarray, triangles: np.ndarray, colour: tuple[float, float, float],
                   alpha: float = 1.0) -> Poly3DCollection:
    """A triangulated surface lit from one direction, so edges and holes read in a still picture."""
    faces = vertices[triangles]
    normals = np.cross(faces[:, 1] - faces[:, 0], faces[:, 2] - faces[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True) + 1e-30
    light = np.abs(normals @ np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8]))
    shade = (0.35 + 0.65 * light)[:, None] * np.array(colour)[None, :]
    return Poly3DCollection(faces, facecolors=np.clip(shade, 0, 1), edgecolors=(0, 0, 0, 0.15), linewidths=0.2,
                            alpha=alpha)


#: (elevation, azimuth, title) of the part's views: three orthogonal and an isometric one
PART_VIEWS = ((90.0, -90.0, "top: x-y"), (0.0, -90.0, "front: x-z"), (0.0, 0.0, "side: y-z"),
              (30.0, -60.0, "isometric"))


def draw_part(surface: tuple[np.ndarray, np.ndarray], interfaces: dict[str, dict | None]) -> bytes:
    """PNG bytes of a part's surface from four views, every interface's centre marked and named."""
    vertices, triangles = (np.asarray(surface[0], float), np.asarray(surface[1]))
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    extent = np.maximum(high - low, 0.02 * float(np.max(high - low)) or 1.0)
    fig = plt.figure(figsize=(13, 3.6), dpi=80)
    for col, (elev, azim, name) in enumerate(PART_VIEWS):
        ax = fig.add_subplot(1, 4, col + 1, projection="3d")
        if col < 3:
            ax.set_proj_type("ortho")
        ax.add_collection3d(shaded_surface(vertices, triangles, (0.75, 0.75, 0.8), alpha=0.6))
        for label, data in interfaces.items():
            if data and data.get("centre"):
                ax.scatter(*data["centre"], color="tab:red", s=12)
                ax.text(*data["centre"], f" {label}", fontsize=7, color="tab:red")
        for k, axis in enumerate("xyz"):
            getattr(ax, f"set_{axis}lim")(low[k] - 0.04 * extent[k], high[k] + 0.04 * extent[k])
            getattr(ax, f"set_{axis}label")(f"{axis} [m]", fontsize=7)
        ax.set_box_aspect(tuple(extent * 1.08))
        ax.tick_params(labelsize=5)
        ax.view_init(elev=elev, azim=azim)
        ax.set_title(name, fontsize=8)
    fig.suptitle("the program's part; red: interface centres", fontsize=8)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.02, top=0.88, wspace=0.05)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    return buffer.getvalue()


def describe_part(surface: tuple[np.ndarray, np.ndarray], interfaces: dict[str, dict | None]) -> str:
    vertices = np.asarray(surface[0], float)
    lines = [f"a part spanning {vec(vertices.min(axis=0))} to {vec(vertices.max(axis=0))} m, "
             f"{len(surface[1])} surface triangles"]
    for label, data in interfaces.items():
        if data:
            lines.append(f"  interface '{label}': centre {vec(data.get('centre'))}, mean outward normal "
                         f"{vec(data.get('mean_normal'))}, area {num(float(data.get('area') or 0.0))} m²")
    return "\n".join(lines)
