"""The task flow, written once for every level (paper Fig. 2, 4-6).

Choose components -> write the program (two LLM steps, or the tool-calling agent) -> grade it
with the task kind's scorer -> grade the agent's first program too if it differs -> save the
programs -> the record. A selection lost to the server ends the task before any code request.
An assembly is its parts' flows, then its own flow only when every part passed.
"""

from __future__ import annotations

import asyncio
import time
from dataclasses import dataclass
from typing import Any

from meceng.agents.loop import run_agent
from meceng.agents.prompts import repair_prompt
from meceng.agents.steps import choose_components, generate_code, given_selection
from meceng.agents.toolbox import Toolbox
from meceng.eval.chain import RIGID_STAGES, StageResult, Verdict
from meceng.llm.types import Backend
from meceng.tasks.base import TaskInstance

from .consensus import consensus_flow
from .evaluation import Evaluator
from .grading import offload
from .kinds import AssemblyKind, PartKind, TaskKind, single_kind
from .records import agent_block, agent_generation, lost_record, not_started_record, task_record
from .rundir import RunWriter, save_programs
from .settings import RunSettings
from .traces import save_traces


@dataclass(frozen=True)
class FlowContext:
    """The run's services every task flow uses."""

    backend: Backend
    evaluator: Evaluator
    settings: RunSettings
    writer: RunWriter


async def run_flow(instance: TaskInstance, kind: TaskKind, ctx: FlowContext) -> dict[str, Any]:
    """One task instance from the prompts to its record."""
    try:
        return await _flow(instance, kind, ctx)
    finally:
        ctx.evaluator.release(instance)


async def _flow(instance: TaskInstance, kind: TaskKind, ctx: FlowContext) -> dict[str, Any]:
    settings, evaluator = ctx.settings, ctx.evaluator
    if settings.agent == "consensus":
        return await consensus_flow(instance, kind, ctx)
    t0 = time.perf_counter()
    evaluator.prefetch(instance)
    select_template, code_template = settings.templates(instance.kind)
    repair = instance.draft is not None
    if repair:  # the draft already chose its components: no selection request
        selection = given_selection(instance)
    else:
        selection = await choose_components(ctx.backend, instance, kind.catalog, select_template)
    if selection.infrastructure_error is not None:  # no code request with a context the model never chose
        return lost_record(instance, selection.infrastructure_error, _times(t0, time.perf_counter()),
                           selection=selection)
    question = (repair_prompt(code_template, instance.description, kind.catalog.context(selection.names),
                              instance.draft.program, instance.texts) if repair else None)
    agent = None
    if settings.agent == "loop" or (repair and settings.repair_tools):
        toolbox = Toolbox(instance, kind.catalog, kind.limits, evaluator.pool, files=kind.files,
                          vision=settings.llm.vision)
        agent = await run_agent(ctx.backend, instance, kind.catalog, selection, toolbox, template=code_template,
                                max_rounds=settings.max_rounds, token_budget=settings.token_budget, prompt=question)
        generation = agent_generation(agent)
    else:
        generation = await generate_code(ctx.backend, instance, kind.catalog, selection, code_template,
                                         prompt=question)
    t_llm = time.perf_counter()
    if generation.infrastructure_error is not None:
        return lost_record(instance, generation.infrastructure_error, _times(t0, t_llm),
                           selection=selection, generation=generation)
    graded = await kind.grade(instance, generation.code, selection.names, generation.error, keep=True)
    first, first_facts = graded.verdict, graded.facts
    if agent is not None and agent.first_code != agent.final_code:
        first_graded = await kind.grade(instance, agent.first_code, selection.names, agent.error, keep=False)
        first, first_facts = first_graded.verdict, first_graded.facts
    files = await offload(evaluator.grading, save_programs, ctx.writer.run_dir, instance, generation.code)
    record = task_record(instance, selection, generation, graded.verdict, graded.candidate, graded.reference,
                         _times(t0, t_llm, time.perf_counter()), files)
    kind.extend(record, instance, graded, ctx.writer.run_dir)
    # the viewer's plots: the executions are dropped once the record exists
    traces = await offload(evaluator.grading, save_traces, ctx.writer.run_dir, instance.key, graded.candidate,
                           graded.reference)
    if traces is not None:
        record["files"]["traces"] = traces
    if agent is not None:
        record["agent"] = agent_block(agent, first)
        if "design" in first_facts:  # a design task: what the first program's values gave
            record["agent"]["first_design"] = first_facts["design"]
    if repair:
        record["repair"] = {**instance.draft.to_json(), "tools": settings.repair_tools,
                            "repaired": graded.verdict.overall}
    return record


def _times(t0: float, t_llm: float, t_end: float | None = None) -> dict[str, float]:
    end = t_llm if t_end is None else t_end
    return {"llm_s": t_llm - t0, "evaluation_s": end - t_llm, "total_s": end - t0}


async def run_assembly(instance: TaskInstance, ctx: FlowContext) -> list[dict[str, Any]]:
    """Level 3b: every part's flow first; the assembly's own flow only when all passed, and then
    both its program and the ground truth load the LLM-made parts. A part lost to the server makes
    the assembly lost too (not a model failure; ``--resume`` does both again).

    Returns the part records followed by the assembly's record.
    """
    t0 = time.perf_counter()
    # a part the assembly uses twice (two identical bearing blocks) is generated once and loaded twice
    unique = {part.key: part for _, part in instance.parts}
    part_records = list(await asyncio.gather(*(run_flow(part, part_kind(part, ctx), ctx) for part in unique.values())))
    by_key = dict(zip(unique, part_records, strict=True))
    part_keys = {slot: part.key for slot, part in instance.parts}
    part_timing = {"parts_llm_s": sum(r["timing"]["llm_s"] for r in part_records),
                   "parts_evaluation_s": sum(r["timing"]["evaluation_s"] for r in part_records),
                   "parts_wall_s": time.perf_counter() - t0}
    lost = [r for r in part_records if r["first_failure"] == "infrastructure"]
    if lost:
        reasons = "; ".join(f"part {r['slug']}: {r['infrastructure_error']}" for r in lost)
        record = lost_record(instance, reasons, {"llm_s": 0.0, "evaluation_s": 0.0,
                                                 "total_s": part_timing["parts_wall_s"], **part_timing})
        record["parts"] = part_keys
        return [*part_records, record]
    passed = sum(1 for r in part_records if r["overall"])
    parts_stage = StageResult("parts_overall", passed == len(part_records),
                              f"{passed} of {len(part_records)} parts passed")
    if not parts_stage.passed:
        stages = (parts_stage, StageResult("mbs_started", False, "not started: a part failed"),
                  *(StageResult(name, None, "not started") for name in RIGID_STAGES))
        return [*part_records, not_started_record(instance, Verdict(stages), part_keys, part_timing)]
    files = {f"{slot}.npz": ctx.writer.run_dir / by_key[part.key]["files"]["part"] for slot, part in instance.parts}
    kind = AssemblyKind(ctx.evaluator, files, (parts_stage, StageResult("mbs_started", True, "all parts passed")),
                        part_keys, part_timing)
    return [*part_records, await run_flow(instance, kind, ctx)]


def part_kind(instance: TaskInstance, ctx: FlowContext) -> PartKind:
    return PartKind(ctx.evaluator, keep_at=ctx.writer.part_path(instance))


async def run_instance(instance: TaskInstance, ctx: FlowContext) -> list[dict[str, Any]]:
    """The records one task instance produces (an assembly: its parts' and its own)."""
    if instance.kind == "assembly":
        return await run_assembly(instance, ctx)
    keep_at = ctx.writer.part_path(instance) if instance.kind == "part" else None
    return [await run_flow(instance, single_kind(instance, ctx.evaluator, keep_at), ctx)]
