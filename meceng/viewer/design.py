"""A design task's page section (level 4): the spec's quantity against its target band, drawn as a
number line in SVG (the answer's value, and the agent's first program's when it differs), with the
values the answer declared."""

from __future__ import annotations

import html
from typing import Any

WIDTH, HEIGHT, PAD = 640, 74, 30


def _x(value: float, lo: float, hi: float) -> float:
    return PAD + (WIDTH - 2 * PAD) * (value - lo) / (hi - lo)


def design_section(record: dict[str, Any]) -> str:
    design = record.get("design") or {}
    target, tolerance = design.get("target"), design.get("tolerance")
    if target is None or not tolerance:
        return "<p class='muted'>no design outcome recorded</p>"
    first = (record.get("agent") or {}).get("first_design") or {}
    marks = [("final answer", design.get("value"), "#1a7f37" if design.get("passed") else "#cf222e")]
    if first.get("value") is not None and first.get("values") != design.get("values"):
        marks.insert(0, ("first program", first["value"], "#888"))
    shown = [v for _, v, _ in marks if isinstance(v, int | float)]
    lo = min([target - 3 * tolerance, *shown])
    hi = max([target + 3 * tolerance, *shown])
    span = (hi - lo) * 0.05 or tolerance
    lo, hi = lo - span, hi + span
    band = (f"<rect x='{_x(target - tolerance, lo, hi):.1f}' y='14' width='"
            f"{_x(target + tolerance, lo, hi) - _x(target - tolerance, lo, hi):.1f}' height='26' fill='#d7f0dc'/>"
            f"<line x1='{_x(target, lo, hi):.1f}' x2='{_x(target, lo, hi):.1f}' y1='10' y2='44' stroke='#1a7f37' "
            "stroke-dasharray='3,2'/>")
    axis = (f"<line x1='{PAD}' x2='{WIDTH - PAD}' y1='40' y2='40' stroke='#444'/>"
            f"<text x='{PAD}' y='58' font-size='11'>{lo:.4g}</text>"
            f"<text x='{WIDTH - PAD}' y='58' font-size='11' text-anchor='end'>{hi:.4g}</text>"
            f"<text x='{_x(target, lo, hi):.1f}' y='70' font-size='11' text-anchor='middle'>target {target:g} ± "
            f"{tolerance:.3g}</text>")
    dots = "".join(f"<circle cx='{_x(v, lo, hi):.1f}' cy='27' r='5' fill='{color}'><title>{html.escape(name)}: "
                   f"{v:.6g}</title></circle>" for name, v, color in marks if isinstance(v, int | float))
    svg = (f"<svg class='design' width='{WIDTH}' height='{HEIGHT}' role='img' aria-label='the spec quantity "
           f"against its target band'>{band}{axis}{dots}</svg>")
    legend = " · ".join(f"<span style='color:{c}'>●</span> {html.escape(n)} {v:.6g}" if isinstance(v, int | float)
                        else f"{html.escape(n)}: none" for n, v, c in marks)
    margin = design.get("margin")
    return (f"<p>{html.escape(str(design.get('quantity', '')))} ({html.escape(str(design.get('unit', '')))}): "
            f"{legend}; green band: the target ± its tolerance"
            + (f"; margin {margin:.3g} (1 on target, 0 at the edge)" if isinstance(margin, int | float) else "")
            + f"</p>{svg}<p>declared DESIGN: <code>{html.escape(str(design.get('values')))}</code></p>")
