"""Behaviour's converged runs (``eval/convergence.py``): the step count R a task instance is compared
at, found once from the ground truth and kept with it, and the candidate's run at R x the steps.

The ground truth runs at 1, 2, 4, ... x its steps until its self-error at R against 2R no longer
widens a tolerance, at most ``CONVERGE_CAP``; the nominal run and the one with twice the steps are
the runs behaviour always had (a task model whose floor does not bind stops there: R = 1, nothing
more is run, for the ground truth or the candidate). Each run is one more ground-truth execution,
kept in the reference store as its motion alone (``slim``: the trajectory of 32,000 steps would be
tens of MB and nobody reads it) under a key of its own, and R itself is stored as a small fact
beside them, so a later run loads the two executions it compares with and nothing else. The
candidate runs again at R x the steps only when R > 1 and its own run finished; where that second
run fails (a timeout at 16 x the steps), behaviour compares at the nominal steps with today's
floor and the record says so.
"""

from __future__ import annotations

import asyncio
import dataclasses
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from typing import Any

from meceng.eval.behaviour import STEP_MARGIN, BehaviourTolerance
from meceng.eval.convergence import (
    CONVERGE_CAP,
    CONVERGED,
    PROGRESS,
    STEP_BUDGET,
    ConvergedRuns,
    Convergence,
    StepCheck,
    largest_factor,
    settled,
    stalled,
    step_check,
)
from meceng.tasks.base import TaskInstance
from meceng.tools.execution import Execution

#: The store's variant of a slim converged run (motion only) and of the fact that holds R.
SLIM = "motion-only"
#: Runs a ground truth (or a candidate) at this many times the instance's steps.
RunAt = Callable[[int], Awaitable[Execution]]


def at_steps(instance: TaskInstance, factor: int) -> TaskInstance:
    """The instance with its simulation block's numberOfSteps times ``factor`` (nothing else changes)."""
    return dataclasses.replace(instance, sim=dataclasses.replace(instance.sim, steps=factor * instance.sim.steps))


def slim(execution: Execution) -> Execution:
    """What behaviour reads of a converged run: its outcome and motion (no items, no trajectory)."""
    return Execution(stage=execution.stage, error=execution.error, error_kind=execution.error_kind,
                     error_line=execution.error_line, warnings=execution.warnings, returncode=execution.returncode,
                     wall_time=execution.wall_time, solve_time=execution.solve_time, motion=execution.motion)


def fact_variant(tolerance: BehaviourTolerance) -> str:
    """The store variant R is kept under: every setting that decides it."""
    return (f"convergence:cap={CONVERGE_CAP}:budget={STEP_BUDGET}:converged={CONVERGED}:progress={PROGRESS}:"
            f"margin={STEP_MARGIN}:relative={tolerance.relative}:horizon={tolerance.horizon}")


@dataclass(frozen=True)
class ConvergedTruth:
    """The ground truth's side: at R x the steps, at 2R, and the nominal pair behind today's floor."""

    convergence: Convergence
    truth: Execution  # at R
    finer: Execution  # at 2R
    nominal: Execution  # at the instance's steps
    floor: Execution  # at twice them (the step error of the nominal run)
    complete: bool = True  # every run needed to find R ran (else R is not stored: found again next time)


async def find_convergence(run_at: RunAt, nominal_steps: int, tolerance: BehaviourTolerance,
                           cap: int = CONVERGE_CAP) -> ConvergedTruth:
    """Double R from 1 until the ground truth at R and 2R agree within the base tolerance
    (``eval/convergence.settled``) or R reaches the cost bound (``largest_factor``); a doubling that
    does not cut the self-error by ``PROGRESS`` ends it at the R before (``stalled``). A run that
    fails ends the search at the last R whose pair ran (R = 1 with no finer run: no floor, as before).
    ``cap``: the most R may be, below ``CONVERGE_CAP`` for an assembly (``ASSEMBLY_CAP``)."""
    cap = largest_factor(nominal_steps, cap)
    runs: dict[int, asyncio.Future[Execution]] = {}

    def start(factor: int) -> asyncio.Future[Execution]:
        if factor not in runs:
            runs[factor] = asyncio.ensure_future(run_at(factor))
        return runs[factor]

    start(1)
    start(2)
    checks: list[StepCheck] = []
    factor, complete, note = 1, True, ""
    try:
        while True:
            coarse, fine = await start(factor), await start(2 * factor)
            check = step_check(coarse.motion, fine.motion, factor, tolerance)
            if check is None:  # a run failed: the last pair that ran
                complete = False
                factor = max(1, factor // 2)
                break
            checks.append(check)
            if settled(check):
                break
            if stalled(checks):
                factor //= 2
                note = (f"more steps do not resolve it: the self-error is {checks[-2].ratio:.3g} at R = {factor} and "
                        f"{check.ratio:.3g} at R = {2 * factor}; compared at R = {factor} with its floor")
                break
            if factor >= cap:
                break
            factor *= 2
    finally:
        for future in runs.values():
            if not future.done():
                future.cancel()
    if not complete:
        note = "a ground-truth run with more steps failed: R is the last that ran"
    done = bool(checks) and settled(checks[-1]) and checks[-1].factor == factor and complete
    convergence = Convergence(factor, nominal_steps, done, tuple(checks), cap, note)
    return ConvergedTruth(convergence, runs[factor].result(), runs[2 * factor].result(), runs[1].result(),
                          runs[2].result(), complete)


async def from_fact(run_at: RunAt, fact: dict[str, Any], nominal_steps: int) -> ConvergedTruth:
    """The ground truth's side from a stored R: the runs at R and 2R (and the nominal pair)."""
    factor = int(fact["factor"])
    checks = tuple(StepCheck(int(c["factor"]), float(c["ratio"]), str(c["quantity"])) for c in fact.get("checks", []))
    cap = int(fact.get("cap", CONVERGE_CAP))
    convergence = Convergence(factor, nominal_steps, bool(fact["converged"]), checks, cap, str(fact.get("note", "")))
    factors = sorted({1, 2, factor, 2 * factor})
    found = dict(zip(factors, await asyncio.gather(*(run_at(f) for f in factors)), strict=True))
    return ConvergedTruth(convergence, found[factor], found[2 * factor], found[1], found[2])


async def candidate_runs(run_candidate: RunAt, candidate: Execution, truth: ConvergedTruth) -> ConvergedRuns:
    """The motions behaviour compares: at R = 1 the graded runs themselves; at R > 1 the candidate
    once more at R x the steps (only when its own run finished: one that did not fails behaviour
    as it ran). A failed run at R falls back to the nominal steps with the ground truth's floor."""
    convergence = truth.convergence
    if convergence.factor == 1:
        return ConvergedRuns(convergence, candidate.motion, truth.truth.motion, truth.finer.motion)
    if not candidate.solved:
        said = dataclasses.replace(convergence, note=_and(convergence.note,
                                                           "the candidate's run did not finish: compared as it ran"))
        return ConvergedRuns(said, candidate.motion, truth.truth.motion, truth.finer.motion)
    again = await run_candidate(convergence.factor)
    if again.solved and again.motion is not None:
        return ConvergedRuns(convergence, again.motion, truth.truth.motion, truth.finer.motion)
    why = f"{again.error_kind or again.stage}: {(again.error or '')[:200]}"
    fallback = dataclasses.replace(
        convergence, factor=1, converged=False,
        note=_and(convergence.note, f"the candidate's run at {convergence.factor} x the steps failed ({why}): "
                                    "compared at the nominal steps, tolerances widened by the ground truth's step "
                                    "error there"))
    return ConvergedRuns(fallback, candidate.motion, truth.nominal.motion, truth.floor.motion)


def _and(*notes: str) -> str:
    """Notes that all hold, in order (an empty one left out)."""
    return "; ".join(n for n in notes if n)
