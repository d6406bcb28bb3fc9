"""How long the programs of a run took and how many reached a limit (issue 45).

A program is graded by its CPU time: reaching the CPU limit is the program's timeout (a verdict);
reaching the wall-clock bound with CPU time to spare is the machine's (an infrastructure failure,
not graded, done again by ``--resume``). The report shows both counts beside each other, so that a
reader sees whether a run's timeouts were the models' or the machine's load. Counted over the
executions a run's records keep: each task's candidate (``execution``) and its ground truth
(``reference_execution``); a record with no program run (no code, a flagged mesh size) adds none.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

#: the executions a task record keeps
EXECUTION_KEYS = ("execution", "reference_execution")
#: error kinds that mean a limit stopped the program: the CPU limit, the wall-clock bound
CPU_LIMIT = "timeout"
WALL_BOUND = "wall_timeout"
#: executions that never started a program
NOT_RUN = ("no_code", "mesh_size")


def executions(record: dict[str, Any]) -> list[dict[str, Any]]:
    """The execution summaries of one record that ran a program."""
    found = []
    for key in EXECUTION_KEYS:
        run = record.get(key)
        if not isinstance(run, dict) or run.get("error_kind") in NOT_RUN or run.get("stage") in ("not_run", None):
            continue
        found.append(run)
    return found


def _p95(values: list[float]) -> float | None:
    return float(np.percentile(values, 95)) if values else None


def execution_limits(records: Iterable[dict[str, Any]]) -> dict[str, Any]:
    """Executions, how many reached the CPU limit and the wall-clock bound, and the CPU and wall
    seconds they took (P95 and max; records before issue 45 have no CPU time)."""
    runs = [run for record in records for run in executions(record)]
    cpu = [float(r["cpu_s"]) for r in runs if r.get("cpu_s") is not None]
    wall = [float(r.get("wall_s", r.get("wall_time")) or 0.0) for r in runs]
    return {
        "executions": len(runs),
        "cpu_limit": sum(1 for r in runs if r.get("error_kind") == CPU_LIMIT),
        "wall_bound": sum(1 for r in runs if r.get("error_kind") == WALL_BOUND),
        "cpu_s_p95": _p95(cpu), "cpu_s_max": max(cpu) if cpu else None,
        "wall_s_p95": _p95(wall), "wall_s_max": max(wall) if wall else None,
    }


LIMIT_HEADERS = ["run", "executions", "CPU limit reached (program's timeout)",
                 "wall-clock bound reached (machine's, not graded)", "CPU s (P95 / max)", "wall s (P95 / max)"]


def limit_rows(runs: Iterable[tuple[str, list[dict[str, Any]]]]) -> list[list[str]]:
    """The report's table: one row per (run label, records)."""

    def pair(a: float | None, b: float | None) -> str:
        return "–" if a is None or b is None else f"{a:.1f} / {b:.1f}"

    rows = []
    for label, records in runs:
        c = execution_limits(records)
        if c["executions"]:
            rows.append([label, str(c["executions"]), str(c["cpu_limit"]), str(c["wall_bound"]),
                         pair(c["cpu_s_p95"], c["cpu_s_max"]), pair(c["wall_s_p95"], c["wall_s_max"])])
    return rows
