"""How hard a design instance is, measured with our own reference in this process: the band of
passing designs as a fraction of the allowed range, and what an engineer's closed-form estimate
gives. Shown by ``meceng tasks show`` and the design docs; the figures per task model are kept in
``tasks/design/figures.json`` (written by ``scripts/design_figures.py``)."""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product
from typing import Any

import numpy as np

from meceng.tasks.base import TaskInstance
from meceng.tasks.design_base import DesignTask
from meceng.tasks.design_sim import simulate


def measured(design_task: DesignTask, design: dict[str, float]) -> float:
    """The spec's quantity of the reference built with ``design`` (nan when it fails to solve)."""
    try:
        times, q = simulate(design_task.program(design))
    except Exception:
        return float("nan")
    return design_task.measure(times, q, design)


def _passes(task: DesignTask, design: dict[str, float]) -> bool:
    return task.verdict(measured(task, design))[0]


def band_along(task: DesignTask, name: str, fixed: dict[str, float], start: float, steps: int = 7) -> float:
    """The width of the passing interval of variable ``name`` around ``start`` (which passes), the
    other variables at ``fixed``: each edge found by doubling outwards, then ``steps`` bisections."""
    variable = next(v for v in task.variables if v.name == name)
    width = 0.0
    for direction in (-1.0, 1.0):
        bound = variable.high if direction > 0 else variable.low
        inside, step = start, 0.002 * (variable.high - variable.low)
        outside = None
        while True:
            trial = float(np.clip(inside + direction * step, variable.low, variable.high))
            if _passes(task, {**fixed, name: trial}):
                inside = trial
                if trial == bound:
                    break
                step *= 2
            else:
                outside = trial
                break
        if outside is not None:
            for _ in range(steps):
                middle = 0.5 * (inside + outside)
                if _passes(task, {**fixed, name: middle}):
                    inside = middle
                else:
                    outside = middle
        width += abs(inside - start)
    return width


def band_fraction(task: DesignTask, grid: int = 5) -> float:
    """The passing designs' share of the allowed range (one variable: the passing interval around
    the gold design; two: the mean passing width of the first variable over a grid of the others,
    each line searched from the first variable's passing value closest to the gold one)."""
    first, *others = task.variables
    span = first.high - first.low
    if not others:
        return band_along(task, first.name, {}, task.gold[first.name]) / span
    widths = []
    for point in product(*(np.linspace(v.low, v.high, grid) for v in others)):
        fixed = {v.name: float(x) for v, x in zip(others, point, strict=True)}
        start = _passing_start(task, first, fixed)
        widths.append(0.0 if start is None else band_along(task, first.name, fixed, start))
    return float(np.mean(widths)) / span


def _passing_start(task: DesignTask, variable: Any, fixed: dict[str, float], samples: int = 41) -> float | None:
    """A passing value of ``variable`` with the others ``fixed``: a root of spec - target on a grid."""
    xs = np.linspace(variable.low, variable.high, samples)
    values = np.array([measured(task, {**fixed, variable.name: float(x)}) for x in xs]) - task.target
    for i in range(samples - 1):
        a, b = values[i], values[i + 1]
        if np.isfinite(a) and np.isfinite(b) and a * b <= 0:
            lo, hi = float(xs[i]), float(xs[i + 1])
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                m = measured(task, {**fixed, variable.name: mid}) - task.target
                if not np.isfinite(m):
                    break
                if abs(m) <= 0.5 * task.tolerance:
                    return mid
                lo, hi = (lo, mid) if (m > 0) == (b > 0) else (mid, hi)
    return None


@dataclass(frozen=True)
class EstimateCheck:
    design: dict[str, float]
    value: float
    passed: bool
    error_in_tolerances: float  # |value - target| / tolerance

    def to_json(self) -> dict[str, Any]:
        return {"design": self.design, "value": self.value, "passed": self.passed,
                "error_in_tolerances": round(self.error_in_tolerances, 3)}


def check_estimate(instance: TaskInstance) -> EstimateCheck:
    """The engineer's closed-form design, clipped to the range, run through the reference."""
    task: DesignTask = instance.design
    raw = task.model.estimate(task.values, task.target)
    design = {v.name: float(np.clip(raw[v.name], v.low, v.high)) for v in task.variables}
    value = measured(task, design)
    error = abs(value - task.target) / task.tolerance if np.isfinite(value) else float("inf")
    return EstimateCheck(design, value, bool(error <= 1.0), float(error))


def model_figures(slug: str) -> dict[str, Any] | None:
    """The figures ``scripts/design_figures.py --write`` measured for a design task model (None: not yet)."""
    import json
    from pathlib import Path

    path = Path(__file__).resolve().parent / "design" / "figures.json"
    return json.loads(path.read_text()).get(slug) if path.exists() else None


def hardness(instance: TaskInstance) -> dict[str, Any]:
    """What ``meceng tasks show`` adds for a design instance: the model's measured band and estimate
    figures, and the estimate of this instance with the verdict it gets."""
    task: DesignTask = instance.design
    check = check_estimate(instance)
    return {"band": model_figures(instance.slug),
            "estimate": {"method": task.model.estimate_text, **check.to_json()}}
