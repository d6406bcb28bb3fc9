"""``--agent consensus``: K independent programs per task, grouped by behaviour, the largest group's
program as the answer and its share as the run's confidence (``eval/consensus.py`` says how groups
are formed).

Each sample is the paper's two steps (choose components, write the program) asked again with its
own sampling seed (``ChatRequest.sample``); each program runs in the sandbox with its motion
recorded and is graded against the ground truth like any answer, so the record holds every sample's
paper and behaviour verdict, but the grouping never sees the ground truth: only the samples' own
motions. The same program text is run and graded once. A sample the server lost (or whose program
the wall clock stopped under its CPU limit) is recorded as such and counted nowhere; when every
sample is lost, the task is lost (``--resume`` does it again).
"""

from __future__ import annotations

import asyncio
import time
from dataclasses import dataclass, replace
from typing import Any

from meceng.agents.steps import Generation, Selection, choose_components, generate_code
from meceng.eval.behaviour import tolerance_for
from meceng.eval.consensus import Consensus, consensus_of
from meceng.llm.ensemble import model_of_sample
from meceng.llm.types import Backend, ChatRequest, ChatResponse, LLMSettings
from meceng.tasks.base import TaskInstance

from .grading import offload
from .kinds import Graded, TaskKind
from .records import lost_record, task_record
from .rundir import save_programs
from .traces import save_traces


class SampledBackend:
    """The run's backend with every request marked as sample ``index`` (its own seed and cache key)."""

    def __init__(self, inner: Backend, index: int) -> None:
        self.inner = inner
        self.index = index
        self.name = inner.name

    async def chat(self, request: ChatRequest) -> ChatResponse:
        return await self.inner.chat(replace(request, sample=self.index))

    async def aclose(self) -> None:
        return None


@dataclass(frozen=True)
class Sample:
    index: int
    selection: Selection
    generation: Generation | None  # None: the selection was lost

    @property
    def lost(self) -> str | None:
        return self.selection.infrastructure_error or (
            self.generation.infrastructure_error if self.generation is not None else None)


async def draw(backend: Backend, instance: TaskInstance, kind: TaskKind, templates: tuple[str, str],
               index: int) -> Sample:
    """One independent answer: both LLM steps as sample ``index``."""
    sampled = SampledBackend(backend, index)
    selection = await choose_components(sampled, instance, kind.catalog, templates[0])
    if selection.infrastructure_error is not None:
        return Sample(index, selection, None)
    return Sample(index, selection, await generate_code(sampled, instance, kind.catalog, selection, templates[1]))


def sample_json(sample: Sample, graded: Graded | None, consensus: Consensus, llm: LLMSettings) -> dict[str, Any]:
    """A sample in the record: the model that wrote it (``llm``, the k mod M rule's), its program,
    both verdicts against the ground truth, its group."""
    generation = sample.generation
    block: dict[str, Any] = {
        "index": sample.index, "model": llm.model,
        "seed": None if llm.api_defaults else llm.sample_seed(sample.index), "lost": sample.lost,
        "components": list(sample.selection.names),
        "code": generation.code if generation is not None else None,
        "code_error": generation.error if generation is not None else None,
        "endpoint": (generation.meta.get("endpoint") if generation is not None else None),
        "group": consensus.group_of(sample.index),
        "tokens": {"prompt": sum(s.meta.get("prompt_tokens", 0) for s in _steps(sample)),
                   "completion": sum(s.meta.get("completion_tokens", 0) for s in _steps(sample))},
    }
    if graded is not None:
        verdict = graded.verdict
        behaviour = verdict.behaviour or {}
        block.update(overall=verdict.overall, first_failure=verdict.first_failure,
                     error_categories=list(verdict.error_categories), behaviour_passed=behaviour.get("passed"),
                     behaviour_detail=behaviour.get("detail"), ran=graded.candidate.motion is not None,
                     execution_error=graded.candidate.error)
    return block


def _steps(sample: Sample) -> list[Selection | Generation]:
    return [sample.selection] + ([sample.generation] if sample.generation is not None else [])


async def consensus_flow(instance: TaskInstance, kind: TaskKind, ctx: Any) -> dict[str, Any]:
    """One task instance under ``--agent consensus`` (``ctx``: the flow's ``FlowContext``)."""
    settings, evaluator = ctx.settings, ctx.evaluator

    def model(index: int) -> LLMSettings:
        return model_of_sample(settings.sample_models, index)

    t0 = time.perf_counter()
    evaluator.prefetch(instance)
    templates = settings.templates(instance.kind)
    samples = list(await asyncio.gather(*(draw(ctx.backend, instance, kind, templates, k)
                                          for k in range(settings.samples))))
    t_llm = time.perf_counter()
    answered = [s for s in samples if s.lost is None]
    if not answered:
        first = samples[0]
        record = lost_record(instance, f"every sample lost: {first.lost}", _times(t0, t_llm),
                             selection=first.selection, generation=first.generation)
        record["consensus"] = {"samples": [sample_json(s, None, Consensus((), None, 0.0, 0), model(s.index))
                                           for s in samples], "k": settings.samples}
        return record
    # the same program (and components) is run and graded once
    jobs: dict[tuple[Any, ...], asyncio.Task[Graded]] = {}
    job_of: dict[int, asyncio.Task[Graded]] = {}
    for s in answered:
        assert s.generation is not None
        key = (s.generation.code, s.selection.names, s.generation.error)
        if key not in jobs:
            jobs[key] = asyncio.ensure_future(kind.grade(instance, s.generation.code, s.selection.names,
                                                         s.generation.error, keep=False))
        job_of[s.index] = jobs[key]
    await asyncio.gather(*jobs.values())
    graded: dict[int, Graded] = {index: job.result() for index, job in job_of.items()}
    motions = [graded[s.index].candidate.motion if s.index in graded else None for s in samples]
    programs = [s.generation.code if s.generation is not None else None for s in samples]
    # a sample the wall clock stopped with CPU time to spare was the machine's, not the model's: lost
    lost = [s.lost is not None or (s.index in graded and graded[s.index].candidate.lost_to_machine) for s in samples]
    if all(lost):
        reason = next(graded[s.index].candidate.error for s in samples if s.index in graded)
        return lost_record(instance, f"every sample lost: {reason}", _times(t0, t_llm, time.perf_counter()),
                           selection=answered[0].selection, generation=answered[0].generation)
    consensus = await offload(evaluator.grading, consensus_of, motions, programs, lost, tolerance_for(instance.slug))
    assert consensus.chosen is not None
    chosen = samples[consensus.chosen]
    answer = graded[chosen.index]
    assert chosen.generation is not None
    files = await offload(evaluator.grading, save_programs, ctx.writer.run_dir, instance, chosen.generation.code)
    record = task_record(instance, chosen.selection, chosen.generation, answer.verdict, answer.candidate,
                         answer.reference, _times(t0, t_llm, time.perf_counter()), files)
    record["tokens"] = {key: sum(sum(int(step.meta.get(f"{key}_tokens", 0)) for step in _steps(s)) for s in samples)
                        for key in ("prompt", "completion", "reasoning")}
    kind.extend(record, instance, answer, ctx.writer.run_dir)
    traces = await offload(evaluator.grading, save_traces, ctx.writer.run_dir, instance.key, answer.candidate,
                           answer.reference)
    if traces is not None:
        record["files"]["traces"] = traces
    record["consensus"] = {
        "k": settings.samples, **consensus.to_json(),
        **({"models": [m.model for m in settings.consensus_models]} if settings.consensus_models else {}),
        "samples": [sample_json(s, graded.get(s.index), consensus, model(s.index)) for s in samples],
    }
    return record


def _times(t0: float, t_llm: float, t_end: float | None = None) -> dict[str, float]:
    end = t_llm if t_end is None else t_end
    return {"llm_s": t_llm - t0, "evaluation_s": end - t_llm, "total_s": end - t0}
