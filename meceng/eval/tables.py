"""The numbers of the report, as pure functions of run records (paper section 4).

Every rate comes with its sample count and a 95 % Wilson interval, so a reader sees what is
noise. Tables are sorted as in the paper (by overall success, best first).
"""

from __future__ import annotations

from collections import Counter, defaultdict
from typing import Any

import numpy as np

from meceng.eval.aggregate import token_totals
from meceng.eval.categories import CATEGORIES
from meceng.eval.rates import Rate, Run, stage_rate
from meceng.eval.topology import CAUSES

#: Tables 2-5 and Figures 8-10 are about the rigid-body levels; a part has no such stages.
RIGID_LEVELS = ("1", "2")
#: the levels graded by the system graph, where a topology can fail (assemblies included)
GRAPH_LEVELS = ("1", "2", "3b")

RIGID_COLUMNS = (
    ("choose_components", "comp."),
    ("solver_success", "solver"),
    ("topology_match", "topol."),
    ("solution_match", "numsol"),
    ("graph_content_match", "graph"),
    ("overall", "overall"),
)


def stage_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Table 2: success per stage per run, sorted by overall success."""
    rows = []
    labels = [run.label for run in runs]
    for run in runs:
        if run.flexible_only:
            continue  # Table 6 and 7 describe it
        tasks = run.graded(run.rigid_levels)
        label = _label(run, labels)
        rows.append({"run": label, "model": run.model, "n": len(tasks),
                     "infrastructure_failures": sum(1 for t in run.tasks if t.get("first_failure") == "infrastructure"),
                     **{key: stage_rate(tasks, key) for key, _ in RIGID_COLUMNS}})
    return sorted(rows, key=lambda r: -(r["overall"].value or 0.0))


def _label(run: Run, labels: list[str]) -> str:
    return run.label if labels.count(run.label) == 1 else f"{run.label} ({run.path.parent.name})"


#: Table 6: part metrics over every part record, MBS metrics over the assemblies.
FLEXIBLE_COLUMNS = (
    ("3a", "choose_part_components", "part comp."),
    ("3a", "mesh_match", "mesh"),
    ("3a", "overall", "parts overall"),
    ("3b", "mbs_started", "MBS started"),
    ("3b", "choose_components", "comp."),
    ("3b", "graph_content_match", "graph"),
    ("3b", "overall", "overall"),
)


def flexible_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Table 6 (runs with level 3 records), sorted by parts overall like the paper."""
    rows = []
    labels = [run.label for run in runs]
    for run in runs:
        parts, assemblies = run.graded(("3a",)), run.graded(("3b",))
        if not parts and not assemblies:
            continue
        rows.append({"run": _label(run, labels), "model": run.model, "parts": len(parts),
                     "assemblies": len(assemblies),
                     **{label: stage_rate(parts if level == "3a" else assemblies, stage)
                        for level, stage, label in FLEXIBLE_COLUMNS}})
    return sorted(rows, key=lambda r: -(r["parts overall"].value or 0.0))


def flexible_timing_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Table 7: LLM time, part and MBS evaluation time, generated tokens, P95 context, batch size."""
    rows = []
    labels = [run.label for run in runs]
    for run in runs:
        tasks = run.graded(("3a", "3b"))
        if not tasks:
            continue
        contexts = [m.get("context_used", 0) for t in tasks for m in
                    (t.get("selection", {}).get("meta"), t.get("generation", {}).get("meta")) if m]
        rows.append({
            "run": _label(run, labels), "model": run.model,
            "llm_min": sum(t.get("timing", {}).get("llm_s", 0.0) for t in tasks) / 60,
            "parts_eval_min": sum(t.get("timing", {}).get("evaluation_s", 0.0) for t in tasks
                                  if t.get("level") == "3a") / 60,
            "mbs_eval_min": sum(t.get("timing", {}).get("mbs_evaluation_s", 0.0) for t in tasks
                                if t.get("level") == "3b") / 60,
            "generated_tokens_k": sum(t.get("tokens", {}).get("completion", 0) for t in tasks) / 1000,
            "prompt_tokens_k": sum(t.get("tokens", {}).get("prompt", 0) for t in tasks) / 1000,
            "reasoning_tokens_k": sum(t.get("tokens", {}).get("reasoning", 0) for t in tasks) / 1000,
            "context_p95": float(np.percentile(contexts, 95)) if contexts else None,
            "batch_size": run.settings["llm"].get("batch_size"),
        })
    return rows


def token_cost_table(runs: list[Run], prices: dict[str, tuple[float, float]] | None = None) -> list[dict[str, Any]]:
    """Per model, over all its runs and levels: prompt, completion and reasoning tokens (reasoning
    is part of completion, as the APIs bill it) and, with prices per million prompt and completion
    tokens, the cost. Infrastructure failures count too: their calls were made."""
    groups: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for run in runs:
        groups[run.model].extend(run.tasks)
    rows = []
    for model, tasks in sorted(groups.items()):
        totals = token_totals(tasks)
        price = (prices or {}).get(model)
        cost = None if price is None else (totals["prompt"] * price[0] + totals["completion"] * price[1]) / 1e6
        rows.append({"model": model, "tasks": len(tasks), **totals, "cost": cost})
    return rows


def thinking_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Table 4: per model and thinking setting: overall, tokens, LLM time."""
    groups: dict[tuple[str, str], list[Run]] = defaultdict(list)
    for run in runs:
        groups[(run.model_key, run.think)].append(run)
    rows = []
    for (model, think), members in sorted(groups.items()):
        tasks = [t for r in members for t in r.graded(RIGID_LEVELS)]
        if not tasks:
            continue
        completion = [t.get("tokens", {}).get("completion", 0) for t in tasks]
        llm_time = sum(t.get("timing", {}).get("llm_s", 0.0) for t in tasks)
        rows.append({"model": model, "think": think, "n": len(tasks), "overall": stage_rate(tasks, "overall"),
                     "completion_tokens_mean": sum(completion) / len(completion) if completion else 0.0,
                     "llm_time_min": llm_time / 60})
    return rows


def error_category_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Table 5: per model, graph-content error categories (once per task), proportions, means; levels 1-2.
    Paper texts only: an open text's graph content is not graded (``eval.chain.by_behaviour``)."""
    groups = _by_model([r for r in runs if r.texts == "paper"], RIGID_LEVELS)
    rows = []
    for model, tasks in sorted(groups.items()):
        counts = {c: sum(1 for t in tasks if c in t.get("error_categories", [])) for c in CATEGORIES}
        total = sum(counts.values())
        rows.append({"model": model, "n": len(tasks), "counts": counts, "total": total,
                     "proportions": {c: (counts[c] / total if total else 0.0) for c in CATEGORIES},
                     "mean_per_task": total / len(tasks) if tasks else 0.0})
    return rows


def topology_cause_rows(groups: dict[str, list[dict[str, Any]]]) -> list[dict[str, Any]]:
    """Per model, its topology failures by cause (eval.topology.CAUSES); records graded before
    causes were recorded count as ``unknown``."""
    rows = []
    for model, tasks in sorted(groups.items()):
        failed = [t for t in tasks if t.get("first_failure") == "topology_match"]
        causes = Counter((t.get("topology_causes") or {}).get("cause", "unknown") for t in failed)
        rows.append({"model": model, "failures": len(failed), **{c: causes.get(c, 0) for c in (*CAUSES, "unknown")}})
    return rows


def topology_cause_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Beside Table 5: why topology failed, per model, on every level graded by the system graph
    (the paper's rule fails an inert surplus item too; this table shows how much of the failure
    that is)."""
    return topology_cause_rows(_by_model([r for r in runs if r.texts == "paper"], GRAPH_LEVELS))


def _by_model(runs: list[Run], levels: tuple[str, ...]) -> dict[str, list[dict[str, Any]]]:
    """Graded records of ``levels`` per model; a model with none of them has no entry."""
    groups: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for run in runs:
        groups[run.model_key].extend(run.graded(levels))
    return {model: tasks for model, tasks in groups.items() if tasks}


def series(runs: list[Run], axis: str, stage: str = "overall") -> dict[str, dict[str, Rate]]:
    """model -> value of ``axis`` (temperature, think, select_template, code_template) -> the rate
    of ``stage``, levels 1-2."""
    out: dict[str, dict[str, list[dict[str, Any]]]] = defaultdict(lambda: defaultdict(list))
    for run in runs:
        key = f"{run.temperature:g}" if axis == "temperature" else str(getattr(run, axis))
        if tasks := run.graded(RIGID_LEVELS):
            out[run.model_key][key].extend(tasks)
    return {m: {k: stage_rate(v, stage) for k, v in sorted(d.items())} for m, d in sorted(out.items())}


def component_series(runs: list[Run]) -> dict[str, dict[str, Rate]]:
    """model -> selection template -> component-selection rate (Fig. 9, solid bars), levels 1-2."""
    return series(runs, "select_template", "choose_components")


def repair_table(runs: list[Run]) -> list[dict[str, Any]]:
    """The repair benchmark per run: the share of drafts repaired, over all and per fault label."""
    rows = []
    for run in runs:
        drafts = [t for t in run.graded() if t.get("repair")]
        if not drafts:
            continue
        labels: dict[str, list[dict[str, Any]]] = defaultdict(list)
        for t in drafts:
            labels[t["repair"]["label"]].append(t)
        rows.append({"run": run.label, "model": run.model, "tools": bool(drafts[0]["repair"]["tools"]),
                     "overall": _repaired(drafts), "labels": {k: _repaired(v) for k, v in sorted(labels.items())}})
    return rows


def _repaired(drafts: list[dict[str, Any]]) -> Rate:
    return Rate(sum(1 for t in drafts if t["repair"]["repaired"]), len(drafts))


def tools_contribution(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per model with runs of both kinds: repaired with tools minus without, in points."""
    out = []
    for model in dict.fromkeys(r["model"] for r in rows):
        on = [r for r in rows if r["model"] == model and r["tools"]]
        off = [r for r in rows if r["model"] == model and not r["tools"]]
        if on and off:
            a, b = on[0]["overall"], off[0]["overall"]
            out.append({"model": model, "with": a, "without": b,
                        "points": None if a.value is None or b.value is None else 100 * (a.value - b.value)})
    return out


def difficulty(runs: list[Run]) -> list[dict[str, Any]]:
    """Fig. 11: per task model, 1 - mean overall success over all runs; hardest first."""
    groups: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for run in runs:
        for t in run.graded():  # an open text's task is graded otherwise: a row of its own
            groups[t["slug"] if t.get("texts", "paper") == "paper" else f"{t['slug']} [{t['texts']} text]"].append(t)
    rows = []
    for slug, tasks in groups.items():
        rate = stage_rate(tasks, "overall")
        rows.append({"slug": slug, "level": tasks[0]["level"], "id": tasks[0].get("id"), "n": len(tasks),
                     "overall": rate, "difficulty": 1 - (rate.value or 0.0)})
    return sorted(rows, key=lambda r: (-r["difficulty"], r["id"] or 0))


def behaviour_table(runs: list[Run]) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """The behaviour verdict beside the paper's, per run over levels 1, 2 and 3b: both rates and how
    the two verdicts split; and every record where they differ (run, task, both verdicts)."""
    rows, disagreements = [], []
    labels = [run.label for run in runs]
    for run in runs:
        if run.texts != "paper":  # an open text's verdict is its behaviour: nothing to set beside it
            continue
        tasks = [t for t in run.graded(GRAPH_LEVELS) if isinstance(t.get("behaviour"), dict)
                 and t["behaviour"].get("passed") is not None]
        if not tasks:
            continue
        label = _label(run, labels)
        split = Counter((bool(t.get("overall")), bool(t["behaviour"]["passed"])) for t in tasks)
        rows.append({"run": label, "model": run.model, "n": len(tasks), "paper": stage_rate(tasks, "overall"),
                     "behaviour": Rate(split[(True, True)] + split[(False, True)], len(tasks)),
                     "paper_only": split[(True, False)], "behaviour_only": split[(False, True)]})
        disagreements += [{"run": label, "task": f"{t['slug']}@{t.get('seed')}", "level": str(t.get("level")),
                           "paper": "pass" if t.get("overall") else f"fail ({t.get('first_failure')})",
                           "behaviour": t["behaviour"].get("detail", "")}
                          for t in tasks if bool(t.get("overall")) != bool(t["behaviour"]["passed"])]
    return sorted(rows, key=lambda r: -(r["behaviour"].value or 0.0)), disagreements


def texts_table(runs: list[Run]) -> list[dict[str, Any]]:
    """Issue 36: per run setting (model, temperature, thinking, prompts) that has an open-text run,
    the rates on the paper's texts and on the open ones side by side, levels 1-2. The paper's texts
    with both verdicts (the paper's, what its rates count, and behaviour), the open texts' overall
    (behaviour: ``eval.chain.by_behaviour``); ``points``: open overall minus the paper texts'
    behaviour rate, the same grader on both. None of the cells when no run has the texts."""
    if not any(run.texts != "paper" for run in runs):
        return []
    groups: dict[str, dict[str, list[dict[str, Any]]]] = defaultdict(lambda: defaultdict(list))
    models: dict[str, str] = {}
    for run in runs:
        if tasks := run.graded(RIGID_LEVELS):
            groups[run.setting_label][run.texts].extend(tasks)
            models[run.setting_label] = run.model
    rows = []
    for setting, by_texts in groups.items():
        paper, open_ = by_texts.get("paper", []), by_texts.get("open", [])
        behaviour = [t for t in paper if isinstance(t.get("behaviour"), dict)
                     and t["behaviour"].get("passed") is not None]
        paper_behaviour = Rate(sum(1 for t in behaviour if t["behaviour"]["passed"]), len(behaviour))
        open_overall = stage_rate(open_, "overall")
        points = (None if open_overall.value is None or paper_behaviour.value is None
                  else 100 * (open_overall.value - paper_behaviour.value))
        rows.append({"setting": setting, "model": models[setting], "paper": stage_rate(paper, "overall"),
                     "paper_behaviour": paper_behaviour, "open": open_overall, "points": points})
    return sorted(rows, key=lambda r: -(r["open"].value or 0.0))


TEXTS_HEADERS = ["run", "paper texts: overall", "paper texts: behaviour", "open texts: overall (behaviour)",
                 "open − paper behaviour (points)"]


def texts_cells(row: dict[str, Any]) -> list[str]:
    """A row of ``texts_table`` as the report's table cells (``TEXTS_HEADERS``)."""
    return [row["setting"], row["paper"].text(), row["paper_behaviour"].text(), row["open"].text(),
            "–" if row["points"] is None else f"{row['points']:+.1f}"]
