"""The ``compare`` tool: do two programs of the model's own move alike?

No ground truth anywhere: both programs run in the sandbox with the description's end time and
steps and their bodies' motion recorded (``tools/recording.py``), and are compared with the
behaviour comparison made symmetric (``eval/agreement.py``: the smaller of the two motions' scales,
0.1 % of it). Only when they part are both run again with twice the steps, so that a difference
within either program's own step error is not called a parting (a finer run can only widen a
tolerance: two programs that agree need no second run). The answer is in the inspector's words:
its body labels (``#3 RigidBody 'arm'``), numbers at four digits, global frame, SI units.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable

import numpy as np

from meceng.agents.sources import scale_words
from meceng.eval.agreement import Agreement, compare_motions
from meceng.eval.behaviour import Deviation
from meceng.eval.bodies import read_bodies
from meceng.inspect.view import build_view
from meceng.inspect.words import num, vec
from meceng.tools.execution import Execution

#: Runs one program with its motion recorded; ``True``: with twice the steps (its own step error).
Recorder = Callable[[str, bool], Awaitable[Execution]]

#: Matched pairs listed one a line; the rest are counted.
PAIR_LINES = 12

_UNITS = {"position": "m", "velocity": "m/s", "angular_velocity": "rad/s", "axis": "rad", "deformation": "m"}
_QUANTITIES = {"position": "centre-of-mass position", "velocity": "centre-of-mass velocity",
               "angular_velocity": "angular velocity", "axis": "principal-axis direction",
               "deformation": "interface-point position (deformation)"}
NOTE = ("(agreement is evidence, not proof: a mistake both programs share does not show; a parting shows that "
        "at least one of them differs from the other)")


async def compare_programs(record: Recorder, code_a: str, code_b: str, trim: Callable[[str | None], str | None]
                           ) -> str:
    """Run both programs, compare their motions and answer in words."""
    a, b = await asyncio.gather(record(code_a, False), record(code_b, False))
    agreement = compare_motions(a.motion, b.motion)
    refined = False
    if agreement.agree is False and a.solved and b.solved and agreement.ends[0] == agreement.ends[1]:
        finer_a, finer_b = await asyncio.gather(record(code_a, True), record(code_b, True))
        agreement = compare_motions(a.motion, b.motion, finer_a=finer_a.motion, finer_b=finer_b.motion)
        refined = True
    return compare_words(agreement, a, b, trim, refined)


class _Names:
    """Both programs' bodies as the inspector names them, with mass and start."""

    def __init__(self, side: str, run: Execution) -> None:
        self.side = side
        self.view = build_view(run.items, run.system, None) if run.items is not None else None
        self.bodies = {m.index: m for m in read_bodies(run.motion) or []}

    def label(self, index: int) -> str:
        body = self.view.body(index) if self.view is not None else None
        motion = self.bodies.get(index)
        name = body.label if body is not None else f"#{index}" + (f" {motion.kind}" if motion else "")
        return f"{self.side}'s {name}"

    def full(self, index: int) -> str:
        motion = self.bodies.get(index)
        if motion is None or not len(motion.t):
            return self.label(index)
        return f"{self.label(index)} (mass {num(motion.mass)}, starts at {vec(motion.p[0])})"

    def state(self, index: int, t: float, quantity: str) -> str:
        """Where the body is at ``t``, and the quantity that parted where it is not the position."""
        motion = self.bodies.get(index)
        if motion is None or not len(motion.t):
            return f"{self.label(index)}: no state"
        k = int(np.argmin(np.abs(motion.t - t)))
        text = f"{self.label(index)} at {vec(motion.p[k])}"
        if quantity == "velocity":
            text += f" with velocity {vec(motion.v[k])}"
        elif quantity == "angular_velocity" and motion.w is not None:
            text += f" with angular velocity {vec(motion.w[k])}"
        return text


def _deviation(d: Deviation, names: tuple[_Names, _Names]) -> str:
    unit = _UNITS.get(d.quantity, "")
    return (f"{_QUANTITIES.get(d.quantity, d.quantity)} of {names[0].label(d.body)} and "
            f"{names[1].label(d.candidate_body)}: {num(d.value)} {unit} apart, tolerance {num(d.tolerance)} {unit}")


def _unlike(names: tuple[_Names, _Names], a: int, b: int) -> str:
    """A matched pair whose mass or principal moments differ by more than 0.1 % says so: a body can
    move alike with another mass (a free fall), and the model should still see it."""
    x, y = names[0].bodies.get(a), names[1].bodies.get(b)
    if x is None or y is None:
        return ""
    said = []
    if abs(x.mass - y.mass) > 1e-3 * max(abs(x.mass), abs(y.mass)):
        said.append("masses")
    if (x.principal is None) != (y.principal is None) or (
            x.principal is not None and y.principal is not None and (x.principal.shape != y.principal.shape or np.any(
                np.abs(x.principal - y.principal) > 1e-3 * max(float(np.max(np.abs(x.principal))), 1e-300)))):
        said.append("inertias")
    return f" — {' and '.join(said)} differ" if said else ""


def _failures(a: Execution, b: Execution, trim: Callable[[str | None], str | None]) -> list[str]:
    """A program that stopped with an error, in the words ``simulate`` uses (stage; error)."""
    return [f"program {side}: stage: {run.stage}; error: {trim(run.error)}"
            for side, run in (("A", a), ("B", b)) if run.error]


def compare_words(agreement: Agreement, a: Execution, b: Execution,
                  trim: Callable[[str | None], str | None], refined: bool = False) -> str:
    """The answer a model reads: the verdict first, then the matched bodies, the largest deviation
    and the tolerances."""
    failures = _failures(a, b, trim)
    if agreement.agree is None or agreement.verdict is None:
        missing = [side for side, run in (("A", a), ("B", b)) if run.motion is None]
        head = ("compare: not compared: " + " and ".join(f"program {s}" for s in missing)
                + " did not run to its solve" if missing else "compare: " + agreement.detail)
        return "\n".join([head, *failures])
    names = (_Names("A", a), _Names("B", b))
    verdict = agreement.verdict
    lines = [_head(agreement, names), *failures]
    first = verdict.first_divergence
    if first is not None:
        lines.append(f"  then: {names[0].state(first.body, first.time, first.quantity)}; "
                     f"{names[1].state(first.candidate_body, first.time, first.quantity)}")
    lines.append(f"bodies matched by mass, inertia and motion ({len(agreement.pairs)} pairs, A ↔ B):")
    pairs = [f"  {names[0].full(x)} ↔ {names[1].full(y)}{_unlike(names, x, y)}" for x, y in agreement.pairs]
    lines += pairs[:PAIR_LINES]
    if len(pairs) > PAIR_LINES:
        lines.append(f"  … {len(pairs) - PAIR_LINES} more pairs")
    lines += [f"  unmatched: {names[0].full(x)}" for x in agreement.unmatched_a[:PAIR_LINES]]
    lines += [f"  unmatched: {names[1].full(y)}" for y in agreement.unmatched_b[:PAIR_LINES]]
    largest = verdict.largest
    if largest is not None:
        lines.append(f"largest deviation: {_deviation(largest, names)} ({num(largest.ratio)} of it) at "
                     f"t = {num(largest.time)} s")
    lines.append(_tolerances(agreement, names, refined))
    lines.append(NOTE)
    return "\n".join(lines)


def _head(agreement: Agreement, names: tuple[_Names, _Names]) -> str:
    verdict = agreement.verdict
    assert verdict is not None
    ends = agreement.ends
    first = verdict.first_divergence
    if agreement.agree:
        samples = len(next(iter(names[0].bodies.values())).t) if names[0].bodies else 0
        return (f"compare: A and B move alike up to t = {num(verdict.compared_until or 0.0)} s (every matched body "
                f"within its tolerance at all {samples} sampled times)")
    short = (f"A's motion ends at t = {num(ends[0] or 0.0)} s, B's at t = {num(ends[1] or 0.0)} s"
             if ends[0] != ends[1] else "")
    if len(names[0].bodies) != len(names[1].bodies):
        return (f"compare: A and B differ: A has {len(names[0].bodies)} moving bodies, B has "
                f"{len(names[1].bodies)}" + (f"; {short}" if short else ""))
    if first is None:
        until = f"; up to t = {num(min(e or 0.0 for e in ends))} s they move alike" if short else ""
        return f"compare: A and B differ: {short or agreement.detail}{until}"
    parted = f"part at t = {num(first.time)} s: {_deviation(first, names)}"
    return (f"compare: A and B differ: {short}; over the time both ran, they {parted}" if short
            else f"compare: A and B {parted}")


def _tolerances(agreement: Agreement, names: tuple[_Names, _Names], refined: bool) -> str:
    scale, verdict = agreement.scales, agreement.verdict
    if scale is None or verdict is None:
        return ""
    sides = {"A": list(names[0].bodies.values()), "B": list(names[1].bodies.values())}
    text = (f"tolerances, {num(100 * verdict.relative)} % of the smaller of the two motions' scales: "
            + scale_words(verdict.relative, scale, sides, lambda side, index: names[side == "B"].label(index)))
    if refined:
        widened = "; ".join(verdict.widened) or "none"
        text += f"; both run again with twice the steps: widened by a program's own step error: {widened}"
    return text
