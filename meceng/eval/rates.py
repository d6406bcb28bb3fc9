"""Runs as the report reads them, and rates with their sample count and 95 % Wilson interval, so a
reader sees what is noise."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any


def wilson(successes: int, n: int, z: float = 1.959963984540054) -> tuple[float, float]:
    """95 % Wilson score interval of a binomial proportion; (0, 1) for n = 0."""
    if n == 0:
        return 0.0, 1.0
    p = successes / n
    denominator = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denominator
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denominator
    # rounding can put an end a hair past the rate itself (at 0 % or 100 %): the interval must hold it
    return max(0.0, min(p, centre - half)), min(1.0, max(p, centre + half))


@dataclass(frozen=True)
class Rate:
    passed: int
    n: int

    @property
    def value(self) -> float | None:
        return self.passed / self.n if self.n else None

    @property
    def interval(self) -> tuple[float, float]:
        return wilson(self.passed, self.n)

    @property
    def error_bar(self) -> tuple[float, float]:
        """Distances from the rate down and up to the interval's ends, never negative (for plots)."""
        if self.value is None:
            return 0.0, 0.0
        low, high = self.interval
        return max(0.0, self.value - low), max(0.0, high - self.value)

    def text(self) -> str:
        if not self.n:
            return "–"
        low, high = self.interval
        return f"{100 * self.value:.1f} [{100 * low:.0f}–{100 * high:.0f}]"

    def to_json(self) -> dict[str, Any]:
        low, high = self.interval
        return {"passed": self.passed, "n": self.n, "rate": self.value, "ci95": [low, high]}


def run_model(settings: dict[str, Any]) -> str:
    """A run's model as the report and viewer name it (from its settings.json); a consensus run
    across models names them all (``a+b``), so its rates are never pooled with its first model's."""
    models = settings.get("pipeline", {}).get("consensus_models")
    if models:
        return "+".join(str(m["model"]) for m in models)
    return str(settings.get("llm", {}).get("model", "?"))


@dataclass(frozen=True)
class Run:
    path: Path
    settings: dict[str, Any]
    summary: dict[str, Any]
    tasks: list[dict[str, Any]]

    @property
    def model(self) -> str:
        return run_model(self.settings)

    @property
    def temperature(self) -> float:
        return float(self.settings["llm"]["temperature"])

    @property
    def think(self) -> str:
        return str(self.settings["llm"]["think"])

    @property
    def select_template(self) -> str:
        return str(self.settings["prompt"]["select_template"])

    @property
    def code_template(self) -> str:
        return str(self.settings["prompt"]["code_template"])

    @property
    def texts(self) -> str:
        """Which task texts the run's tasks had: "paper" (runs before issue 36 say none) or "open"."""
        return str(self.settings.get("pipeline", {}).get("texts", "paper"))

    @property
    def model_key(self) -> str:
        """The model as the report groups runs by it: an open-text run's rates are never pooled with
        the paper-text runs of the same model (they are graded differently)."""
        return self.model if self.texts == "paper" else f"{self.model} [{self.texts} texts]"

    @property
    def label(self) -> str:
        return (f"{self.model} T={self.temperature:g} think={self.think} "
                f"{self.select_template}/{self.code_template}"
                + ("" if self.texts == "paper" else f" texts={self.texts}"))

    @property
    def setting_label(self) -> str:
        """The label without the texts: runs that differ only in their texts share it."""
        return f"{self.model} T={self.temperature:g} think={self.think} {self.select_template}/{self.code_template}"

    def graded(self, levels: tuple[str, ...] | None = None) -> list[dict[str, Any]]:
        """Task records that say something about the model (infrastructure failures left out),
        of the given levels only if ``levels`` is set."""
        return [t for t in self.tasks if t.get("first_failure") != "infrastructure"
                and (levels is None or str(t.get("level")) in levels)]

    @property
    def rigid_levels(self) -> tuple[str, ...] | None:
        """Levels 1-2 when the run has rigid tasks (Table 2 is about them), else everything."""
        return ("1", "2") if any(str(t.get("level")) in ("1", "2") for t in self.tasks) else None

    @property
    def flexible_only(self) -> bool:
        return bool(self.tasks) and all(str(t.get("level")) in ("3a", "3b") for t in self.tasks)


def load_runs(paths: list[Path]) -> list[Run]:
    """Run folders, run.json files, or folders holding run folders (a sweep's --out)."""
    files: list[Path] = []
    for path in paths:
        if path.is_file():
            files.append(path)
        elif (path / "run.json").exists():
            files.append(path / "run.json")
        elif path.is_dir():
            files.extend(sorted(path.glob("*/run.json")))
        else:
            raise FileNotFoundError(f"{path}: no run.json there")
    if not files:
        raise FileNotFoundError("no run.json found in " + ", ".join(map(str, paths)))
    runs = []
    for file in files:
        data = json.loads(file.read_text())
        runs.append(Run(file, data["settings"], data["summary"], data["tasks"]))
    return runs


def stage_rate(tasks: list[dict[str, Any]], stage: str) -> Rate:
    if stage == "overall":
        return Rate(sum(1 for t in tasks if t.get("overall")), len(tasks))
    passed = sum(1 for t in tasks for s in t.get("stages", []) if s["name"] == stage and s["passed"]
                 and s.get("required", True) is not False)
    # a record that does not require the stage (an open text's writing stages) is not in its rate
    exempt = sum(1 for t in tasks for s in t.get("stages", []) if s["name"] == stage
                 and s.get("required", True) is False)
    return Rate(passed, len(tasks) - exempt)
