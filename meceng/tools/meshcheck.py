"""The mesh-size pre-check of part programs (paper section 2.4).

A part program must hard-code its mesh size, ``GenerateMesh(maxh=0.01)``, so the size is known
before anything runs. Missing or computed ``maxh``: the program is flagged and not run. A ``maxh``
finer than the minimum derived from the ground truth's bounding box is raised to that minimum,
silently: an overly fine mesh is impractical, not wrong.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from meceng.syntax import parse


@dataclass(frozen=True)
class MeshCheck:
    code: str | None
    maxh: tuple[float, ...] = ()
    raised: bool = False
    error: str | None = None


def _literal(node: ast.expr) -> float | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, int | float) and not isinstance(node.value, bool):
        return float(node.value)
    return None


def check_mesh_size(code: str, minimum: float) -> MeshCheck:
    """Find every ``GenerateMesh`` call; require a literal ``maxh``; raise values below ``minimum``."""
    try:
        tree = parse(code)
    except SyntaxError as exc:
        return MeshCheck(None, error=f"syntax error: {exc.msg}")
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Call)
             and (getattr(n.func, "attr", None) == "GenerateMesh" or getattr(n.func, "id", None) == "GenerateMesh")]
    if not calls:
        return MeshCheck(None, error="no GenerateMesh(maxh=...) call: the part is not meshed")
    lines = code.splitlines(keepends=True)
    replacements: list[tuple[int, int, int, str]] = []
    values = []
    for call in calls:
        keyword = next((k for k in call.keywords if k.arg == "maxh"), None)
        value = _literal(keyword.value) if keyword is not None else None
        if keyword is None or value is None:
            return MeshCheck(None, error=f"GenerateMesh in line {call.lineno} has no hard-coded maxh: flagged, not run")
        if value <= 0:
            return MeshCheck(None, error=f"maxh must be positive (line {call.lineno})")
        values.append(value)
        if value < minimum:
            node = keyword.value
            replacements.append((node.lineno, node.col_offset, node.end_col_offset or node.col_offset, repr(minimum)))
    for line, start, end, text in sorted(replacements, reverse=True):
        source = lines[line - 1]
        lines[line - 1] = source[:start] + text + source[end:]
    return MeshCheck("".join(lines), tuple(values), raised=bool(replacements))
