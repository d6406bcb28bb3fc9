"""The consensus section of a task page (``--agent consensus``): the groups the samples formed by
how they move, which sample answered and with what confidence, every sample's own verdicts against
the ground truth, and what each pair comparison said. No script: plain tables and details."""

from __future__ import annotations

import html
from typing import Any

from meceng.viewer.diff import side_by_side


def _esc(value: Any) -> str:
    return html.escape(str(value), quote=True)


def _verdict(sample: dict[str, Any]) -> tuple[str, str]:
    """(css class, words) of a sample's paper verdict against the ground truth."""
    if sample.get("lost"):
        return "na", f"lost: {sample['lost']}"
    if "overall" not in sample:
        return "na", "not graded"
    if sample["overall"]:
        return "pass", "passed"
    return "fail", f"failed at {sample.get('first_failure')}"


def _group_colour(index: int | None) -> str:
    palette = ("#3a7bd5", "#e08a2e", "#7a4fb5", "#2e9e8f", "#c24d7c", "#8a8a2e", "#5c6b7a")
    return "#bbb" if index is None else palette[index % len(palette)]


def consensus_section(block: dict[str, Any]) -> str:
    samples = block.get("samples", [])
    groups = block.get("groups", [])
    counted = block.get("counted") or sum(1 for s in samples if not s.get("lost"))
    chosen = block.get("chosen")
    head = (f"<table class='kv'><tr><th>samples</th><td>{_esc(block.get('k', len(samples)))} drawn, {_esc(counted)} "
            f"answered by the server</td></tr><tr><th>groups</th><td>{_esc(len(groups))} (sizes "
            f"{_esc(', '.join(str(len(g)) for g in groups) or 'none')})</td></tr>"
            f"<tr><th>answer</th><td>sample #{_esc(chosen)} of group 1</td></tr>"
            f"<tr><th>confidence</th><td><b>{_esc(block.get('confidence'))}</b> (the largest group's share; the "
            f"grouping never saw the ground truth)</td></tr>")
    if block.get("models"):  # a consensus run across models (--consensus-models)
        models = block["models"]
        head += (f"<tr><th>models</th><td>{_esc(', '.join(models))} (sample k written by model k mod "
                 f"{len(models)})</td></tr>")
    head += "</table>"
    bars = "".join(f"<span class='cgroup' style='background:{_group_colour(g)};flex:{len(members)}'>"
                   f"group {g + 1}: {len(members)} sample{'s' if len(members) != 1 else ''}</span>"
                   for g, members in enumerate(groups))
    # which model wrote each sample (``model``, recorded since consensus across models; k mod M)
    by_model = any(s.get("model") for s in samples)
    rows = []
    for s in samples:
        cls, words = _verdict(s)
        behaviour = {True: "moves as the ground truth", False: "moves otherwise", None: "–"}[s.get("behaviour_passed")]
        status = {True: "ok", False: "bad"}.get(s.get("behaviour_passed"), "")
        group = s.get("group")
        tag = (f"<span class='cdot' style='background:{_group_colour(group)}'></span> {group + 1}"
               if group is not None else "–")
        mark = " ← answer" if s.get("index") == chosen else ""
        rows.append(f"<tr class='{cls}'><td>#{_esc(s.get('index'))}{_esc(mark)}</td><td>{tag}</td>"
                    + (f"<td>{_esc(s.get('model') or '–')}</td>" if by_model else "")
                    + f"<td>{_esc(s.get('seed'))}</td><td>{_esc(s.get('endpoint') or '')}</td>"
                    f"<td>{'yes' if s.get('ran') else 'no'}</td><td class='verdict'>{_esc(words)}</td>"
                    f"<td class='{status}'>{_esc(behaviour)}</td></tr>")
    table = ("<table class='consensus'><tr><th>sample</th><th>group</th>" + ("<th>model</th>" if by_model else "")
             + "<th>seed</th><th>answered by</th>"
             "<th>ran</th><th>paper's verdict (ground truth)</th><th>behaviour (ground truth)</th></tr>"
             + "".join(rows) + "</table>")
    out = [head, f"<div class='cbars'>{bars}</div>", table]
    answer = next((s for s in samples if s.get("index") == chosen), None)
    for g, members in enumerate(groups[1:], start=2):
        other = next((s for s in samples if s.get("index") == members[0]), None)
        if answer and other and answer.get("code") and other.get("code") and other["code"] != answer["code"]:
            diff, changed = side_by_side(other["code"], answer["code"])
            out.append(f"<details><summary>group {g}: sample #{_esc(members[0])} beside the answer ({changed} changed "
                       f"line(s))</summary><div class='diffwrap'>{diff}</div></details>")
    pairs = "".join(f"<tr class='{'pass' if a['agree'] else 'fail'}'><td>#{_esc(a['a'])} – #{_esc(a['b'])}</td>"
                    f"<td>{'agree' if a['agree'] else 'differ'}</td><td class='detail'>{_esc(a['detail'])}</td></tr>"
                    for a in block.get("agreements", []))
    if pairs:
        out.append("<details><summary>every pair compared (at the smaller of the two motions' scales)"
                   f"</summary><table class='stages'>{pairs}</table></details>")
    return "".join(out)
