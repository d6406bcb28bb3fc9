"""Level 4: the design task's scorer (issue 42), a task kind like the rigid one.

The program's ``DESIGN`` is read statically and its solver calls counted before anything runs;
then the candidate runs as any level 1-2 program, and the reference is built with the candidate's
values (run once per distinct design, through the reference store when there is one, and again
with more steps for behaviour). The spec's quantity is measured on that reference; the candidate
must move like it. Stages: design_declared, one_simulation, the open text's chain (finished
assemble, solver success; the writing stages not required), design_met, behaviour_match.
"""

from __future__ import annotations

import asyncio
import dataclasses

import numpy as np

from meceng.eval.behaviour import tolerance_for
from meceng.eval.chain import BEHAVIOUR_STAGE, RIGID_STAGES, StageResult, Verdict, by_behaviour, evaluate_rigid
from meceng.eval.design import DESIGN_DECLARED, DESIGN_MET, ONE_SIMULATION, count_simulations, judge_design, read_design
from meceng.tasks.base import TaskInstance
from meceng.tasks.design_base import DesignTask
from meceng.tools.execution import Execution

from .evaluation import Evaluator, not_run
from .graded import Graded
from .grading import offload


def _stopped(stages: list[StageResult], why: str) -> Verdict:
    """A verdict whose later stages did not run (``passed=None``)."""
    later = [ONE_SIMULATION, *RIGID_STAGES[1:], DESIGN_MET, BEHAVIOUR_STAGE]
    done = {s.name for s in stages}
    return Verdict((*stages, *(StageResult(n, None, f"not started: {why}") for n in later if n not in done)),
                   graded_by="behaviour")


async def grade_design(evaluator: Evaluator, instance: TaskInstance, code: str | None,
                       selected: tuple[str, ...] | None, code_error: str | None) -> Graded:
    task: DesignTask = instance.design
    ranges = {v.name: (v.low, v.high) for v in task.variables}
    nothing = Execution(stage="not_run")
    outcome = judge_design(None, task.target, task.tolerance, None, task.spec.quantity, task.spec.unit)
    if code is None:
        verdict = _stopped([StageResult(DESIGN_DECLARED, False, code_error or "no program")], "no program")
        return Graded(verdict, not_run(code_error), nothing, {"design": outcome.to_json()})
    declared = read_design(code, ranges)
    if declared.values is None:
        verdict = _stopped([StageResult(DESIGN_DECLARED, False, declared.error or "")], "no valid DESIGN")
        return Graded(verdict, nothing, nothing, {"design": outcome.to_json()})
    values = declared.values
    stages = [StageResult(DESIGN_DECLARED, True, f"DESIGN = {values} (line {declared.line})")]
    simulations = count_simulations(code)
    if simulations.error is not None:
        stages.append(StageResult(ONE_SIMULATION, False, simulations.error))
        return Graded(_stopped(stages, "not exactly one simulation"), nothing, nothing,
                      {"design": dataclasses.replace(outcome, values=values).to_json()})
    stages.append(StageResult(ONE_SIMULATION, True, f"one solver call (line {simulations.lines[0]})"))

    program = task.program(values)
    tolerance = tolerance_for(task.system)
    reference_task = asyncio.ensure_future(evaluator.ground_truth(instance, program))
    # behaviour at the step count where the reference's own step error no longer decides (issue 43)
    truth_task = asyncio.ensure_future(
        evaluator.convergence(instance, program, lambda: asyncio.shield(reference_task), tolerance))
    candidate = await evaluator.execute(code, instance, check=True)
    reference = await reference_task
    converged = await evaluator.converged_runs(code, instance, candidate, await truth_task)
    chain = await offload(
        evaluator.grading, evaluate_rigid, candidate, reference, end_time=instance.sim.end_time,
        steps=instance.sim.steps, selected=selected, required=instance.required_components,
        dependencies=evaluator.catalog.dependency_map(), tolerances=evaluator.tolerances,
        behaviour=tolerance, converged=converged)
    open_verdict = by_behaviour(chain)
    value = None
    if reference.times is not None and reference.trajectory is not None and reference.solved:
        value = task.measure(np.asarray(reference.times), np.asarray(reference.trajectory), values)
    outcome = judge_design(value, task.target, task.tolerance, values, task.spec.quantity, task.spec.unit)
    chain_stages = list(open_verdict.stages)
    at = next((i for i, s in enumerate(chain_stages) if s.name == BEHAVIOUR_STAGE), len(chain_stages))
    met = StageResult(DESIGN_MET, outcome.passed if reference.solved else None, outcome.detail)
    chain_stages.insert(at, met)
    verdict = dataclasses.replace(open_verdict, stages=(*stages, *chain_stages))
    return Graded(verdict, candidate, reference, {"design": outcome.to_json()})
