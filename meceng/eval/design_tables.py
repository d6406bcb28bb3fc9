"""Level 4 in the report: pure functions of the records (issue 42).

The first-try rate (the first program the agent wrote; without the agent, the one program) beside
the final rate, how the failures split over the design stages, and the spread of the spec's margins
(1: on target, 0: at the tolerance's edge, below 0: outside) over the answers whose design was judged.
"""

from __future__ import annotations

import statistics
from typing import Any

from meceng.eval.rates import Rate, Run

DESIGN_LEVEL = ("4",)
HEADERS = ["run", "n", "first try", "final", "DESIGN invalid", "not one simulation", "spec missed",
           "behaviour failed", "margin median [min, max]"]


def _first_overall(task: dict[str, Any]) -> bool:
    agent = task.get("agent")
    return bool(agent["first_overall"]) if agent and "first_overall" in agent else bool(task.get("overall"))


def design_rows(runs: list[Run]) -> list[dict[str, Any]]:
    rows = []
    for run in runs:
        tasks = run.graded(DESIGN_LEVEL)
        if not tasks:
            continue
        failures = [t.get("first_failure") for t in tasks]
        margins = [m for t in tasks if (m := (t.get("design") or {}).get("margin")) is not None]
        rows.append({
            "run": run.label, "n": len(tasks),
            "first": Rate(sum(_first_overall(t) for t in tasks), len(tasks)),
            "final": Rate(sum(bool(t.get("overall")) for t in tasks), len(tasks)),
            "invalid": failures.count("design_declared"), "simulations": failures.count("one_simulation"),
            "missed": failures.count("design_met"), "behaviour": failures.count("behaviour_match"),
            "margins": margins,
        })
    return rows


def design_cells(row: dict[str, Any]) -> list[str]:
    margins = row["margins"]
    spread = (f"{statistics.median(margins):.2f} [{min(margins):.2f}, {max(margins):.2f}]" if margins else "–")
    return [row["run"], str(row["n"]), row["first"].text(), row["final"].text(), str(row["invalid"]),
            str(row["simulations"]), str(row["missed"]), str(row["behaviour"]), spread]
