"""Do two programs move alike? The behaviour comparison with no ground truth on either side.

Outside a benchmark there is no reference to grade against; what can be checked is whether two
programs written for the same system, independently or in two different ways (joints against
constraints, another reference frame), move alike. This is the behaviour verdict's comparison
(``eval/behaviour.compare_bodies``: bodies matched by their physics, centres of mass, velocities,
angular velocities and principal axes compared at the same sample times) made symmetric:

- **Scales.** Every tolerance is ``relative`` (0.1 %, the behaviour verdict's) of a scale of the
  motion; without a ground truth the scale is the *smaller* of the two programs' (per quantity:
  size, travel, speed). For two programs that agree the two scales are the same to within that
  very tolerance, so the choice does not decide an agreement; where they part, the smaller keeps
  a program that flies away or turns NaN from widening the test of the other, and finds the
  first divergence earliest. The tolerances are the same with A and B swapped (scales and step
  errors are taken from both); what stays A's is the sample times reported and which principal
  axes are compared (A's distinct ones: a body symmetric in A has no axis to compare).
- **Step error.** The behaviour verdict allows 3 x the ground truth's own step error (the same
  program with twice the steps). Here each side may have its own, the larger counts per matched
  quantity; the caller passes the finer runs (``finer_a``, ``finer_b``) or not. A finer run can
  only widen a tolerance, so two programs that agree without it agree with it: the agent's
  ``compare`` runs the finer pair only when the first comparison parts.
- **Length.** A program that stopped early (a solver failure) is compared over the time both ran
  and does not agree; the answer says where each one ended.

``compare_motions`` is a pure function of two motion records (``Execution.motion``, recorded with
``tools/recording.run_recorded`` on the same grid); the consensus of K programs groups by it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from meceng.eval.behaviour import BehaviourTolerance, BehaviourVerdict, Words, compare_bodies
from meceng.eval.bodies import BodyMotion, Scales, read_bodies, scales

#: How the verdict's text names the two programs: A in the ground truth's place, B in the candidate's.
AB = Words(candidate="B", truth="A", short="B")


@dataclass(frozen=True)
class Agreement:
    """Whether two programs' motions agree, and the comparison behind it.

    In ``verdict`` program A stands where the ground truth stands in the behaviour verdict and B where
    the candidate does: ``Deviation.body`` is A's object number, ``Deviation.candidate_body`` B's, and
    ``matching`` holds (B's object, A's object) pairs."""

    agree: bool | None  # None: not compared (a program has no motion record: it never reached its solve)
    detail: str
    verdict: BehaviourVerdict | None = None
    scales: Scales | None = None
    unmatched_a: tuple[int, ...] = ()  # object numbers of A's bodies that have no partner in B
    unmatched_b: tuple[int, ...] = ()
    ends: tuple[float | None, float | None] = (None, None)  # the last recorded time of A and of B

    @property
    def pairs(self) -> tuple[tuple[int, int], ...]:
        """(A's object, B's object) of every matched pair, in A's order."""
        return tuple(sorted((a, b) for b, a in self.verdict.matching)) if self.verdict else ()

    def to_json(self) -> dict[str, Any]:
        return {"agree": self.agree, "detail": self.detail,
                "verdict": self.verdict.to_json() if self.verdict else None,
                "scales": self.scales.to_json() if self.scales else None,
                "pairs": [{"a": a, "b": b} for a, b in self.pairs],
                "unmatched_a": list(self.unmatched_a), "unmatched_b": list(self.unmatched_b),
                "ends": list(self.ends)}


def joint_scales(a: Scales, b: Scales) -> Scales:
    """The smaller of two programs' scales, field by field (a non-finite one does not count)."""

    def smaller(x: float, y: float) -> float:
        finite = [v for v in (x, y) if np.isfinite(v) and v > 0]
        return min(finite) if finite else 1.0

    return Scales(smaller(a.length, b.length), smaller(a.speed, b.speed), smaller(a.duration, b.duration),
                  smaller(a.travel, b.travel), smaller(a.turning, b.turning))


def _head(bodies: list[BodyMotion], n: int) -> list[BodyMotion]:
    """The bodies' first n samples."""

    def cut(x: np.ndarray | None) -> np.ndarray | None:
        return None if x is None else x[:n]

    return [replace(b, t=b.t[:n], p=b.p[:n], v=b.v[:n], w=cut(b.w), rotation=cut(b.rotation), points=cut(b.points))
            for b in bodies]


def finite_head(bodies: list[BodyMotion]) -> list[BodyMotion]:
    """The bodies' samples up to the first non-finite state of any of them (a program that blew up):
    what the scales are taken from."""
    n = min((len(b.t) for b in bodies), default=0)
    for b in bodies:
        bad = ~np.all(np.isfinite(b.p[:n]) & np.isfinite(b.v[:n]), axis=1)
        if b.w is not None:
            bad |= ~np.all(np.isfinite(b.w[:n]), axis=1)
        if bad.any():
            n = min(n, int(np.argmax(bad)))
    return _head(bodies, max(n, 1))


def _finite_scales(bodies: list[BodyMotion]) -> Scales:
    return scales(finite_head(bodies))


def _end(bodies: list[BodyMotion]) -> float | None:
    return float(bodies[0].t[-1]) if bodies and len(bodies[0].t) else None


def compare_motions(motion_a: dict[str, Any] | None, motion_b: dict[str, Any] | None,
                    tolerance: BehaviourTolerance | None = None, finer_a: dict[str, Any] | None = None,
                    finer_b: dict[str, Any] | None = None) -> Agreement:
    """Whether programs A and B move alike (see the module's text for the tolerances); ``finer_*``:
    the same program's motion with ``tools/recording.REFINE`` times the steps, or None."""
    tol = tolerance or BehaviourTolerance()
    a, b = read_bodies(motion_a), read_bodies(motion_b)
    missing = [name for name, bodies in (("A", a), ("B", b)) if bodies is None]
    if a is None or b is None:
        return Agreement(None, f"not compared: no motion of {' and '.join(missing)} (never reached its solve)")
    empty = [name for name, bodies in (("A", a), ("B", b)) if bodies and not len(bodies[0].t)]
    if empty:  # the recorder gave up before its first sample (a warning of the run)
        return Agreement(None, f"not compared: no motion sample of {' and '.join(empty)}")
    ends = (_end(a), _end(b))
    if not a and not b:
        return Agreement(True, "neither program has a moving body", ends=ends)
    scale = joint_scales(_finite_scales(a) if a else scales(b), _finite_scales(b) if b else scales(a))
    n = min((len(x[0].t) for x in (a, b) if x), default=0)
    short = bool(a and b) and len(a[0].t) != len(b[0].t)
    if short:
        a, b = _head(a, n), _head(b, n)
    verdict = compare_bodies(b, a, scale, tol, refined_truths=read_bodies(finer_a),
                             refined_candidates=read_bodies(finer_b), words=AB)
    paired_b = {c for c, _ in verdict.matching}
    paired_a = {g for _, g in verdict.matching}
    unmatched_a = tuple(x.index for x in a if x.index not in paired_a)
    unmatched_b = tuple(x.index for x in b if x.index not in paired_b)
    agree = bool(verdict.passed) and not short
    detail = verdict.detail
    if short:
        detail = (f"A's motion ends at t = {ends[0]:.4g} s, B's at t = {ends[1]:.4g} s; over the time both ran: "
                  + detail)
    return Agreement(agree, detail, verdict, scale, unmatched_a, unmatched_b, ends)
