"""The level 1-2 evaluation chain in the paper's order (Fig. 6a), as one pure function.

choose components -> finished assemble -> topology match -> graph content match -> solver success
-> solution match -> overall. Finished assemble gates everything after it, topology gates graph
content, and solver success gates the solution match; a stage that was not evaluated because
its gate failed is recorded with ``passed = None`` and counts as not passed in the rates.

An open text (issue 36: the system in an engineer's words, ``TaskInstance.texts == "open"``) does
not say how to write the program, so the stages that compare the writing with the ground truth's
(topology, graph content, the solution's coordinates) and the component choice are recorded as not
required (``required=False``: in no rate, never a failure), and the task passes when its system
moves as the ground truth's: a ``behaviour_match`` stage after the solver (``by_behaviour``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from meceng.eval.behaviour import BehaviourTolerance, compare_behaviour
from meceng.eval.components import check_components
from meceng.eval.convergence import ConvergedRuns
from meceng.eval.graph import GraphTolerance, compare_graphs
from meceng.eval.solution import compare_solutions
from meceng.tools.execution import Execution

RIGID_STAGES = (
    "choose_components",
    "finished_assemble",
    "topology_match",
    "graph_content_match",
    "solver_success",
    "solution_match",
)

#: An open-text task's stages: the paper's, then the behaviour verdict as a stage of its own.
BEHAVIOUR_STAGE = "behaviour_match"
#: The paper's stages an open text does not require: they compare how a program is written.
NOT_REQUIRED_BY_OPEN_TEXTS = ("choose_components", "topology_match", "graph_content_match", "solution_match")


@dataclass(frozen=True)
class StageResult:
    name: str
    passed: bool | None
    detail: str = ""
    # False: recorded but not part of the verdict (an open text's writing stages): in no rate, never
    # the first failure. Written to the record only when False, so the paper's records are unchanged.
    required: bool = True

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "passed": self.passed, "detail": self.detail,
                **({} if self.required else {"required": False})}


@dataclass(frozen=True)
class Verdict:
    """The graded outcome of one task: every stage in order, the first failure, categories."""

    stages: tuple[StageResult, ...]
    error_categories: tuple[str, ...] = ()
    differences: tuple[dict[str, Any], ...] = ()
    solution_norm: float | None = None
    infrastructure_error: str | None = None
    topology_causes: dict[str, Any] | None = None  # why topology_match failed (eval.topology)
    # does the program's system move as the ground truth's (eval.behaviour)? Beside the paper's
    # verdict: it changes neither ``overall`` nor any stage. None: not graded for behaviour (3a).
    behaviour: dict[str, Any] | None = None
    # "paper": the paper's chain decides; "behaviour": an open-text task (``by_behaviour``)
    graded_by: str = "paper"

    @property
    def overall(self) -> bool:
        if self.infrastructure_error is not None or not self.stages:
            return False
        return all(s.passed for s in self.stages if s.required and not _not_applicable(s))

    @property
    def first_failure(self) -> str | None:
        if self.infrastructure_error is not None:
            return "infrastructure"
        for stage in self.stages:
            if stage.passed is False and stage.required:
                return stage.name
        return None

    def stage(self, name: str) -> StageResult:
        for s in self.stages:
            if s.name == name:
                return s
        raise KeyError(name)

    def to_json(self) -> dict[str, Any]:
        return {
            "stages": [s.to_json() for s in self.stages],
            "overall": self.overall,
            "first_failure": self.first_failure,
            "error_categories": list(self.error_categories),
            "differences": [_jsonable_difference(d) for d in self.differences[:50]],
            "solution_norm": self.solution_norm,
            "infrastructure_error": self.infrastructure_error,
            "topology_causes": self.topology_causes,
            **({"behaviour": self.behaviour} if self.behaviour is not None else {}),
            **({"graded_by": self.graded_by} if self.graded_by != "paper" else {}),
        }


@dataclass(frozen=True)
class Tolerances:
    solution: float = 1e-5
    graph: GraphTolerance = field(default_factory=GraphTolerance)


def evaluate_rigid(
    candidate: Execution,
    reference: Execution,
    *,
    end_time: float,
    steps: int,
    selected: Iterable[str] | None,
    required: Iterable[str],
    dependencies: Mapping[str, Iterable[str]],
    tolerances: Tolerances | None = None,
    behaviour: BehaviourTolerance | None = None,
    refined: dict[str, Any] | None = None,
    converged: ConvergedRuns | None = None,
) -> Verdict:
    """Grade a candidate execution against the reference execution of the same task instance.

    ``selected`` None means no component selection took place (grading a program directly);
    that stage is then recorded as not applicable and does not count against overall.
    ``refined``: the ground truth's motion with more steps (its own step error, for behaviour).
    ``converged``: the motions behaviour compares instead, at the step count where the ground truth's
    own step error no longer decides (``eval/convergence.py``); the paper's stages never read them.
    """
    tol = tolerances or Tolerances()
    if not reference.solved or reference.items is None or reference.trajectory is None:
        return Verdict(
            stages=(),
            infrastructure_error=f"reference program failed: {reference.error or reference.stage}",
        )
    if candidate.lost_to_machine:  # the wall clock stopped it with CPU time to spare: nothing to grade
        return Verdict(stages=(), infrastructure_error=f"program not graded: {candidate.error}")
    stages: list[StageResult] = []
    if selected is None:
        stages.append(StageResult("choose_components", None, "not applicable: no component selection"))
    else:
        check = check_components(selected, required, dependencies)
        stages.append(StageResult("choose_components", check.passed, check.detail))

    if not candidate.finished_assemble or candidate.items is None:
        reason = candidate.error or f"stopped at stage '{candidate.stage}'"
        stages.append(StageResult("finished_assemble", False, reason))
        stages += [StageResult(n, None, "not evaluated: assemble did not finish") for n in RIGID_STAGES[2:]]
        return Verdict(tuple(stages), behaviour=_behaviour(candidate, reference, behaviour, refined, converged))
    stages.append(StageResult("finished_assemble", True, "mbs.Assemble() finished"))

    graph = compare_graphs(candidate.items, reference.items, tol.graph)
    topology_ok = graph.counts_match and bool(graph.topology_match)
    stages.append(StageResult("topology_match", topology_ok, graph.detail if not topology_ok else
                              "system graphs are isomorphic by item type"))
    if topology_ok:
        stages.append(StageResult("graph_content_match", bool(graph.content_match), graph.detail))
    else:
        stages.append(StageResult("graph_content_match", None, "not evaluated: topology differs"))

    norm = None
    if candidate.solved and candidate.trajectory is not None and candidate.times is not None:
        stages.append(StageResult("solver_success", True, "simulation finished"))
        solution = compare_solutions(candidate.times, candidate.trajectory, reference.times,
                                     reference.trajectory, end_time, steps, tol.solution)
        stages.append(StageResult("solution_match", solution.passed, solution.detail))
        norm = solution.norm
    else:
        stages.append(StageResult("solver_success", False, candidate.error or f"stage '{candidate.stage}'"))
        stages.append(StageResult("solution_match", None, "not evaluated: solver failed"))
    return Verdict(tuple(stages), tuple(graph.error_categories), tuple(graph.differences), norm,
                   topology_causes=graph.topology.to_json() if graph.topology else None,
                   behaviour=_behaviour(candidate, reference, behaviour, refined, converged))


def by_behaviour(verdict: Verdict) -> Verdict:
    """The verdict of an open-text task from the paper's verdict of the same program: the stages
    that compare the writing (and the component choice) stay in the record as not required, with
    what they found in their detail; a ``behaviour_match`` stage after the solver decides. The
    paper's error categories and graph differences describe the writing, not an error: dropped."""
    if verdict.infrastructure_error is not None or not verdict.stages:
        return dataclasses.replace(verdict, graded_by="behaviour")
    behaviour = verdict.behaviour or {}
    passed = behaviour.get("passed")
    stages = [dataclasses.replace(s, required=False, passed=None if s.name != "choose_components" else s.passed,
                                  detail=f"not required (open text, graded by behaviour): {s.detail}")
              if s.name in NOT_REQUIRED_BY_OPEN_TEXTS else s for s in verdict.stages]
    stages.append(StageResult(BEHAVIOUR_STAGE, passed, str(behaviour.get("detail", "not graded"))))
    # no motion of the ground truth to compare with: not the model's failure
    infra = None if passed is not None else f"behaviour not graded: {behaviour.get('detail', 'no verdict')}"
    return Verdict(tuple(stages), solution_norm=verdict.solution_norm, infrastructure_error=infra,
                   behaviour=verdict.behaviour, graded_by="behaviour")


def _behaviour(candidate: Execution, reference: Execution, tolerance: BehaviourTolerance | None,
               refined: dict[str, Any] | None, converged: ConvergedRuns | None = None) -> dict[str, Any]:
    """The behaviour block: at the converged step count when the caller found one (with the record of
    which and why under ``steps``), else the graded runs with ``refined``'s floor."""
    if converged is None:
        return compare_behaviour(candidate.motion, reference.motion, tolerance, refined).to_json()
    verdict = compare_behaviour(converged.candidate, converged.truth, tolerance, converged.finer)
    out = {**verdict.to_json(), "steps": converged.convergence.to_json()}
    steps = converged.convergence
    if steps.factor > 1 or steps.note or not steps.converged:  # not the graded runs' plain comparison: say so
        said = [f"compared at {steps.factor} x the steps ({steps.steps})"] if steps.factor > 1 else []
        if not steps.converged:
            counts: dict[str, int] = {}
            for widened in verdict.widened:
                quantity = widened.split(" of ", 1)[0]
                counts[quantity] = counts.get(quantity, 0) + 1
            bound = f" at the cost bound (R <= {steps.cap})" if steps.factor >= steps.cap else ""
            said.append(f"not converged{bound}: the ground truth's own step error still widens " + (
                ", ".join(f"the {q} of {n} bod{'y' if n == 1 else 'ies'}" for q, n in counts.items())
                if counts else "no tolerance it decides"))
        if steps.note:
            said.append(steps.note)
        out["detail"] = f"{out['detail']} [{'; '.join(said)}]"
    return out


def _not_applicable(stage: StageResult) -> bool:
    return stage.name in ("choose_components", "choose_part_components") and stage.passed is None


def _jsonable_difference(d: dict[str, Any]) -> dict[str, Any]:
    out = dict(d)
    for key in ("value", "expected"):
        text = repr(out.get(key))
        out[key] = out.get(key) if len(text) <= 200 else text[:197] + "..."
    return out
