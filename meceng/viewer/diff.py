"""Side-by-side diff of the extracted program and the reference program, as an HTML table.

``difflib.HtmlDiff`` does the same but costs 10-50 ms a pair (its intraline pass runs ndiff over
the whole file); a site of 20 000 records must write a page in a few ms. Here lines are matched
with ``SequenceMatcher`` once and only lines of a replaced block are compared character-wise.
"""

from __future__ import annotations

import difflib
import html


def _marked(a: str, b: str) -> tuple[str, str]:
    """Two changed lines with the changed characters wrapped in <mark>."""
    if len(a) + len(b) > 600:  # a long generated line: mark it whole, not character by character
        return f"<mark>{html.escape(a)}</mark>", f"<mark>{html.escape(b)}</mark>"
    left, right = [], []
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        x, y = html.escape(a[i1:i2]), html.escape(b[j1:j2])
        if op == "equal":
            left.append(x)
            right.append(y)
        else:
            left.append(f"<mark>{x}</mark>" if x else "")
            right.append(f"<mark>{y}</mark>" if y else "")
    return "".join(left), "".join(right)


def _row(kind: str, n1: int | None, t1: str, n2: int | None, t2: str) -> str:
    return (f"<tr class='{kind}'><td class='n'>{'' if n1 is None else n1}</td><td class='l'>{t1}</td>"
            f"<td class='n'>{'' if n2 is None else n2}</td><td class='r'>{t2}</td></tr>")


def side_by_side(program: str, reference: str, context: int = 3) -> tuple[str, int]:
    """The HTML table (program left, reference right; equal stretches longer than 2 x ``context``
    folded) and the number of changed lines."""
    a, b = program.splitlines(), reference.splitlines()
    rows: list[str] = []
    changed = 0
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if op == "equal":
            span = i2 - i1
            keep = range(span) if span <= 2 * context + 1 else [*range(context), -1, *range(span - context, span)]
            for k in keep:
                if k == -1:
                    rows.append(f"<tr class='fold'><td colspan='4'>⋯ {span - 2 * context} equal lines ⋯</td></tr>")
                else:
                    text = html.escape(a[i1 + k])
                    rows.append(_row("eq", i1 + k + 1, text, j1 + k + 1, text))
            continue
        changed += max(i2 - i1, j2 - j1)
        for k in range(max(i2 - i1, j2 - j1)):
            left = a[i1 + k] if i1 + k < i2 else None
            right = b[j1 + k] if j1 + k < j2 else None
            if left is not None and right is not None:
                t1, t2 = _marked(left, right)
                rows.append(_row("chg", i1 + k + 1, t1, j1 + k + 1, t2))
            elif left is not None:
                rows.append(_row("add", i1 + k + 1, html.escape(left), None, ""))
            else:
                rows.append(_row("del", None, "", j1 + k + 1, html.escape(right or "")))
    table = ("<table class='diff'><colgroup><col class='n'><col><col class='n'><col></colgroup>"
             "<thead><tr><th colspan='2'>extracted program</th>"
             "<th colspan='2'>reference program</th></tr></thead><tbody>" + "".join(rows) + "</tbody></table>")
    return table, changed
