"""The behaviour verdict: does the candidate's system move as the ground truth's does?

Beside the paper's verdict, never instead of it. The candidate's bodies are matched to the ground
truth's by their physics (``eval/bodies.py``), then compared at the ground truth's sample times on
what can be observed: the centre of mass's path and velocity, the angular velocity, and the
principal axes up to the body's symmetry (an axis whose moment equals another's is not compared).
Item types, creation order, reference points and local axes do not enter.

Every tolerance is a fraction ``relative`` of the ground truth's own scales (``Scales``): positions
within ``relative`` x the motion's range (the farthest a centre of mass travels, at least 1 % of the
system's size), velocities within ``relative`` x the range of the centres of mass' velocities, a
body's angular velocity and axes within what moves a point at the body's inertia radius by
``relative`` x the largest rim speed and the system's size, a flexible body's interface points within
10 x ``relative`` of their travel; and never less than 3 x what the ground truth's own time stepping
moves a quantity by (the same program with twice the steps). Where that floor would bind, the
caller compares runs at more steps instead (``eval/convergence.py``). Sensitive systems (an unstable
equilibrium, chaotic or impacting motion) get a horizon per task model: the motion is compared up
to the time two correct formulations of the ground truth stay within the tolerance
(``BEHAVIOUR_HORIZONS``, measured by ``scripts/behaviour_sensitivity.py``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from meceng.eval.bodies import BodyMotion, Scales, match_bodies, read_bodies, scales

#: Two moments closer than this (relative to the largest) make a symmetric body: its axes in
#: that plane are not compared.
DEGENERATE = 1e-6
#: A flexible body's interface points are compared within this many ``relative`` of their travel.
DEFORMATION = 10.0
#: A tolerance is at least this many times the ground truth's own step error (``_step_allowances``).
STEP_MARGIN = 3.0


@dataclass(frozen=True)
class BehaviourTolerance:
    relative: float = 1e-3  # a fraction of the system's size, speed range, ...
    horizon: float | None = None  # compare up to this fraction of the simulated time (None: all of it)


#: Task models whose ground truth is itself sensitive (see docs/behaviour.md): the fraction of
#: the simulated time compared. Measured with scripts/behaviour_sensitivity.py.
BEHAVIOUR_HORIZONS: dict[str, float] = {
    # upright on two in-line wheels, an unstable equilibrium: the same scooter with its wheels' axes
    # along local z parts from the ground truth by round-off alone at 0.73-0.98 of the 2 s at 7 of
    # 10 seeds (``--alternatives 10``); compared over the first half, where it stays within 1e-3
    "non_steerable_scooter_with_ideal_rolling": 0.5,
}


def tolerance_for(slug: str) -> BehaviourTolerance:
    return BehaviourTolerance(horizon=BEHAVIOUR_HORIZONS.get(slug))


@dataclass(frozen=True)
class Deviation:
    """The largest deviation of one matched pair's quantity (value and tolerance in SI units)."""

    body: int  # the ground truth's object number
    candidate_body: int
    quantity: str  # position, velocity, angular_velocity, axis, deformation
    value: float
    tolerance: float
    time: float

    @property
    def ratio(self) -> float:
        return self.value / self.tolerance if self.tolerance > 0 else float("inf")

    def to_json(self) -> dict[str, Any]:
        return {"body": self.body, "candidate_body": self.candidate_body, "quantity": self.quantity,
                "value": _round(self.value), "tolerance": _round(self.tolerance), "ratio": _round(self.ratio),
                "time": _round(self.time)}


@dataclass(frozen=True)
class BehaviourVerdict:
    passed: bool | None  # None: not evaluated (no motion recorded: an infrastructure matter)
    detail: str
    matching: tuple[tuple[int, int], ...] = ()  # (candidate object, ground-truth object)
    largest: Deviation | None = None
    first_divergence: Deviation | None = None  # the earliest sample where any quantity left its tolerance
    scales: Scales | None = None
    relative: float = 0.0
    compared_until: float | None = None
    deviations: tuple[Deviation, ...] = field(default_factory=tuple)
    widened: tuple[str, ...] = ()  # the tolerances the ground truth's own step error widened

    def to_json(self) -> dict[str, Any]:
        return {"passed": self.passed, "detail": self.detail,
                "matching": [{"candidate": c, "truth": g} for c, g in self.matching],
                "largest": self.largest.to_json() if self.largest else None,
                "first_divergence": self.first_divergence.to_json() if self.first_divergence else None,
                "scales": self.scales.to_json() if self.scales else None, "relative": self.relative,
                "compared_until": _round(self.compared_until), "widened_by_step_error": list(self.widened)}


def _round(value: float | None) -> float | None:
    return None if value is None else float(f"{value:.4g}")


def _axis_angles(candidate: BodyMotion, truth: BodyMotion, n: int) -> np.ndarray | None:
    """(n,) the largest angle between a compared principal axis of the truth and the candidate's
    axis of the same rank; None when no axis is compared (points, 2D bodies, spheres)."""
    truth_axes, candidate_axes = truth.global_axes(), candidate.global_axes()
    if truth_axes is None or truth.principal is None or truth.principal.size != 3:
        return None
    values = truth.principal
    top = max(float(np.max(values)), 1e-300)
    unique = [i for i in range(3) if all(abs(values[i] - values[j]) > DEGENERATE * top for j in range(3) if j != i)]
    if not unique:
        return None
    if candidate_axes is None or candidate.principal is None or candidate.principal.size != 3:
        return np.full(n, np.pi / 2)
    angles = np.zeros(n)
    for i in unique:
        a, b = truth_axes[:n, :, i], candidate_axes[:n, :, i]
        # the angle between the lines (either sign of an axis), well conditioned near zero
        cosine = np.abs(np.einsum("ni,ni->n", a, b))
        angles = np.maximum(angles, np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), cosine))
    return angles


def _pair_errors(candidate: BodyMotion, truth: BodyMotion, n: int, scale: Scales, relative: float
                 ) -> list[tuple[str, np.ndarray, float]]:
    """(quantity, deviation per sample, tolerance) of one matched pair over the first n samples."""
    shift = (candidate.t[:n] - truth.t[:n])[:, None]  # adaptive steps land beside the grid: first order back
    position = candidate.p[:n] - candidate.v[:n] * shift
    out = [("position", np.linalg.norm(position - truth.p[:n], axis=1), relative * scale.travel),
           ("velocity", np.linalg.norm(candidate.v[:n] - truth.v[:n], axis=1), relative * scale.speed)]
    size = max(truth.size, candidate.size)
    if truth.w is not None and size > 1e-3 * scale.length:
        omega = candidate.w[:n] if candidate.w is not None else np.zeros((n, 3))
        out.append(("angular_velocity", np.linalg.norm(omega - truth.w[:n], axis=1), relative * scale.turning / size))
        angles = _axis_angles(candidate, truth, n)
        if angles is not None:
            out.append(("axis", angles, min(relative * scale.length / size, 0.5)))
    deformation = _point_deviation(candidate, truth, n, relative * scale.length)
    if deformation is not None and truth.points is not None:
        # deflections are small beside the system: within DEFORMATION x relative of the farthest a
        # ground-truth interface point travels (a clamped beam: its tip's swing; a swinging one: its arc)
        travel = max(float(np.linalg.norm(np.ptp(truth.points[:, j], axis=0))) for j in range(truth.points.shape[1]))
        out.append(("deformation", deformation, max(DEFORMATION * relative * travel, 1e-12)))
    return out


def _point_deviation(candidate: BodyMotion, truth: BodyMotion, n: int, near: float) -> np.ndarray | None:
    """(n,) a flexible body's deformation: how far the ground truth's interface points (its markers on
    the mesh) lie from the candidate's that start at the same place; points the candidate has no
    marker at are not observed."""
    if truth.points is None or candidate.points is None:
        return None
    worst = None
    for j in range(truth.points.shape[1]):
        distance = np.linalg.norm(candidate.points[0] - truth.points[0, j], axis=1)
        i = int(np.argmin(distance))
        if distance[i] > near:
            continue
        deviation = np.linalg.norm(candidate.points[:n, i] - truth.points[:n, j], axis=1)
        worst = deviation if worst is None else np.maximum(worst, deviation)
    return worst


def _step_allowances(refined: list[BodyMotion] | None, bodies: list[BodyMotion], n: int, scale: Scales,
                     relative: float) -> dict[tuple[int, str], float]:
    """What a program's own time stepping moves each of its quantities by (the same program with
    ``REFINE`` times the steps, matched by object number), times ``STEP_MARGIN``: a program built
    another way has a step error of its own, of that size."""
    finer = {b.index: b for b in refined or []}
    out: dict[tuple[int, str], float] = {}
    for body in bodies:
        other = finer.get(body.index)
        if other is None or len(other.t) < n:
            continue
        for quantity, values, _ in _pair_errors(other, body, n, scale, relative):
            if np.all(np.isfinite(values)):
                out[(body.index, quantity)] = STEP_MARGIN * float(np.max(values))
    return out


@dataclass(frozen=True)
class Words:
    """How a verdict's ``detail`` names the two sides (the behaviour verdict: candidate and ground
    truth; the agreement of two programs: B and A)."""

    candidate: str = "the candidate"
    truth: str = "the ground truth"
    short: str = "candidate"  # the candidate's bodies: "(candidate's 3)"


def compare_behaviour(candidate_motion: dict[str, Any] | None, truth_motion: dict[str, Any] | None,
                      tolerance: BehaviourTolerance | None = None, refined: dict[str, Any] | None = None
                      ) -> BehaviourVerdict:
    """The behaviour verdict of a candidate's motion record against the ground truth's; ``refined``:
    the ground truth's record with more steps, whose difference widens a tolerance it exceeds."""
    tol = tolerance or BehaviourTolerance()
    truths = read_bodies(truth_motion)
    if truths is None:
        return BehaviourVerdict(None, "not evaluated: the ground truth's motion was not recorded")
    candidates = read_bodies(candidate_motion)
    if candidates is None:
        return BehaviourVerdict(False, "no motion: the candidate's system was not simulated")
    return compare_bodies(candidates, truths, scales(truths), tol, refined_truths=read_bodies(refined))


def compare_bodies(candidates: list[BodyMotion], truths: list[BodyMotion], scale: Scales,
                   tol: BehaviourTolerance, refined_truths: list[BodyMotion] | None = None,
                   refined_candidates: list[BodyMotion] | None = None, words: Words = Words()
                   ) -> BehaviourVerdict:
    """The comparison itself, on bodies already read and with the scales every tolerance is a
    fraction of given by the caller (the behaviour verdict: the ground truth's; two programs of
    the same model: the larger of the two, ``eval/agreement.py``). ``refined_*``: the same side
    with more steps, whose step error widens a tolerance (each side's own, the larger counts).
    Samples are taken at the truth's times; ``Deviation.body`` is the truth's object number."""
    if not truths:
        passed = not candidates
        return BehaviourVerdict(passed, f"no bodies in {words.truth}" + ("" if passed else
                                f"; {words.candidate} has {len(candidates)}"), scales=scale, relative=tol.relative)
    pairs = match_bodies(candidates, truths, scale)
    matching = tuple((candidates[c].index, truths[g].index) for c, g in pairs)
    common = dict(matching=matching, scales=scale, relative=tol.relative)
    if len(candidates) != len(truths):
        return BehaviourVerdict(False, f"{len(candidates)} bodies move, {words.truth} has {len(truths)}", **common)
    times = truths[0].t
    limit = float(times[-1]) if len(times) else 0.0
    if tol.horizon is not None:
        limit = float(times[0]) + tol.horizon * (limit - float(times[0]))
    n_truth = int(np.searchsorted(times, limit + 1e-12, side="right"))
    n = min(n_truth, len(candidates[0].t))
    if n < n_truth:
        reached = float(candidates[0].t[-1]) if len(candidates[0].t) else 0.0
        return BehaviourVerdict(False, f"{words.candidate}'s motion ends at t = {reached:.4g} s of {limit:.4g} s",
                                compared_until=limit, **common)
    deviations: list[Deviation] = []
    first: Deviation | None = None
    allowances = _step_allowances(refined_truths, truths, n, scale, tol.relative)
    own = _step_allowances(refined_candidates, candidates, n, scale, tol.relative)
    for c, g in pairs:
        cand, truth = candidates[c], truths[g]
        for quantity, values, allowed in _pair_errors(cand, truth, n, scale, tol.relative):
            allowed = max(allowed, allowances.get((truth.index, quantity), 0.0), own.get((cand.index, quantity), 0.0))
            bad = ~np.isfinite(values)
            values = np.where(bad, np.inf, values)
            k = int(np.argmax(values))
            deviations.append(Deviation(truth.index, cand.index, quantity, float(values[k]), allowed, float(times[k])))
            over = np.nonzero(values > allowed)[0]
            if len(over):
                j = int(over[0])
                if first is None or times[j] < first.time:
                    first = Deviation(truth.index, cand.index, quantity, float(values[j]), allowed, float(times[j]))
    largest = max(deviations, key=lambda d: d.ratio) if deviations else None
    passed = first is None
    if passed:
        detail = (f"motions match up to t = {limit:.4g} s (largest: {largest.quantity} of body {largest.body} at "
                  f"{largest.ratio:.3g} of its tolerance)" if largest else "nothing moves")
    else:
        assert first is not None
        detail = (f"motions part at t = {first.time:.4g} s: {first.quantity} of body {first.body} "
                  f"({words.short}'s {first.candidate_body}) off by {first.value:.3g} > {first.tolerance:.3g}")
    widened = sorted({f"{q} of body {b}" for (b, q), v in allowances.items()
                      if any(d.body == b and d.quantity == q and d.tolerance == v for d in deviations)}
                     | {f"{q} of {words.short}'s body {b}" for (b, q), v in own.items()
                        if any(d.candidate_body == b and d.quantity == q and d.tolerance == v for d in deviations)})
    return BehaviourVerdict(passed, detail, largest=largest, first_divergence=first, compared_until=limit,
                            deviations=tuple(deviations), widened=tuple(widened), **common)
