"""``meceng report``: HTML (images embedded), Markdown and PNGs from one or more runs.

Sections follow the paper's section 4: success per stage (Table 2), thinking (Table 4), error
categories (Table 5), temperature (Fig. 8), prompt variants (Fig. 9-10), task difficulty
(Fig. 11). Rates show n and a 95 % Wilson interval. Plots are drawn headless (Agg).
"""

from __future__ import annotations

import base64
import html
import json
from pathlib import Path
from typing import Any

from meceng.eval.calibration import consensus_sections
from meceng.eval.categories import CATEGORIES
from meceng.eval.design_tables import HEADERS as DESIGN_HEADERS
from meceng.eval.design_tables import design_cells, design_rows
from meceng.eval.limits import LIMIT_HEADERS, limit_rows
from meceng.eval.rates import Rate, Run, load_runs
from meceng.eval.tables import (
    FLEXIBLE_COLUMNS,
    RIGID_COLUMNS,
    TEXTS_HEADERS,
    behaviour_table,
    component_series,
    difficulty,
    error_category_table,
    flexible_table,
    flexible_timing_table,
    repair_table,
    series,
    stage_table,
    texts_cells,
    texts_table,
    thinking_table,
    token_cost_table,
    tools_contribution,
    topology_cause_table,
)
from meceng.eval.topology import CAUSES as TOPOLOGY_CAUSES
from meceng.report.plots import bar_plot, difficulty_plot, line_plot, release_plot


def _table(headers: list[str], rows: list[list[str]], links: list[str] | None = None) -> tuple[str, str]:
    """The same table as Markdown and as HTML; ``links``: a URL per row for its first cell (the
    viewer's records of that row). No rows, no table: its section is left out of the report."""
    if not rows:
        return "", ""
    md = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    md += ["| " + " | ".join(r) + " |" for r in rows]
    head = "".join(f"<th>{html.escape(h)}</th>" for h in headers)

    def cells(i: int, r: list[str]) -> str:
        out = [f"<td>{html.escape(c)}</td>" for c in r]
        if links and r:
            out[0] = f"<td><a href='{html.escape(links[i], quote=True)}'>{html.escape(r[0])}</a></td>"
        return "".join(out)

    body = "".join(f"<tr>{cells(i, r)}</tr>" for i, r in enumerate(rows))
    return "\n".join(md), f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _viewer_links(out: Path, key: str, values: list[str]) -> list[str] | None:
    """Links into a viewer written beside the report (``meceng view ... --out <report>/viewer``):
    the index filtered to ``key`` = each value; None when there is no viewer there."""
    if not (out / "viewer" / "index.html").exists():
        return None
    from urllib.parse import quote

    return [f"viewer/index.html#{key}={quote(v, safe='')}" for v in values]


def _spec_models(path: Path | None) -> list[dict[str, Any]]:
    """A sweep spec's [[models]] entries (none without a spec)."""
    import tomllib

    return [] if path is None else list(tomllib.loads(path.read_text()).get("models", []))


def model_facts(path: Path | None) -> dict[str, tuple[str, float | None]]:
    """model name -> (release date, size in B) from a sweep spec's [[models]] entries."""
    return {m["name"]: (str(m["release"]), m.get("size_b")) for m in _spec_models(path) if m.get("release")}


def model_prices(path: Path | None) -> dict[str, tuple[float, float]]:
    """model name -> (price per million prompt tokens, per million completion tokens) from a sweep
    spec's [[models]] entries that give both."""
    return {m["name"]: (float(m["price_prompt"]), float(m["price_completion"])) for m in _spec_models(path)
            if m.get("price_prompt") is not None and m.get("price_completion") is not None}


def build_report(paths: list[Path], out: Path, models_file: Path | None = None) -> dict[str, Path]:
    """Write report.html, report.md, report.json and the PNGs into ``out``; returns their paths."""
    runs: list[Run] = load_runs(paths)
    out.mkdir(parents=True, exist_ok=True)
    sections: list[tuple[str, str, str, str | None]] = []  # title, markdown, html, png name

    stages = stage_table(runs)
    headers = ["run", "n", *[label for _, label in RIGID_COLUMNS]]
    rows = [[r["run"], str(r["n"]), *[r[k].text() for k, _ in RIGID_COLUMNS]] for r in stages]
    md, ht = _table(headers, rows, _viewer_links(out, "model", [r["model"] for r in stages]))
    bar_plot(out / "stages.png", {r["run"]: {label: r[k] for k, label in RIGID_COLUMNS} for r in stages},
              "Success rate per stage", "success (%)")
    sections.append(("Success per stage (Table 2)", md, ht, "stages.png"))

    texts = texts_table(runs)
    md, ht = _table(TEXTS_HEADERS, [texts_cells(r) for r in texts])
    sections.append(("Paper and open texts side by side (levels 1-2; open texts graded by behaviour)", md, ht, None))

    thinking = thinking_table(runs)
    md, ht = _table(["model", "think", "n", "overall", "completion tokens (mean)", "LLM time (min)"],
                    [[r["model"], r["think"], str(r["n"]), r["overall"].text(), f"{r['completion_tokens_mean']:.0f}",
                      f"{r['llm_time_min']:.2f}"] for r in thinking])
    sections.append(("Thinking (Table 4; levels 1-2)", md, ht, None))

    categories = error_category_table(runs)
    md, ht = _table(["model", "n", *CATEGORIES, "mean per task"],
                    [[r["model"], str(r["n"]),
                      *[f"{r['counts'][c]} ({100 * r['proportions'][c]:.0f} %)" for c in CATEGORIES],
                      f"{r['mean_per_task']:.2f}"] for r in categories])
    sections.append(("Graph content error categories (Table 5; levels 1-2)", md, ht, None))

    tokens = token_cost_table(runs, model_prices(models_file))
    md, ht = _table(["model", "tasks", "prompt tokens", "completion tokens", "of which reasoning", "cost"],
                    [[r["model"], str(r["tasks"]), f"{r['prompt']:,}", f"{r['completion']:,}", f"{r['reasoning']:,}",
                      "–" if r["cost"] is None else f"{r['cost']:,.2f}"] for r in tokens])
    sections.append(("Tokens and cost per model (all levels; cost where the --models spec gives prices)", md, ht,
                     None))

    causes = topology_cause_table(runs)
    md, ht = _table(["model", "topology failures", *TOPOLOGY_CAUSES, "not recorded"],
                    [[r["model"], str(r["failures"]), *[str(r[c]) for c in TOPOLOGY_CAUSES], str(r["unknown"])]
                     for r in causes])
    sections.append(("Topology failures by cause (beside Table 5; levels 1, 2 and 3b)", md, ht, None))

    behaviour, differ = behaviour_table(runs)
    md, ht = _table(["run", "n", "paper overall", "behaviour", "paper only", "behaviour only"],
                    [[r["run"], str(r["n"]), r["paper"].text(), r["behaviour"].text(), str(r["paper_only"]),
                      str(r["behaviour_only"])] for r in behaviour])
    sections.append(("Behaviour beside the paper's verdict (levels 1, 2 and 3b)", md, ht, None))
    md, ht = _table(["run", "task", "level", "paper", "behaviour"],
                    [[d["run"], d["task"], d["level"], d["paper"], d["behaviour"]] for d in differ[:200]])
    sections.append(("Where the two verdicts differ", md, ht, None))

    temperature = series(runs, "temperature")
    if any(len(v) > 1 for v in temperature.values()):
        line_plot(out / "temperature.png", temperature, "Overall success vs temperature", "temperature")
    md, ht = _table(["model", "temperature", "overall"],
                    [[m, k, r.text()] for m, d in temperature.items() for k, r in d.items()])
    sections.append(("Temperature (Fig. 8; levels 1-2)", md, ht,
                     "temperature.png" if (out / "temperature.png").exists() else None))

    select = component_series(runs)
    select_overall = series(runs, "select_template")
    bar_plot(out / "select_templates.png", select, "Component selection per selection prompt", "selection (%)")
    md, ht = _table(["model", "selection prompt", "component selection", "overall"],
                    [[m, k, r.text(), select_overall[m][k].text()] for m, d in select.items() for k, r in d.items()])
    sections.append(("Component-selection prompts (Fig. 9; levels 1-2)", md, ht, "select_templates.png"))

    code = series(runs, "code_template")
    bar_plot(out / "code_templates.png", code, "Overall success per code prompt", "overall (%)")
    md, ht = _table(["model", "code prompt", "overall"],
                    [[m, k, r.text()] for m, d in code.items() for k, r in d.items()])
    sections.append(("Code-generation prompts (Fig. 10; levels 1-2)", md, ht, "code_templates.png"))

    hard = difficulty(runs)
    difficulty_plot(out / "difficulty.png", hard)
    md, ht = _table(["task model", "level", "n", "overall", "difficulty"],
                    [[r["slug"], str(r["level"]), str(r["n"]), r["overall"].text(), f"{100 * r['difficulty']:.1f}"]
                     for r in hard], _viewer_links(out, "task", [r["slug"] for r in hard]))
    sections.append(("Difficulty per task model (Fig. 11)", md, ht, "difficulty.png"))

    facts = model_facts(models_file)
    if facts:
        overall = series(runs, "think")
        points = []
        for model, by_think in overall.items():
            if model in facts and "False" in by_think and by_think["False"].value is not None:
                release, size = facts[model]
                points.append((model, release, size, by_think["False"].value))
        if points:
            release_plot(out / "release.png", points)
            md, ht = _table(["model", "release", "size (B)", "overall (no thinking)"],
                            [[m, r, "" if s is None else f"{s:g}", f"{100 * v:.1f}"] for m, r, s, v in points])
            sections.insert(1, ("Success vs release date (Fig. 7)", md, ht, "release.png"))

    flexible = flexible_table(runs)
    if flexible:
        headers = ["run", "parts", "assemblies", *[label for _, _, label in FLEXIBLE_COLUMNS]]
        rows = [[r["run"], str(r["parts"]), str(r["assemblies"]),
                 *[r[label].text() for _, _, label in FLEXIBLE_COLUMNS]] for r in flexible]
        md, ht = _table(headers, rows)
        sections.append(("Flexible parts and assemblies, levels 3a/3b (Table 6)", md, ht, None))
        timing_rows = [[r["run"], f"{r['llm_min']:.1f}", f"{r['parts_eval_min']:.1f}", f"{r['mbs_eval_min']:.2f}",
                        f"{r['prompt_tokens_k']:.1f}", f"{r['generated_tokens_k']:.1f}",
                        f"{r['reasoning_tokens_k']:.1f}",
                        "–" if r["context_p95"] is None else f"{r['context_p95']:.0f}", str(r["batch_size"])]
                       for r in flexible_timing_table(runs)]
        md, ht = _table(["run", "LLM (min)", "parts eval. (min)", "MBS eval. (min)", "prompt tokens (k)",
                         "gen. tokens (k)", "of which reasoning (k)", "context used (P95)", "batch size"],
                        timing_rows)
        sections.append(("Level 3 time and tokens (Table 7)", md, ht, None))

    agent_rows = []
    for run in runs:
        block = run.summary.get("agent")
        if block:
            agent_rows.append([run.label, str(block["tasks"]), f"{100 * block['first_overall']:.1f}",
                               f"{100 * block['final_overall']:.1f}", f"{100 * block['uplift']:+.1f}",
                               "–" if block["rounds_per_solved"] is None else f"{block['rounds_per_solved']:.2f}",
                               "–" if block["tokens_per_solved"] is None else f"{block['tokens_per_solved']:.0f}",
                               ", ".join(f"{k} {v}" for k, v in sorted(block["tool_calls"].items())) or "none"])
    if agent_rows:
        md, ht = _table(["run", "n", "first answer (%)", "after the loop (%)", "uplift (points)",
                         "rounds per solved", "tokens per solved", "tool calls"], agent_rows)
        sections.append(("Self-validating agent", md, ht, None))

    repair_rows = repair_table(runs)
    if repair_rows:
        labels = sorted({label for row in repair_rows for label in row["labels"]})
        md, ht = _table(["run", "tools", "repaired (%)", *labels],
                        [[row["run"], "on" if row["tools"] else "off", row["overall"].text(),
                          *(row["labels"][k].text() if k in row["labels"] else "–" for k in labels)]
                         for row in repair_rows])
        sections.append(("Repair benchmark: drafts repaired, per fault", md, ht, None))
        contribution = tools_contribution(repair_rows)
        if contribution:
            md, ht = _table(["model", "with tools (%)", "without (%)", "the tools' contribution (points)"],
                            [[c["model"], c["with"].text(), c["without"].text(),
                              "–" if c["points"] is None else f"{c['points']:+.1f}"] for c in contribution])
            sections.append(("Repair benchmark: what the tools are worth", md, ht, None))

    design = design_rows(runs)
    if design:
        md, ht = _table(DESIGN_HEADERS, [design_cells(r) for r in design])
        sections.append(("Design tasks, level 4: first try and final, the spec's margins (1 on target, 0 at the "
                         "tolerance's edge)", md, ht, None))

    for title, headers, rows in consensus_sections(runs):
        sections.append((title, *_table(headers, rows), None))

    md, ht = _table(LIMIT_HEADERS, limit_rows((run.label, run.tasks) for run in runs))
    sections.append(("Program time limits (CPU time is graded; the wall clock only bounds a run)", md, ht, None))

    intro = (f"{len(runs)} run(s), {sum(len(r.tasks) for r in runs)} task records. Rates in % with the 95 % "
             "Wilson interval in brackets; infrastructure failures are left out of the rates.")
    md_doc = ["# MecEng report", "", intro, ""]
    html_doc = ["<!doctype html><html><head><meta charset='utf-8'><title>MecEng report</title>",
                "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}table{border-collapse:collapse;"
                "font-size:13px}td,th{border:1px solid #ccc;padding:3px 6px}th{background:#eef}"
                "img{max-width:100%;height:auto}</style></head><body>",
                "<h1>MecEng report</h1>", f"<p>{html.escape(intro)}</p>"]
    for title, md, ht, png in sections:
        if not md:  # nothing of that kind in these runs (a flexible-only run has no Table 4)
            continue
        md_doc += [f"## {title}", "", md, ""]
        html_doc += [f"<h2>{html.escape(title)}</h2>", ht]
        if png:
            md_doc += [f"![{title}]({png})", ""]
            data = base64.b64encode((out / png).read_bytes()).decode()
            html_doc.append(f"<p><img alt='{html.escape(title)}' src='data:image/png;base64,{data}'></p>")
    html_doc.append("</body></html>")
    (out / "report.md").write_text("\n".join(md_doc))
    (out / "report.html").write_text("\n".join(html_doc))
    machine = {
        "runs": [str(r.path) for r in runs],
        "stages": [{**{k: v for k, v in r.items() if not isinstance(v, Rate)},
                    **{k: r[k].to_json() for k, _ in RIGID_COLUMNS}} for r in stages],
        "error_categories": categories,
        "topology_causes": causes,
        "behaviour_disagreements": differ,
        "tokens": tokens,
        "texts": [{**{k: v for k, v in r.items() if not isinstance(v, Rate)},
                   **{k: r[k].to_json() for k in ("paper", "paper_behaviour", "open")}} for r in texts],
        "design": [{**{k: v for k, v in r.items() if not isinstance(v, Rate)}, "first": r["first"].to_json(),
                    "final": r["final"].to_json()} for r in design],
        "difficulty": [{**{k: v for k, v in r.items() if k != "overall"}, "overall": r["overall"].to_json()}
                       for r in hard],
    }
    (out / "report.json").write_text(json.dumps(machine, indent=1))
    return {"html": out / "report.html", "markdown": out / "report.md", "json": out / "report.json"}
