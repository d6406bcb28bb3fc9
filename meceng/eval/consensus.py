"""Consensus without a ground truth: independent programs grouped by whether they move alike.

Two programs agree when their motions do (``eval/agreement.compare_motions``, the comparison the
agent's ``compare`` tool answers with): bodies matched by their physics, every quantity within 1e-3
of the smaller of the two motions' scales, so agreement does not depend on which sample is asked
first. No step-error allowance is given (there is no refined run of either program): two
formulations whose time stepping differs by more than that do not agree. The same program text is
the same motion (the simulation is deterministic) and agrees without a comparison.

Groups are cliques: every two samples of a group agree. Agreement need not be transitive (A~B,
B~C, not A~C), so groups are formed greedily: samples in order of how many others they agree with
(most first, ties by sample order), each joining the first group all of whose members it agrees
with, or starting one. A sample that did not run (no program, a failed run: no motion) is a group
of its own, never together with another failure. A sample the server lost is in no group and not
counted. The answer is a sample of the largest group (ties: a group whose samples ran, then the
group holding the earliest sample); the chosen program is the group's program text written most
often (motions that agree may still differ where motion cannot show it, e.g. a free body's mass),
then its earliest sample; the group's share of the counted samples is the confidence.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from meceng.eval.agreement import compare_motions
from meceng.eval.behaviour import BehaviourTolerance


@dataclass(frozen=True)
class Agreement:
    """Two samples compared: whether they agree, and the behaviour comparison's words."""

    a: int
    b: int
    agree: bool
    detail: str

    def to_json(self) -> dict[str, Any]:
        return {"a": self.a, "b": self.b, "agree": self.agree, "detail": self.detail}


@dataclass(frozen=True)
class Consensus:
    groups: tuple[tuple[int, ...], ...]  # sample indices; largest first, then by first sample
    chosen: int | None  # the answer's sample index (None: every sample was lost)
    confidence: float  # the chosen group's share of the counted samples
    counted: int  # samples the server answered
    agreements: tuple[Agreement, ...] = ()

    def group_of(self, sample: int) -> int | None:
        return next((g for g, members in enumerate(self.groups) if sample in members), None)

    def to_json(self) -> dict[str, Any]:
        return {"groups": [list(g) for g in self.groups], "chosen": self.chosen,
                "confidence": round(self.confidence, 4), "counted": self.counted,
                "agreements": [a.to_json() for a in self.agreements]}


def motions_agree(a: dict[str, Any] | None, b: dict[str, Any] | None,
                  tolerance: BehaviourTolerance | None = None) -> tuple[bool, str]:
    """Whether two motion records agree (``eval/agreement.compare_motions``, the comparison the
    agent's ``compare`` tool gives: no ground truth, the smaller of the two scales); the words say
    where they part when they do not."""
    if a is None or b is None:
        return False, "not both simulated"
    result = compare_motions(a, b, tolerance)
    return result.agree is True, result.detail


def group_samples(ran: Sequence[bool], lost: Sequence[bool], agree: Callable[[int, int], bool]) -> Consensus:
    """Groups and the answer from which samples ran, which were lost, and pairwise agreement
    (asked only of two samples that both ran, ``a < b``)."""
    n = len(ran)
    live = [i for i in range(n) if not lost[i]]
    running = [i for i in live if ran[i]]
    pairs = {(a, b): agree(a, b) for k, a in enumerate(running) for b in running[k + 1:]}

    def agrees(a: int, b: int) -> bool:
        return pairs[(min(a, b), max(a, b))]

    degree = {i: sum(agrees(i, j) for j in running if j != i) for i in running}
    groups: list[list[int]] = []
    for i in sorted(running, key=lambda i: (-degree[i], i)):
        home = next((g for g in groups if all(agrees(i, j) for j in g)), None)
        if home is None:
            groups.append([i])
        else:
            home.append(i)
    groups.extend([i] for i in live if not ran[i])
    ordered = sorted((tuple(sorted(g)) for g in groups), key=lambda g: (-len(g), not ran[g[0]], g[0]))
    if not ordered:
        return Consensus((), None, 0.0, 0)
    best = ordered[0]
    return Consensus(tuple(ordered), best[0], len(best) / len(live), len(live))


def consensus_of(motions: Sequence[dict[str, Any] | None], programs: Sequence[str | None], lost: Sequence[bool],
                 tolerance: BehaviourTolerance | None = None) -> Consensus:
    """The consensus of K samples: their motion records (None: not simulated), their program texts
    (equal texts agree without a comparison) and which were lost to the server."""
    words: dict[tuple[int, int], Agreement] = {}

    def agree(a: int, b: int) -> bool:
        if programs[a] is not None and programs[a] == programs[b]:
            words[(a, b)] = Agreement(a, b, True, "the same program")
        else:
            ok, detail = motions_agree(motions[a], motions[b], tolerance)
            words[(a, b)] = Agreement(a, b, ok, detail)
        return words[(a, b)].agree

    ran = [m is not None and not lost[i] for i, m in enumerate(motions)]
    result = group_samples(ran, lost, agree)
    chosen = result.chosen
    if result.groups:  # within the group: the program text written most often, then the earliest
        best = result.groups[0]
        chosen = min(best, key=lambda i: (-sum(programs[j] == programs[i] for j in best), i))
    return Consensus(result.groups, chosen, result.confidence, result.counted,
                     tuple(words[k] for k in sorted(words)))
