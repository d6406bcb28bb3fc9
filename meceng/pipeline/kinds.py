"""Task kinds: what a rigid task, a part and an assembly add to the one task flow.

A kind is the scorer half of a task (as in inspect: dataset + solver + scorer): its component
catalog, the limits its tools run under, the files its programs load, how its program is graded
and what its record adds. Selection, generation, the agent loop, first-vs-final grading, timing,
program files and the record itself are the flow's (``flow.py``), written once for all kinds.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

from meceng.catalog.component import Catalog
from meceng.eval.chain import StageResult
from meceng.tasks.base import TaskInstance
from meceng.tools.execution import ExecutionLimits

from .design import grade_design
from .evaluation import Evaluator
from .graded import Graded


class TaskKind(Protocol):
    catalog: Catalog
    limits: ExecutionLimits
    files: dict[str, Path] | None  # what the program loads (an assembly's parts)

    async def grade(self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None,
                    error: str | None, *, keep: bool) -> Graded:
        """Grade one program; ``keep``: the final answer (a passing part is kept for its assembly)."""
        ...

    def extend(self, record: dict[str, Any], instance: TaskInstance, graded: Graded, run_dir: Path) -> None:
        """Add what this kind's record holds beyond the shared fields."""
        ...


@dataclass
class RigidKind:
    """Levels 1-2: the paper's chain from components to the numerical solution."""

    evaluator: Evaluator
    files: dict[str, Path] | None = None

    @property
    def catalog(self) -> Catalog:
        return self.evaluator.catalog

    @property
    def limits(self) -> ExecutionLimits:
        return self.evaluator.limits

    async def grade(self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None,
                    error: str | None, *, keep: bool) -> Graded:
        return Graded(*await self.evaluator.evaluate(instance, code, selected, error))

    def extend(self, record: dict[str, Any], instance: TaskInstance, graded: Graded, run_dir: Path) -> None:
        return None


@dataclass
class PartKind:
    """Level 3a: mesh-size pre-check, meshing and reduction, the part metrics; a passing final
    part is kept at ``keep_at`` for the assembly that needs it."""

    evaluator: Evaluator
    keep_at: Path | None = None
    files: dict[str, Path] | None = None

    @property
    def catalog(self) -> Catalog:
        return self.evaluator.part_catalog

    @property
    def limits(self) -> ExecutionLimits:
        return self.evaluator.part_limits

    async def grade(self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None,
                    error: str | None, *, keep: bool) -> Graded:
        verdict, candidate, reference, facts = await self.evaluator.evaluate_part(
            instance, code, selected, error, save_to=self.keep_at if keep else None)
        return Graded(verdict, candidate, reference, facts)

    def extend(self, record: dict[str, Any], instance: TaskInstance, graded: Graded, run_dir: Path) -> None:
        facts = dict(graded.facts)
        if "saved_part" in facts:
            record["files"]["part"] = str(Path(facts.pop("saved_part")).relative_to(run_dir))
        candidate, reference = graded.candidate, graded.reference
        record["timing"].update({k: round(v, 4) for k, v in {
            "part_run_s": candidate.wall_time, "reference_run_s": reference.wall_time, **candidate.part_times,
            "metrics_s": facts.pop("metrics_s", 0.0)}.items()})
        record["part"] = {**facts, "spec": instance.part.to_json(), "reference_times": reference.part_times,
                          "reference_nodes": (reference.part or {}).get("nodes")}


@dataclass
class AssemblyKind:
    """Level 3b once its parts passed: the level 1-2 chain on a program that loads the LLM-made
    parts (``files``, handed to the ground truth too), after the stages its parts decided."""

    evaluator: Evaluator
    files: dict[str, Path]
    parts_stages: tuple[StageResult, ...]
    part_keys: dict[str, str]
    part_timing: dict[str, float]

    @property
    def catalog(self) -> Catalog:
        return self.evaluator.assembly_catalog

    @property
    def limits(self) -> ExecutionLimits:
        return self.evaluator.limits

    async def grade(self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None,
                    error: str | None, *, keep: bool) -> Graded:
        chain, candidate, reference = await self.evaluator.evaluate(instance, code, selected, error, files=self.files)
        verdict = dataclasses.replace(chain, stages=(*self.parts_stages, *chain.stages))
        return Graded(verdict, candidate, reference)

    def extend(self, record: dict[str, Any], instance: TaskInstance, graded: Graded, run_dir: Path) -> None:
        timing = record["timing"]
        timing["mbs_evaluation_s"] = timing["evaluation_s"]
        timing["total_s"] = round(timing["total_s"] + self.part_timing.get("parts_wall_s", 0.0), 4)
        timing.update({k: round(v, 4) for k, v in self.part_timing.items()})
        record["parts"] = self.part_keys


@dataclass
class DesignKind(RigidKind):
    """Level 4: a rigid task's catalog and limits; graded by its declared values, the spec and behaviour."""

    async def grade(self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None,
                    error: str | None, *, keep: bool) -> Graded:
        return await grade_design(self.evaluator, instance, code, selected, error)

    def extend(self, record: dict[str, Any], instance: TaskInstance, graded: Graded, run_dir: Path) -> None:
        record["design"] = graded.facts.get("design")


def single_kind(instance: TaskInstance, evaluator: Evaluator, keep_at: Path | None = None) -> TaskKind:
    """The scorer of a task that is not an assembly: a part, a design task or a rigid one."""
    if instance.kind == "part":
        return PartKind(evaluator, keep_at=keep_at)
    if instance.design is not None:
        return DesignKind(evaluator)
    return RigidKind(evaluator)
