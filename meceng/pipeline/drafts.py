"""Drafts graded as a model's program would be: which fail, and whether the grader's category is
the fault's label (a mismatch is a finding about the grader or the fault, counted and listed)."""

from __future__ import annotations

import asyncio
import random
from dataclasses import dataclass, replace
from typing import Any

from meceng.logs import get_logger
from meceng.tasks.base import TaskInstance
from meceng.tasks.drafts import PART_EXPECTED, Draft, candidate_drafts

from .evaluation import Evaluator

log = get_logger(__name__)


@dataclass(frozen=True)
class GradedDraft:
    draft: Draft
    fails: bool
    first_failure: str | None
    categories: tuple[str, ...]
    by_behaviour: bool = False  # an open text's draft: graded by behaviour, which names no category

    @property
    def agrees(self) -> bool | None:
        """The grader says what the label says: the category among the record's categories (levels
        1-2), or the first failed stage among the fault's expected ones (parts); None where the
        behaviour verdict graded it (an open text): it names no category to agree with."""
        if self.by_behaviour:
            return None
        if self.draft.label in PART_EXPECTED:
            return self.first_failure in PART_EXPECTED[self.draft.label]
        return self.draft.label in self.categories

    def to_json(self, program: bool = True) -> dict[str, Any]:
        block = self.draft.to_json()
        if not program:
            block.pop("program")
        return {**block, "fails": self.fails, "first_failure": self.first_failure,
                "grader_categories": list(self.categories), "agrees": self.agrees}


async def grade_drafts(instance: TaskInstance, evaluator: Evaluator) -> list[GradedDraft]:
    """Every candidate draft of the instance, graded (the reference execution is shared)."""
    async def one(draft: Draft) -> GradedDraft:
        try:
            if instance.kind == "part":
                verdict = (await evaluator.evaluate_part(instance, draft.program, None, None))[0]
            else:
                verdict = (await evaluator.evaluate(instance, draft.program, None, None))[0]
        except Exception as exc:  # a draft the harness cannot grade is no task; the run goes on
            log.error("draft not graded", task=instance.key, draft=draft.id, error=f"{type(exc).__name__}: {exc}")
            return GradedDraft(draft, False, "not graded", ())
        return GradedDraft(draft, not verdict.overall and verdict.infrastructure_error is None, verdict.first_failure,
                           tuple(verdict.error_categories), by_behaviour=instance.texts == "open")
    return list(await asyncio.gather(*(one(d) for d in candidate_drafts(instance))))


def failing(graded: list[GradedDraft]) -> list[GradedDraft]:
    """The drafts a repair task uses: those the grader fails (a fault without effect is no task)."""
    return [g for g in graded if g.fails]


async def drafts_of(instance: TaskInstance) -> list[GradedDraft]:
    """``meceng drafts``: an instance's drafts graded outside a run."""
    from meceng.eval.chain import Tolerances
    from meceng.tools.execution import ExecutionLimits

    return await grade_drafts(instance, Evaluator(2, ExecutionLimits(), Tolerances()))


async def repair_instances(instances: list[TaskInstance], evaluator: Evaluator, per_task: int) -> list[TaskInstance]:
    """The repair benchmark's tasks: for every instance (assemblies have no drafts), up to
    ``per_task`` of its failing drafts in an order drawn from its key, so the kinds of fault spread
    over the instances; each carries the grader's verdict on its draft."""
    async def one(instance: TaskInstance) -> list[TaskInstance]:
        if instance.kind == "assembly":
            return []
        try:
            chosen = failing(await grade_drafts(instance, evaluator))
        finally:
            evaluator.release(instance)
        random.Random(instance.key).shuffle(chosen)
        return [replace(instance, draft=replace(g.draft, graded={"first_failure": g.first_failure,
                                                                 "categories": list(g.categories),
                                                                 "agrees": g.agrees}))
                for g in chosen[:per_task]]
    return [task for tasks in await asyncio.gather(*(one(i) for i in instances)) for task in tasks]
