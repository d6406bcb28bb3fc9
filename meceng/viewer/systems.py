"""The system's picture on a task page: the program's beside the ground truth's, at t = 0 and at
the end, in the snapshot's four views, as inline SVG.

The shapes come from the record's traces file (``scenes``, written at grading); SVG costs
milliseconds per record, so every rigid and assembly record gets its picture, not only failures.
Each view shares one scale across the four rows, so a misplaced body or a turned axis shows as
a difference between the program's rows and the ground truth's.
"""

from __future__ import annotations

import json
from html import escape
from typing import Any

import numpy as np

from meceng.inspect.scene import COLOURS, LEGEND, VIEWS, Projection, Shape, bounds, hull

WIDTH, HEIGHT = 230, 170


def _number(x: float) -> str:
    return f"{x:.4g}"


def _svg(shapes: list[Shape], projection: Projection, low: np.ndarray, high: np.ndarray) -> str:
    span = np.maximum(high - low, 1e-9)
    scale = min(WIDTH / span[0], HEIGHT / span[1])
    offset = np.array([(WIDTH - span[0] * scale) / 2, (HEIGHT - span[1] * scale) / 2])

    def screen(points: np.ndarray) -> np.ndarray:
        xy = (projection.apply(points) - low) * scale + offset
        xy[:, 1] = HEIGHT - xy[:, 1]  # SVG's y grows downwards
        return xy

    out = []
    for shape in shapes:
        colour = COLOURS[shape.role]
        xy = screen(np.asarray(shape.points))
        if shape.kind == "box":
            points = " ".join(f"{x:.1f},{y:.1f}" for x, y in hull(xy))
            out.append(f"<polygon points='{points}' fill='{colour}' fill-opacity='0.35' stroke='{colour}'/>")
        elif shape.kind in ("line", "arrow"):
            dash = " stroke-dasharray='4 2'" if shape.role == "distance" else ""
            head = " marker-end='url(#head)'" if shape.kind == "arrow" else ""
            out.append(f"<line x1='{xy[0, 0]:.1f}' y1='{xy[0, 1]:.1f}' x2='{xy[1, 0]:.1f}' y2='{xy[1, 1]:.1f}' "
                       f"stroke='{colour}' stroke-width='1.5'{dash}{head}/>")
        elif shape.kind == "point":
            size = 7 if shape.role == "ground" else 5
            if shape.role == "ground":
                out.append(f"<rect x='{xy[0, 0] - size / 2:.1f}' y='{xy[0, 1] - size / 2:.1f}' width='{size}' "
                           f"height='{size}' fill='{colour}'/>")
            else:
                fill = "none" if shape.role == "joint" else colour
                out.append(f"<circle cx='{xy[0, 0]:.1f}' cy='{xy[0, 1]:.1f}' r='{size / 2 + 0.5}' fill='{fill}' "
                           f"stroke='{colour}'/>")
        elif shape.kind == "circle":
            out.append(f"<circle cx='{xy[0, 0]:.1f}' cy='{xy[0, 1]:.1f}' r='{shape.radius * scale:.1f}' "
                       f"fill='none' stroke='{colour}'/>")
        elif shape.kind == "label":
            out.append(f"<text x='{xy[0, 0] + 3:.1f}' y='{xy[0, 1] - 3:.1f}'>{escape(shape.text)}</text>")
    frame = (f"<text class='ax' x='2' y='{HEIGHT - 3}'>{_number(low[0])}…{_number(high[0])} m</text>")
    return (f"<svg class='system' viewBox='0 0 {WIDTH} {HEIGHT}' width='{WIDTH}' height='{HEIGHT}' "
            f"xmlns='http://www.w3.org/2000/svg'>"
            "<defs><marker id='head' markerWidth='6' markerHeight='6' refX='5' refY='3' orient='auto'>"
            f"<path d='M0,0 L6,3 L0,6 z' fill='{COLOURS['load']}'/></marker></defs>"
            f"{''.join(out)}{frame}</svg>")


def system_pictures(scenes_json: Any) -> str | None:
    """The HTML table of pictures from a traces file's ``scenes`` entry, or None."""
    try:
        scenes = json.loads(str(scenes_json))
    except (TypeError, ValueError):
        return None
    rows: list[tuple[str, list[Shape]]] = []
    for prefix, who in (("cand", "program"), ("ref", "ground truth")):
        entry = scenes.get(prefix)
        if not entry:
            continue
        for t, shapes in zip(entry["times"], entry["shapes"], strict=False):
            rows.append((f"{who}, t = {_number(float(t))} s", [Shape.from_json(s) for s in shapes]))
    if not rows:
        return None
    head = "".join(f"<th>{escape(p.name)}</th>" for p in VIEWS)
    limits = [bounds([shapes for _, shapes in rows], p) for p in VIEWS]
    body = "".join(
        f"<tr><th>{escape(label)}</th>"
        + "".join(f"<td>{_svg(shapes, p, low, high)}</td>" for p, (low, high) in zip(VIEWS, limits, strict=True))
        + "</tr>" for label, shapes in rows)
    missing = "" if scenes.get("cand") else "<p class='muted'>the program built no system to draw</p>"
    return (f"{missing}<table class='systems'><tr><th></th>{head}</tr>{body}</table>"
            f"<p class='muted'>{escape(LEGEND)}; each view keeps one scale in all rows</p>")
