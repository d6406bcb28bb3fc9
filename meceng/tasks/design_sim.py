"""Runs one of our own design references in this process, to measure an instance's target.

Only for programs this package writes (never a model's: those run in the sandbox). The coordinates
are recorded as the sandbox's harness records them (``q_ref + q`` after every step, no row at
t = 0), so a spec measured here and on a graded execution reads the same rows.
"""

from __future__ import annotations

from typing import Any

import numpy as np

_SOLVE = "mbs.SolveDynamic(simulationSettings)"


def simulate(program: str) -> tuple[np.ndarray, np.ndarray]:
    """(step times, coordinates per step) of ``program``, which ends in one ``mbs.SolveDynamic``."""
    head, solve, tail = program.rpartition(_SOLVE)
    if not solve or tail.strip():
        raise ValueError("a design reference ends in its one mbs.SolveDynamic(simulationSettings) call")
    namespace: dict[str, Any] = {"__name__": "meceng_design_reference"}
    try:
        import exudyn  # noqa: F401
    except ImportError as exc:
        raise RuntimeError(f"a design task's instance runs its reference in this process, and Exudyn does not "
                           f"import here ({exc}): `meceng doctor` names what is missing") from exc
    exec(compile(head, "<design reference>", "exec"), namespace)
    mbs = namespace["mbs"]
    times: list[float] = []
    rows: list[np.ndarray] = []

    def record(system: Any, t: float) -> bool:
        times.append(t)
        rows.append(np.array(system.systemData.GetODE2CoordinatesTotal()))
        return True

    mbs.SetPostStepUserFunction(record)
    mbs.SolveDynamic(namespace["simulationSettings"])
    return np.asarray(times, dtype=float), np.vstack(rows)
