"""Converged comparisons: the behaviour verdict at a step count where the ground truth's own time
stepping no longer decides it.

A tolerance is never less than ``STEP_MARGIN`` x what the ground truth's step error moves a quantity
by (``eval/behaviour._step_allowances``): a program built another way has a step error of its own.
Where that floor binds, it lets real physics through (the Pratt truss at its 2000 steps: the step
error widens the velocity tolerance 500x, and doubled damping passes). So there, behaviour compares
at ``R`` x the steps on both sides: the ground truth and the candidate run with the simulation
block's ``numberOfSteps`` times R (the harness sets it where the program calls the solver; nothing
else of the candidate changes), R found per instance by doubling until the ground truth's self-error
at R against 2R is within the base tolerance (``CONVERGED``), at most ``CONVERGE_CAP`` and R x the steps
at most ``STEP_BUDGET`` (the cost bound: ``largest_factor``), and only while a doubling cuts that
self-error by ``PROGRESS`` (where it does not, the steps are not what decides it). A task model
whose floor does not bind at its own steps keeps R = 1 and pays nothing more than before (its
nominal run and the one with twice the steps). One that still binds at the bound is compared at the
largest R the bound allows, with the floor kept there (the step error at R = 16 is 1/256 of the
nominal one for a second-order integrator), and its record says it did not converge.

The paper's verdict never sees these runs: they are extra executions for behaviour only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from meceng.eval.behaviour import STEP_MARGIN, BehaviourTolerance, _pair_errors
from meceng.eval.bodies import read_bodies, scales

#: The largest step-count multiplier behaviour compares at: the ground truth then runs at up to
#: 2 x 16 x its steps once per instance (cached in the reference store), a candidate at 16 x.
CONVERGE_CAP = 16
#: And the most steps a candidate's converged run may take (R x steps): the cost bound of the 2,000-step
#: task models is R = 16 (the Pratt truss: 1.2 s a program), of the 4,000-step grid mesh with its
#: contacts R = 8 (9 s a program; at R = 16 it would be 18 s), of a 10,000-step model R = 2.
STEP_BUDGET = 32_000
#: An assembly's ground truth runs with the model's own parts, again for every task (no store can
#: keep it): its search stops at R = 4 (the flexible table's reaches R = 16 at 500 steps, 70 s of
#: ground-truth runs a task against 4 s for the nominal pair; at R = 4 it is 18 s).
ASSEMBLY_CAP = 4
#: The ground truth counts as converged at R when ``STEP_MARGIN`` x its difference to 2R is at most
#: this fraction of the base tolerance, for every body and quantity: the floor no longer binds.
CONVERGED = 1.0
#: Doubling goes on only while it cuts the self-error at least this much (a second-order integrator:
#: 4x, the trusses 3-4x); where it does not, the time step is not what decides the difference (the
#: door hinge's and the rotor's assemblies: 2500 -> 3300 -> 3500; the grid mesh's contacts at seed 0:
#: 11 -> 5.2 -> 5.3), and the R before is kept with its floor, at half the cost.
PROGRESS = 1.5


@dataclass(frozen=True)
class StepCheck:
    """The ground truth at ``factor`` x the steps against twice that: its largest step error."""

    factor: int
    ratio: float  # STEP_MARGIN x the largest difference, over that quantity's base tolerance
    quantity: str  # "velocity of body 3"; "" when nothing moves

    def to_json(self) -> dict[str, Any]:
        return {"factor": self.factor, "ratio": float(f"{self.ratio:.4g}"), "quantity": self.quantity}


@dataclass(frozen=True)
class Convergence:
    """Which step count behaviour compares at, and why (the behaviour record's ``steps`` block)."""

    factor: int  # R: behaviour's runs have R x the nominal steps (1: the graded runs themselves)
    nominal: int  # the simulation block's steps
    converged: bool  # the ground truth's floor does not bind at R (False: it still widens some tolerance)
    checks: tuple[StepCheck, ...] = ()
    cap: int = CONVERGE_CAP  # the largest R the cost bound allowed (``largest_factor``)
    note: str = ""  # why the comparison is not at R (the candidate's run at R failed, ...)

    @property
    def steps(self) -> int:
        return self.factor * self.nominal

    def to_json(self) -> dict[str, Any]:
        return {"factor": self.factor, "steps": self.steps, "nominal_steps": self.nominal,
                "converged": self.converged, "cap": self.cap, "checks": [c.to_json() for c in self.checks],
                **({"note": self.note} if self.note else {})}


def step_check(coarse: dict[str, Any] | None, fine: dict[str, Any] | None, factor: int,
               tolerance: BehaviourTolerance | None = None) -> StepCheck | None:
    """How far the ground truth at ``factor`` x the steps (``coarse``) moves from itself at twice
    them (``fine``), as ``STEP_MARGIN`` x the largest difference over each quantity's base tolerance
    (the coarse run's scales), up to the task model's horizon; None when either has no motion or a
    body is missing (a run that failed)."""
    tol = tolerance or BehaviourTolerance()
    bodies, finer = read_bodies(coarse), read_bodies(fine)
    if bodies is None or finer is None:
        return None
    if not bodies or not len(bodies[0].t):
        return StepCheck(factor, 0.0, "")
    times = bodies[0].t
    limit = float(times[-1])
    if tol.horizon is not None:
        limit = float(times[0]) + tol.horizon * (limit - float(times[0]))
    n = int(np.searchsorted(times, limit + 1e-12, side="right"))
    by_index = {b.index: b for b in finer}
    scale = scales(bodies)
    worst = StepCheck(factor, 0.0, "")
    for body in bodies:
        other = by_index.get(body.index)
        if other is None or len(other.t) < n:
            return None
        for quantity, values, allowed in _pair_errors(other, body, n, scale, tol.relative):
            ratio = STEP_MARGIN * float(np.max(values)) / allowed if allowed > 0 else float("inf")
            if not np.isfinite(ratio):
                ratio = float("inf")
            if ratio > worst.ratio:
                worst = StepCheck(factor, ratio, f"{quantity} of body {body.index}")
    return worst


def largest_factor(nominal_steps: int, cap: int = CONVERGE_CAP, budget: int = STEP_BUDGET) -> int:
    """The largest R tried for a simulation of ``nominal_steps``: a power of two, at most ``cap``, whose
    R x steps stay within ``budget`` (1 when even twice the steps would not)."""
    factor = 1
    while 2 * factor <= cap and 2 * factor * nominal_steps <= budget:
        factor *= 2
    return factor


def stalled(checks: tuple[StepCheck, ...] | list[StepCheck]) -> bool:
    """True when the last doubling did not cut the self-error by ``PROGRESS``."""
    return len(checks) >= 2 and checks[-1].ratio * PROGRESS > checks[-2].ratio


def settled(check: StepCheck | None) -> bool:
    """True when the ground truth's step error at the check's R no longer widens any tolerance."""
    return check is not None and check.ratio <= CONVERGED


@dataclass(frozen=True)
class ConvergedRuns:
    """The motions behaviour compares when R > 1 (``eval/chain.evaluate_rigid``'s ``converged``):
    the candidate's and the ground truth's at R x the steps and the ground truth's at 2R (its own
    step error there, which widens a tolerance only where ``convergence.converged`` is False)."""

    convergence: Convergence
    candidate: dict[str, Any] | None
    truth: dict[str, Any] | None
    finer: dict[str, Any] | None
