"""A picture of what a program built: its system at t = 0 and at a later time, or its part.

Drawn headless with matplotlib (Agg) from the scene of a system view (``scene.py``): rigid bodies
as inertia-equivalent boxes (the box with the body's mass and principal moments, turned with the
body), mass points as dots, the ground as a grey square, joints at their points with their axes,
springs and distance constraints as lines, contact spheres as circles, loads as arrows. Three
orthogonal views and an isometric one per row, axes labelled in metres. Text-only models get
``describe`` instead.
"""

from __future__ import annotations

import io
import textwrap
from collections.abc import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection, PatchCollection
from matplotlib.patches import Circle, Polygon
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from meceng.inspect.answer import num, vec
from meceng.inspect.forms import form, form_words
from meceng.inspect.geometry import placed, rolling_frame
from meceng.inspect.scene import (
    COLOURS,
    JOINTS,
    LEGEND,
    VIEWS,
    Projection,
    Shape,
    bounds,
    build_scene,
    connector_points,
    hull,
    joint_axis,
    sample_index,
)
from meceng.inspect.system import SystemView, direction

_AXIS_NAMES = "xyz"
MAX_LABELS = 40  # body numbers per panel; a larger system names the first ones


def _axis_label(vector: tuple[float, ...]) -> str:
    k = int(np.argmax(np.abs(vector)))
    return f"{'-' if vector[k] < 0 else ''}{_AXIS_NAMES[k]} [m]" if abs(vector[k]) > 0.999 else ""


def draw_shapes(ax: plt.Axes, shapes: Sequence[Shape], projection: Projection, span: np.ndarray | None = None) -> None:
    """One scene in one view on 2D matplotlib axes: shapes of a kind go in one collection (a grid of
    hundreds of springs draws in a fraction of the time of one artist each)."""
    polygons, lines, dashed, circles, points, labels = [], [], [], [], [], []
    for shape in shapes:
        xy = projection.apply(np.asarray(shape.points))
        colour = COLOURS[shape.role]
        if shape.kind == "box":
            polygons.append((hull(xy), colour))
        elif shape.kind == "line":
            (dashed if shape.role == "distance" else lines).append((xy, colour, 1.5 if shape.role == "joint" else 1.0))
        elif shape.kind == "point":
            points.append((xy[0], shape.role, colour))
        elif shape.kind == "circle":
            circles.append((xy[0], shape.radius, colour, shape.role == "body"))
        elif shape.kind == "arrow":
            ax.annotate("", (xy[1, 0], xy[1, 1]), (xy[0, 0], xy[0, 1]), arrowprops={"arrowstyle": "->",
                                                                                   "color": colour})
        elif shape.kind == "label":
            labels.append((xy[0], shape.text))
    if polygons:
        ax.add_collection(PatchCollection([Polygon(h, closed=True) for h, _ in polygons], alpha=0.35,
                                          facecolors=[c for _, c in polygons], edgecolors=[c for _, c in polygons],
                                          linewidths=0.6))
    for group, style in ((lines, "solid"), (dashed, "dashed")):
        if group:
            ax.add_collection(LineCollection([xy for xy, _, _ in group], colors=[c for _, c, _ in group],
                                             linewidths=[w for _, _, w in group], linestyles=style))
    if circles:  # a body's sphere filled like its box would be; a contact's circle hollow
        ax.add_collection(PatchCollection([Circle(tuple(c), r) for c, r, _, _ in circles], alpha=0.6,
                                          facecolors=[(c if filled else "none") for _, _, c, filled in circles],
                                          edgecolors=[c for _, _, c, _ in circles], linewidths=0.8))
    for role, marker, size, hollow in (("ground", "s", 40, False), ("joint", "o", 22, True),
                                       ("spherical", "D", 30, False), ("body", "o", 28, False)):
        chosen = [(p, c) for p, r, c in points if r == role]
        if chosen:
            xy = np.array([p for p, _ in chosen])
            colours = [c for _, c in chosen]
            ax.scatter(xy[:, 0], xy[:, 1], s=size, marker=marker, facecolors="none" if hollow else colours,
                       edgecolors=colours, zorder=3)
    for (x, y), text in spread_labels(labels[:MAX_LABELS], span):
        ax.text(x, y, " " + text, fontsize=7, va="bottom", clip_on=True)


def spread_labels(labels: list[tuple[np.ndarray, str]], span: np.ndarray | None
                  ) -> list[tuple[tuple[float, float], str]]:
    """Labels moved apart where they would sit on top of each other: each one that lands within a
    label's size of an earlier one goes one line lower (screen units from the panel's span)."""
    if span is None:
        return [((float(xy[0]), float(xy[1])), text) for xy, text in labels]
    width, height = 0.07 * float(span[0]), 0.06 * float(span[1])
    placed: list[tuple[float, float]] = []
    out = []
    for xy, text in labels:
        x, y = float(xy[0]), float(xy[1])
        while any(abs(x - px) < width and abs(y - py) < height for px, py in placed):
            y -= height
        placed.append((x, y))
        out.append(((x, y), text))
    return out


def _triad(ax: plt.Axes, projection: Projection) -> None:
    """The global axes as seen in a view without axis-aligned screen directions."""
    for k, name in enumerate(_AXIS_NAMES):
        d = projection.apply(np.eye(3)[k])[0] * 0.08
        ax.annotate("", (0.12 + d[0], 0.12 + d[1]), (0.12, 0.12), xycoords="axes fraction",
                    arrowprops={"arrowstyle": "->", "color": "k", "lw": 0.8})
        ax.text(0.12 + 1.3 * d[0], 0.12 + 1.3 * d[1], name, transform=ax.transAxes, fontsize=7)


def _panel(ax: plt.Axes, shapes: Sequence[Shape], projection: Projection, low: np.ndarray, high: np.ndarray,
           title: str) -> None:
    draw_shapes(ax, shapes, projection, high - low)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(_axis_label(projection.right), fontsize=7)
    ax.set_ylabel(_axis_label(projection.up), fontsize=7)
    if not _axis_label(projection.right):
        ax.set_xticks([])
        ax.set_yticks([])
        _triad(ax, projection)
    ax.tick_params(labelsize=6)
    ax.set_title(title, fontsize=8)


def draw(view: SystemView, times: Sequence[float], title: str = "") -> bytes:
    """PNG bytes: one row per time, each with three orthogonal views and an isometric one."""
    scenes = [build_scene(view, t) for t in times] or [build_scene(view, 0.0)]
    stamps = [view.times[sample_index(view, t)] if view.times else 0.0 for t in times] or [0.0]
    fig, grid = plt.subplots(len(scenes), len(VIEWS), figsize=(13, 3.3 * len(scenes)), dpi=80, squeeze=False)
    for c, projection in enumerate(VIEWS):
        for r, (shapes, (low, high)) in enumerate(zip(scenes, _frames(scenes, projection), strict=True)):
            _panel(grid[r, c], shapes, projection, low, high, f"t = {num(stamps[r])} s — {projection.name}")
    words = caption(view, stamps)
    fig.suptitle((title + ": " if title else "") + words + "\n" + textwrap.fill(LEGEND, 190), fontsize=8)
    # fixed margins: tight_layout measured every label and took a large share of a picture's time
    fig.subplots_adjust(left=0.05, right=0.99, bottom=0.1 / len(scenes), top=1 - 0.3 / len(scenes),
                        wspace=0.3, hspace=0.35)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    plt.close(fig)
    return buffer.getvalue()


def _frames(scenes: list[tuple[Shape, ...]], projection: Projection) -> list[tuple[np.ndarray, np.ndarray]]:
    """Each row's screen window in one view: one scale for all rows (motion between them shows),
    and where the system travels far beyond its own size (a car), each row centred on the system,
    so the vehicle is not a dot at either end of its path (the axes' numbers still say where)."""
    low, high = bounds(scenes, projection)
    rows = [bounds([tuple(x for x in scene if x.kind != "label" and (x.kind, x.role) != ("point", "ground"))
                    or scene], projection)
            for scene in scenes]  # the ground's origin (and its label) would stretch every row
    size = max(float(np.max(h - lo)) for lo, h in rows)
    if float(np.max(high - low)) <= 2.5 * size:
        return [(low, high)] * len(scenes)
    span = np.max([h - lo for lo, h in rows], axis=0)
    return [((lo + h) / 2 - span / 2, (lo + h) / 2 + span / 2) for lo, h in rows]


def caption(view: SystemView, stamps: Sequence[float]) -> str:
    """One line saying what the picture shows and when."""
    rows = " and ".join(f"t = {num(t)} s ({'top' if k == 0 else 'next'} row)" for k, t in enumerate(stamps))
    forms: dict[str, int] = {}
    for body in view.moving_bodies():
        state = body.state_at(0.0)
        kind = form(body).kind if state is not None and form(body) is not None else "dot"
        forms[kind] = forms.get(kind, 0) + 1
    drawn = ", ".join(f"{n} as {k}{'s' if n > 1 else ''}" for k, n in forms.items())
    count = len(view.moving_bodies())
    return (f"the system at {rows}, each seen from the top, the front, the side and isometric; "
            f"{count} {'body' if count == 1 else 'bodies'} ({drawn}), {len(view.connectors)} "
            f"connector{'' if len(view.connectors) == 1 else 's'}")


def describe(view: SystemView, times: Sequence[float], limit: int = 16) -> str:
    """The picture in words, for models that take no images."""
    lines = []
    for t in times:
        k = sample_index(view, t)
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
            lines.append(f"  {body.label} at {vec(state.position)}: {form_words(body, state)}")
        for c in view.connectors[:limit]:
            points = connector_points(view, c, k)
            turned = joint_axis(view, c, k) if c.kind in JOINTS else None
            axis = f", axis {vec(turned)}" if turned is not None else ""
            if c.kind == "SphericalJoint":
                axis = " (spherical: all translations locked, every rotation free)"
            rotation = (view.marker_rotations[k] if k < len(view.marker_rotations) else {}).get(
                c.markers[1] if len(c.markers) > 1 else -1)
            if "axis_local" in c.geometry and len(points) == 2 and (frame := rolling_frame(c.geometry, points[1],
                                                                                            rotation)):
                lines.append(f"  {c.label}: contact point {vec(frame['contact'])}, axle along {vec(frame['axis'])}")
            elif "corners" in c.geometry and points:
                corners = placed(c.geometry["triangle_local"], points[-1], rotation)
                lines.append(f"  {c.label}: sphere at {vec(points[0])}, triangle " + ", ".join(map(vec, corners)))
            elif (c.kind in JOINTS and points) or (len(points) == 2 and np.allclose(points[0], points[1])):
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
                         f"{direction(data.get('mean_normal'))}, area {num(float(data.get('area') or 0.0))} m², "
                         f"{data.get('geometry_faces')} geometry face(s)")
    return "\n".join(lines)
