"""Run a ground-truth program in the test process and return its trajectory.

Used by the physics tests, which check ground truths against what mechanics predicts. The
pipeline itself never runs programs in-process; it uses the isolated executor.
"""

from __future__ import annotations

import numpy as np

SOLVE = "mbs.SolveDynamic(simulationSettings)"


def simulate(program: str) -> tuple[np.ndarray, np.ndarray, object]:
    """Execute ``program`` and return (times, q_total per step, the MainSystem).

    ``q_total = q_ref + q`` of all ODE2 coordinates, one row per time step including t = 0.
    """
    if SOLVE not in program:
        raise ValueError("program has no standard simulation block")
    rows: list[tuple[float, np.ndarray]] = []

    def record(mbs, t):  # post-step user function
        rows.append((t, np.array(mbs.systemData.GetODE2CoordinatesTotal())))
        return True

    hooked = program.replace(SOLVE, f"_hook(mbs)\n{SOLVE}")
    namespace: dict = {"__name__": "__meceng_test__"}

    def hook(mbs):
        namespace["_mbs"] = mbs
        rows.append((0.0, np.array(mbs.systemData.GetODE2CoordinatesTotal())))
        mbs.SetPostStepUserFunction(record)

    namespace["_hook"] = hook
    exec(compile(hooked, "<reference>", "exec"), namespace)
    times = np.array([r[0] for r in rows])
    # the solver may report t = 0 itself; keep the first row per time
    _, first = np.unique(times, return_index=True)
    first.sort()
    q = np.array([rows[i][1] for i in first])
    return times[first], q, namespace["_mbs"]
