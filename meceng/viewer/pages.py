"""One HTML page per task record: why it passed or failed, everything on one page.

Sections in reading order: the verdict, the stage chain with every detail, the graph
differences by error category, the solution plot, the part's metrics and picture, the programs
side by side, the agent's conversation, the prompts and answers (thinking collapsed), what the
executions reported, and whatever else the record holds (a field added later still shows).
Pages carry no script: nothing on them can fail in a browser.
"""

from __future__ import annotations

import html
import json
from collections import defaultdict
from typing import Any

from meceng.eval.parts import PartTolerances
from meceng.tasks.drafts import without_header
from meceng.viewer.consensus import consensus_section
from meceng.viewer.design import design_section
from meceng.viewer.diff import side_by_side

#: record fields a section below shows; anything else lands in "Other fields"
SHOWN = {"id", "slug", "name", "level", "seed", "params", "description", "required_components", "origin", "stages",
         "overall", "first_failure", "error_categories", "differences", "solution_norm", "infrastructure_error",
         "selection", "generation", "execution", "reference_execution", "timing", "tokens", "files", "evaluator",
         "part", "parts", "agent", "traceback", "topology_causes", "repair",
         "behaviour", "texts", "graded_by", "consensus", "design"}


#: what each kind of task text is, in the page's words (issue 36)
TEXT_WORDS = {"paper": "the paper's (says how to write the program; graded by the paper's stages)",
              "open": "open: the system in an engineer's words (graded by behaviour; topology, graph content and "
                      "solution not required)"}


def _behaviour(block: dict[str, Any]) -> str:
    """The behaviour verdict beside the paper's: its word, the matched bodies, where the motions part
    (the dotted red line on the trajectory plot)."""
    word = {True: "passes", False: "fails", None: "not evaluated"}[block.get("passed")]

    def deviation(d: dict[str, Any] | None) -> str:
        if not d:
            return "–"
        return (f"{d['quantity']} of body {d['body']} (program's {d['candidate_body']}) at t = {_g(d['time'])} s: "
                f"{_g(d['value'])} vs tolerance {_g(d['tolerance'])}")

    scales = ", ".join(f"{name.replace('_', ' ')} {_g(value)}" for name, value in (block.get("scales") or {}).items())

    matched = ", ".join(f"program #{m['candidate']} ↔ ground truth #{m['truth']}" for m in block.get("matching", []))
    return _kv([("behaviour", esc(f"{word}: {block.get('detail', '')}")), ("matched bodies", esc(matched or "none")),
                ("motions part", esc(deviation(block.get("first_divergence")))),
                ("largest deviation", esc(deviation(block.get("largest")))),
                ("tolerance", esc(f"{block.get('relative')} of the scales ({scales}); compared until "
                                  f"{_g(block.get('compared_until'))} s; widened by the step error: "
                                  f"{', '.join(block.get('widened_by_step_error') or []) or 'none'}"))])


def _g(value: Any) -> str:
    """A number as a reader wants it (4 significant digits); anything else as it is."""
    return f"{value:.4g}" if isinstance(value, int | float) and not isinstance(value, bool) else str(value)


def esc(value: Any) -> str:
    return html.escape(str(value), quote=True)


def status_of(passed: bool | None) -> str:
    return {True: "pass", False: "fail"}.get(passed, "na")  # type: ignore[arg-type]


def _pre(text: str | None, cls: str = "") -> str:
    return f"<pre class='{cls}'>{esc(text or '')}</pre>" if text else "<p class='muted'>(empty)</p>"


def _details(summary: str, body: str, open_: bool = False) -> str:
    return f"<details{' open' if open_ else ''}><summary>{summary}</summary>{body}</details>"


def _kv(pairs: list[tuple[str, Any]]) -> str:
    rows = "".join(f"<tr><th>{esc(k)}</th><td>{v}</td></tr>" for k, v in pairs)
    return f"<table class='kv'>{rows}</table>"


def _stages(record: dict[str, Any]) -> str:
    def result(s: dict[str, Any]) -> str:
        if s.get("required", True) is False:  # an open text's writing stages: recorded, not graded
            return "not required"
        return {True: "passed", False: "FAILED"}.get(s.get("passed"), "not evaluated")

    rows = "".join(f"<tr class='{status_of(s.get('passed') if s.get('required', True) else None)}'>"
                   f"<td>{esc(s['name'])}</td><td>{result(s)}</td>"
                   f"<td class='detail'>{esc(s.get('detail', ''))}</td></tr>" for s in record.get("stages", []))
    if not rows:
        return "<p class='muted'>no stage was graded</p>"
    return f"<table class='stages'><thead><tr><th>stage</th><th>result</th><th>detail</th></tr></thead>{rows}</table>"


def _differences(record: dict[str, Any]) -> str:
    groups: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for d in record.get("differences", []):
        groups[str(d.get("category", "other"))].append(d)
    out = []
    for category, items in sorted(groups.items()):
        rows = "".join(f"<tr><td>{esc(d.get('item'))}</td><td>{esc(d.get('key'))}</td><td>{esc(d.get('value'))}</td>"
                       f"<td>{esc(d.get('expected'))}</td></tr>" for d in items)
        out.append(f"<h3>{esc(category)} ({len(items)})</h3><table class='grid'><thead><tr><th>item</th><th>field</th>"
                   f"<th>program</th><th>ground truth</th></tr></thead>{rows}</table>")
    causes = record.get("topology_causes")
    if causes:
        rows = [("cause", esc(causes.get("cause"))),
                ("missing item types", esc(_counts(causes.get("missing")))),
                ("surplus item types", esc(_counts(causes.get("surplus")))),
                ("inert items (cannot affect the motion)", esc(", ".join(causes.get("inert") or []) or "none"))]
        out.append("<h3>topology: why it differs</h3>" + _kv(rows))
    return "".join(out)


def _json(value: Any) -> str:
    return _pre(json.dumps(value, indent=1, default=str), "json")


def _part_metrics(record: dict[str, Any]) -> str:
    """Mass, volume, eigenfrequencies and material of the program's part against the ground
    truth's, with the tolerance each is graded with; the mesh metric is in its stage detail."""
    cand = (record.get("execution") or {}).get("part") or {}
    ref = (record.get("reference_execution") or {}).get("part") or {}
    if not ref:
        return ""
    tol = PartTolerances()

    def rel(a: Any, b: Any) -> str:
        try:
            return f"{100 * abs(float(a) - float(b)) / abs(float(b)):.2f} %"
        except (TypeError, ValueError, ZeroDivisionError):
            return "–"

    def freq(p: dict[str, Any]) -> str:
        return ", ".join(f"{f:.5g}" for f in p.get("eigenfrequencies", [])[:tol.compared_frequencies])

    rows = [("interfaces", cand.get("interfaces"), ref.get("interfaces"), "", "exact"),
            ("Young's modulus (Pa)", cand.get("youngs_modulus"), ref.get("youngs_modulus"), "", "exact"),
            ("Poisson's ratio", cand.get("poissons_ratio"), ref.get("poissons_ratio"), "", "exact"),
            ("density (kg/m³)", cand.get("density"), ref.get("density"), "", "exact"),
            ("mass (kg)", cand.get("mass"), ref.get("mass"), rel(cand.get("mass"), ref.get("mass")),
             f"{100 * tol.mass:g} %"),
            ("volume (m³)", (cand.get("geometry") or {}).get("volume"), (ref.get("geometry") or {}).get("volume"),
             rel((cand.get("geometry") or {}).get("volume"), (ref.get("geometry") or {}).get("volume")),
             f"mesh: {100 * tol.mesh:g} % (stage detail)"),
            (f"first {tol.compared_frequencies} eigenfrequencies (Hz)", freq(cand) if cand else None, freq(ref), "",
             f"{100 * tol.eigenfrequencies:g} % (vector norm)"),
            ("nodes / surface triangles", f"{cand.get('nodes')} / {cand.get('surface_triangles')}" if cand else None,
             f"{ref.get('nodes')} / {ref.get('surface_triangles')}", "", ""),
            ("bounding box (m)", cand.get("bounding_box"), ref.get("bounding_box"), "", "")]
    body = "".join(f"<tr><th>{esc(n)}</th><td>{esc('–' if a is None else a)}</td><td>{esc(b)}</td><td>{esc(e)}</td>"
                   f"<td>{esc(t)}</td></tr>" for n, a, b, e, t in rows)
    return (f"<table class='grid'><thead><tr><th>metric</th><th>program</th><th>ground truth</th><th>error</th>"
            f"<th>tolerance</th></tr></thead>{body}</table>")


def _answer(step: dict[str, Any], title: str) -> str:
    meta = step.get("meta") or {}
    thinking = meta.get("thinking") or ""
    parts = [_details("prompt", _pre(step.get("prompt")))]
    if thinking:
        parts.append(_details(f"thinking ({len(thinking)} characters)", _pre(thinking, "thinking")))
    parts.append(_details("answer", _pre(step.get("answer")), open_=True))
    for key in ("error", "infrastructure_error"):
        if step.get(key):
            parts.append(f"<p class='error'>{esc(key)}: {esc(step[key])}</p>")
    if step.get("names"):
        parts.append(f"<p>parsed components: <code>{esc(', '.join(step['names']))}</code>"
                     + (f"; unknown: <code>{esc(', '.join(step.get('unknown', [])))}</code>"
                        if step.get("unknown") else "") + "</p>")
    shown_meta = {k: v for k, v in meta.items() if k != "thinking"}
    if shown_meta:
        parts.append(_details("response metadata", _json(shown_meta)))
    return f"<h3>{esc(title)}</h3>" + "".join(parts)


_CODE_ARGUMENTS = (("code", "code"), ("code_a", "program A"), ("code_b", "program B"))


def _chat(agent: dict[str, Any]) -> str:
    """The agent's conversation round by round: its messages, tool calls and the tool results."""
    calls = ", ".join(f"{name} ×{n}" for name, n in (agent.get("tool_calls") or {}).items()) or "none"
    out = [_kv([("rounds", esc(agent.get("rounds"))), ("stop reason", esc(agent.get("stop_reason"))),
                ("tool calls", esc(calls)),
                ("first program", f"{'passed' if agent.get('first_overall') else 'failed'}"
                                  f" (first failure: {esc(agent.get('first_failure'))})"),
                ("tokens", f"{agent.get('prompt_tokens')} prompt, {agent.get('completion_tokens')} completion")])]
    round_no = 0
    for message in agent.get("transcript", []):
        role = message.get("role", "?")
        if role == "assistant":
            round_no += 1
            out.append(f"<div class='round'>round {round_no}</div>")
        body = []
        if role == "user":
            body.append(_details("prompt", _pre(message.get("content"))))
        elif message.get("content"):
            body.append(_pre(message.get("content")))
        for call in message.get("tool_calls") or []:
            args = dict(call.get("arguments") or {}) if isinstance(call.get("arguments"), dict) else {}
            # a program is shown folded (compare has two: A and B), the other arguments inline
            codes = [(title, args.pop(key)) for key, title in _CODE_ARGUMENTS if isinstance(args.get(key), str)]
            body.append(f"<div class='call'>calls <b>{esc(call.get('name'))}</b>"
                        + (f" {esc(json.dumps(args))}" if args else "") + "</div>")
            for title, code in codes:
                body.append(_details(f"{title} ({len(code.splitlines())} lines)", _pre(code)))
        for picture in message.get("images") or []:  # the record keeps a picture's size, not the picture
            body.append(f"<div class='muted'>a picture went to the model ({esc(picture)})</div>")
        label = f"tool result: {message.get('name', '')}" if role == "tool" else role
        out.append(f"<div class='msg {esc(role)}'><div class='who'>{esc(label)}</div>{''.join(body)}</div>")
    return "".join(out)


def _repair(block: dict[str, Any], reference: str | None) -> str:
    """The seeded fault: its label, what it changed, the grader's verdict on the draft, and the draft
    beside the reference (the answer beside the reference follows under Programs)."""
    graded = block.get("graded") or {}
    facts = _kv([("fault", esc(block.get("fault"))), ("label", esc(block.get("label"))),
                 ("grader on the draft", esc(f"{graded.get('first_failure')} "
                                             f"({', '.join(graded.get('categories') or []) or 'no category'})")),
                 ("label = grader", esc(graded.get("agrees"))), ("tools", esc("on" if block.get("tools") else "off")),
                 ("repaired", esc(block.get("repaired")))])
    if reference is None or not block.get("program"):
        return facts
    table, changed = side_by_side(block["program"], without_header(reference)[0])
    return facts + _details(f"the draft beside the reference ({changed} changed line(s))",
                            f"<div class='diffwrap'>{table}</div>")


def task_page(record: dict[str, Any], *, run_label: str, root: str, program: str | None,
              reference: str | None, file_links: dict[str, str], images: dict[str, str],
              neighbours: tuple[str | None, str | None], system: str | None = None) -> str:
    """The whole page as one string (the caller writes it); ``system`` is the pictures' HTML."""
    key = f"{record.get('origin') + '/' if record.get('origin') else ''}{record['slug']}@{record['seed']}"
    verdict = ("infrastructure failure (not counted)" if record.get("first_failure") == "infrastructure"
               else "passed" if record.get("overall") else f"failed at {record.get('first_failure')}")
    status = "infra" if record.get("first_failure") == "infrastructure" else status_of(bool(record.get("overall")))
    prev, nxt = neighbours
    nav = (f"<a href='{esc(root)}index.html'>all records</a>"
           + (f" · <a href='{esc(prev)}'>previous</a>" if prev else "")
           + (f" · <a href='{esc(nxt)}'>next</a>" if nxt else ""))
    s: list[str] = [f"<nav>{nav}</nav>",
                    f"<h1>{esc(record.get('id'))} {esc(record.get('name', record['slug']))}, seed {esc(record['seed'])}"
                    f" <span class='badge {status}'>{esc(verdict)}</span></h1>",
                    _kv([("run", esc(run_label)), ("key", esc(key)), ("level", esc(record.get("level"))),
                         ("task text", esc(TEXT_WORDS.get(record.get("texts", "paper"), record.get("texts")))),
                         ("error categories", esc(", ".join(record.get("error_categories", [])) or "none")),
                         ("solution norm", esc(_number(record.get("solution_norm")))),
                         ("tokens", esc(_pairs(record.get("tokens"), "{:d}"))),
                         ("timing (s)", esc(_pairs(record.get("timing"), "{:.2f}", strip="_s"))),
                         ("evaluator", esc(record.get("evaluator")))])]
    if record.get("infrastructure_error"):
        s.append(f"<p class='error'>infrastructure: {esc(record['infrastructure_error'])}</p>")
    s += ["<h2>Description</h2>", f"<p class='desc'>{esc(record.get('description', ''))}</p>",
          _details("parameters", _json(record.get("params", {}))),
          "<h2 id='stages'>Stages</h2>", _stages(record)]
    if record.get("design"):
        s += ["<h2 id='design'>Design: the spec's quantity against its target</h2>", design_section(record)]
    if record.get("consensus"):  # what a consensus run adds, before the answer's own details
        s += ["<h2 id='consensus'>Consensus: the samples grouped by how they move</h2>",
              consensus_section(record["consensus"])]
    if record.get("differences") or record.get("topology_causes"):
        s += ["<h2 id='differences'>Graph differences by error category</h2>", _differences(record)]
    if system is not None:
        s += ["<h2 id='system'>System: program vs ground truth</h2>", system]
    if record.get("behaviour"):
        s += ["<h2 id='behaviour'>Behaviour: does it move as the ground truth does?</h2>",
              _behaviour(record["behaviour"])]
    if "trajectory" in images:
        s += ["<h2 id='solution'>Numerical solution: program vs ground truth</h2>",
              "<p class='muted'>the coordinates that differ most; the full trajectories were resampled to ≤ 200 "
              "time points</p>", f"<img class='plot' alt='trajectories' src='{esc(images['trajectory'])}'>"]
    if record.get("part") is not None or str(record.get("level")) == "3a":
        s += ["<h2 id='part'>Part</h2>", _part_metrics(record)]
        if "part" in images:
            s.append(f"<img class='plot' alt='program part and ground-truth part' src='{esc(images['part'])}'>")
        s.append(_details("part record", _json(record.get("part"))))
    if record.get("parts"):
        s.append(_details("parts of this assembly", _json(record["parts"]), open_=True))
    if record.get("repair"):
        s += ["<h2 id='repair'>Repair: the draft</h2>", _repair(record["repair"], reference)]
    s.append("<h2 id='programs'>Programs</h2>")
    links = " · ".join(f"<a href='{esc(href)}'>{esc(name)}</a>" for name, href in file_links.items())
    if links:
        s.append(f"<p>saved files: {links}</p>")
    if program is not None and reference is not None:
        if program.strip() == reference.strip():
            s += ["<p>the extracted program is identical to the reference program</p>",
                  _details("program", _pre(program))]
        else:
            table, changed = side_by_side(program, reference)
            s += [f"<p>{changed} changed line(s)</p>", f"<div class='diffwrap'>{table}</div>"]
    elif reference is not None:
        s += ["<p class='error'>no program was extracted from the answer</p>", _details("reference", _pre(reference))]
    if record.get("agent"):
        s += ["<h2 id='agent'>Agent conversation</h2>", _chat(record["agent"])]
    s.append("<h2 id='answers'>Prompts and answers</h2>")
    for step, title in (("selection", "component selection"), ("generation", "code generation")):
        if record.get(step):
            s.append(_answer(record[step], title))
    s.append("<h2 id='executions'>Executions</h2>")
    for name in ("execution", "reference_execution"):
        if record.get(name):
            run = record[name]
            s.append(_details(f"{'program' if name == 'execution' else 'ground truth'}: stage {esc(run.get('stage'))}"
                              + (f", error {esc(run.get('error_kind'))}" if run.get("error_kind") else ""),
                              _json(run), open_=name == "execution" and bool(run.get("error"))))
    if record.get("traceback"):
        s += ["<h2>Traceback</h2>", _pre(record["traceback"])]
    other = {k: v for k, v in record.items() if k not in SHOWN}
    if other:
        s += ["<h2>Other fields</h2>", _json(other)]
    title = f"{record['slug']} seed {record['seed']} – {run_label}"
    return (f"<!doctype html><html><head><meta charset='utf-8'><title>{esc(title)}</title>"
            f"<link rel='stylesheet' href='{esc(root)}static/viewer.css'></head>"
            f"<body class='task'>{''.join(s)}</body></html>")


def _number(value: Any) -> str:
    return "–" if value is None else f"{value:.3g}" if isinstance(value, float) else str(value)


def _pairs(block: Any, form: str, strip: str = "") -> str:
    """``{'llm_s': 0.011, 'evaluation_s': 0.45}`` as ``llm 0.01 · evaluation 0.45``."""
    if not isinstance(block, dict):
        return "–" if block is None else str(block)
    items = []
    for name, value in block.items():
        label = name.removesuffix(strip).replace("_", " ")
        try:
            items.append(f"{label} {form.format(value)}")
        except (ValueError, TypeError):
            items.append(f"{label} {value}")
    return " · ".join(items) or "–"


def _counts(block: Any) -> str:
    return ", ".join(f"{n}x {t}" for t, n in (block or {}).items()) or "none"
