"""Aggregation of task records into the run summary (rates per stage and level, statistics).

Works on the JSON task records, so a summary can be recomputed from a journal or a run.json.
Tasks that failed for infrastructure reasons (server down, reference broken) are counted apart
and left out of the model's rates: they say nothing about the model.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np

from meceng.eval.categories import CATEGORIES
from meceng.eval.limits import execution_limits


def _percentile(values: Sequence[float], q: float) -> float | None:
    return float(np.percentile(values, q)) if values else None


def _stats(values: Sequence[float]) -> dict[str, float | None]:
    if not values:
        return {"n": 0, "mean": None, "median": None, "p95": None, "max": None, "sum": 0.0}
    arr = np.asarray(values, dtype=float)
    return {"n": len(arr), "mean": float(arr.mean()), "median": float(np.median(arr)),
            "p95": float(np.percentile(arr, 95)), "max": float(arr.max()), "sum": float(arr.sum())}


def stage_rates(records: Iterable[dict[str, Any]]) -> dict[str, Any]:
    records = list(records)
    counted = [r for r in records if r.get("first_failure") != "infrastructure"]
    passed: Counter[str] = Counter()
    # a stage a record does not require (an open text's writing stages) is in no rate: a stage's rate
    # is over the records that require it, None when none does
    exempt: Counter[str] = Counter()
    order: list[str] = []
    for r in counted:
        for s in r.get("stages", []):
            if s["name"] not in order:
                order.append(s["name"])
            if s.get("required", True) is False:
                exempt[s["name"]] += 1
            elif s["passed"]:
                passed[s["name"]] += 1
    n = len(counted)
    rates = {name: (passed[name] / (n - exempt[name]) if n - exempt[name] else None) for name in order}
    overall = sum(1 for r in counted if r.get("overall"))
    rates["overall"] = overall / n if n else None
    return {"tasks": len(records), "counted": n, "infrastructure_failures": len(records) - n,
            # of those, prompts the server's context could not hold (a server setting, not a passing failure)
            "context_exceeded": sum(1 for r in records if r.get("context_exceeded")),
            "passed": {**{k: passed[k] for k in order}, "overall": overall}, "rates": rates}


def agent_summary(records: list[dict[str, Any]]) -> dict[str, Any] | None:
    """First answer vs after the loop (uplift), rounds and tokens per solved task, tools used."""
    agents = [r for r in records if "agent" in r and r.get("first_failure") != "infrastructure"]
    if not agents:
        return None
    n = len(agents)
    first = sum(1 for r in agents if r["agent"]["first_overall"])
    final = sum(1 for r in agents if r.get("overall"))
    solved = [r for r in agents if r.get("overall")]
    tools: Counter[str] = Counter()
    for r in agents:
        tools.update(r["agent"]["tool_calls"])
    return {
        "tasks": n, "first_overall": first / n, "final_overall": final / n, "uplift": (final - first) / n,
        "repaired": sum(1 for r in agents if r.get("overall") and not r["agent"]["first_overall"]),
        "broken_by_loop": sum(1 for r in agents if r["agent"]["first_overall"] and not r.get("overall")),
        "rounds_mean": sum(r["agent"]["rounds"] for r in agents) / n,
        "rounds_per_solved": (sum(r["agent"]["rounds"] for r in solved) / len(solved)) if solved else None,
        "tokens_per_solved": (sum(r["agent"]["completion_tokens"] for r in solved) / len(solved)) if solved else None,
        "tool_calls": dict(tools),
        "stop_reasons": dict(Counter(r["agent"]["stop_reason"] for r in agents)),
    }


def repair_summary(records: list[dict[str, Any]]) -> dict[str, Any] | None:
    """The repair benchmark: drafts repaired, per fault label (the paper's category, or a part's fault)."""
    drafts = [r for r in records if r.get("repair") and r.get("first_failure") != "infrastructure"]
    if not drafts:
        return None
    by_label: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for r in drafts:
        by_label[r["repair"]["label"]][0] += bool(r["repair"]["repaired"])
        by_label[r["repair"]["label"]][1] += 1
    return {"tasks": len(drafts), "repaired": sum(1 for r in drafts if r["repair"]["repaired"]),
            "tools": bool(drafts[0]["repair"]["tools"]), "by_label": dict(sorted(by_label.items())),
            "grader_agrees_with_label": _agreeing(drafts)}


def _agreeing(drafts: list[dict[str, Any]]) -> int | None:
    """Drafts whose grader names the fault's label; None where none was graded by a verdict that
    names categories (an open text's behaviour verdict)."""
    said = [(r["repair"].get("graded") or {}).get("agrees") for r in drafts]
    known = [a for a in said if a is not None]
    return sum(1 for a in known if a) if known else None


def behaviour_summary(records: list[dict[str, Any]]) -> dict[str, Any] | None:
    """The behaviour verdict beside the paper's: its rate (overall and per level) over the graded
    records that carry one, how often the two verdicts agree, and the records where they differ."""
    graded = [r for r in records if isinstance(r.get("behaviour"), dict) and r.get("first_failure") != "infrastructure"
              and r["behaviour"].get("passed") is not None]
    if not graded:
        return None
    pairs = Counter((bool(r.get("overall")), bool(r["behaviour"]["passed"])) for r in graded)
    by_level: dict[str, list[bool]] = defaultdict(list)
    for r in graded:
        by_level[str(r["level"])].append(bool(r["behaviour"]["passed"]))
    differ = [r for r in graded if bool(r.get("overall")) != bool(r["behaviour"]["passed"])]
    return {"graded": len(graded), "passed": pairs[(True, True)] + pairs[(False, True)],
            "rate": (pairs[(True, True)] + pairs[(False, True)]) / len(graded),
            "levels": {level: sum(v) / len(v) for level, v in sorted(by_level.items())},
            "both_pass": pairs[(True, True)], "both_fail": pairs[(False, False)],
            "paper_only": pairs[(True, False)], "behaviour_only": pairs[(False, True)],
            "disagreements": [{"slug": r["slug"], "seed": r.get("seed"), "paper": bool(r.get("overall")),
                               "first_failure": r.get("first_failure"), "behaviour": r["behaviour"].get("detail", "")}
                              for r in differ[:100]]}


def token_totals(records: Iterable[dict[str, Any]]) -> dict[str, int]:
    """Prompt, completion and reasoning tokens of all the records' LLM calls (reasoning is part of
    completion, as the APIs bill it)."""
    totals = {"prompt": 0, "completion": 0, "reasoning": 0}
    for record in records:
        for kind in totals:
            totals[kind] += int((record.get("tokens") or {}).get(kind, 0) or 0)
    return totals


def summarize(records: Iterable[dict[str, Any]]) -> dict[str, Any]:
    """The ``summary`` block of run.json."""
    records = list(records)
    by_level: dict[str, list[dict[str, Any]]] = defaultdict(list)
    by_task: dict[str, list[dict[str, Any]]] = defaultdict(list)
    for r in records:
        by_level[str(r["level"])].append(r)
        by_task[r["slug"]].append(r)
    categories: Counter[str] = Counter()
    for r in records:
        categories.update(set(r.get("error_categories", [])))
    first_failures = Counter(r.get("first_failure") or "none" for r in records)
    calls = [c for r in records for c in (r.get("selection", {}).get("meta"), r.get("generation", {}).get("meta"))
             if c]
    truncated = sum(1 for c in calls if c.get("truncated"))
    return {
        **stage_rates(records),
        "levels": {level: stage_rates(rs) for level, rs in sorted(by_level.items())},
        "tasks_by_model": {slug: {"n": len(rs), "overall": sum(1 for r in rs if r.get("overall"))}
                           for slug, rs in by_task.items()},
        "first_failures": dict(first_failures),
        "error_categories": {c: categories.get(c, 0) for c in CATEGORIES},
        "tokens": {
            "prompt": _stats([c.get("prompt_tokens", 0) for c in calls]),
            "completion": _stats([c.get("completion_tokens", 0) for c in calls]),
            "reasoning": _stats([c.get("reasoning_tokens", 0) for c in calls]),
            # every call of the run, agent rounds and assemblies' parts included (what a bill counts)
            "totals": token_totals(records),
            "context_used_p95": _percentile([c.get("context_used", 0) for c in calls], 95),
            "truncated_answers": truncated,
            "context_limit_hits": sum(1 for c in calls if c.get("context_limit_hit")),
        },
        "agent": agent_summary(records),
        "repair": repair_summary(records),
        "behaviour": behaviour_summary(records),
        "limits": execution_limits(records),  # executions that reached the CPU limit / the wall-clock bound
        "timing": {
            "task_wall_s": _stats([r["timing"]["total_s"] for r in records if "timing" in r]),
            "llm_s": _stats([r["timing"]["llm_s"] for r in records if "timing" in r]),
            "evaluation_s": _stats([r["timing"]["evaluation_s"] for r in records if "timing" in r]),
        },
    }
