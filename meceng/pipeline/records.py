"""Task records: the JSON line each finished task leaves in the journal and in run.json.

One record shape for every level; a task kind adds its own block (``part``, ``parts``), an agent
run adds ``agent``. A record whose task was lost to the server or the harness says so with
``first_failure: "infrastructure"``: it is left out of the rates and done again by ``--resume``.
A lost task whose prompt the server's context could not hold says so too, with the numbers
(``context_exceeded``): the same server would refuse it again, so ``--resume`` keeps it unless the
run is resumed on a server the user names.
"""

from __future__ import annotations

import traceback
from typing import Any

from meceng.agents.loop import AgentResult
from meceng.agents.steps import Generation, Selection
from meceng.eval import EVALUATOR_VERSION
from meceng.eval.chain import Verdict
from meceng.tasks.base import TaskInstance
from meceng.tools.execution import Execution


def _instance_fields(instance: TaskInstance) -> dict[str, Any]:
    fields = {
        "id": instance.task_id, "slug": instance.slug, "name": instance.name, "level": instance.level,
        "seed": instance.seed, "params": instance.params, "description": instance.description,
        "required_components": list(instance.required_components),
        "texts": instance.texts,  # which task text: the paper's, or "open" (an engineer's words)
    }
    if instance.origin:  # a part drawn for an assembly: the key it is resumed and sorted by
        fields["origin"] = instance.origin
    return fields


def _tokens(*metas: dict[str, Any]) -> dict[str, int]:
    return {"prompt": sum(m.get("prompt_tokens", 0) for m in metas),
            "completion": sum(m.get("completion_tokens", 0) for m in metas),
            "reasoning": sum(m.get("reasoning_tokens", 0) for m in metas)}


def task_record(
    instance: TaskInstance,
    selection: Selection,
    generation: Generation,
    verdict: Verdict,
    candidate: Execution,
    reference: Execution,
    timing: dict[str, float],
    files: dict[str, str],
) -> dict[str, Any]:
    infra = selection.infrastructure_error or generation.infrastructure_error or verdict.infrastructure_error
    verdict_json = verdict.to_json()
    if infra and not verdict.infrastructure_error:
        verdict_json.update(overall=False, first_failure="infrastructure")
    return {
        **_instance_fields(instance),
        **verdict_json,
        "infrastructure_error": infra,
        "selection": selection.to_json(),
        "generation": generation.to_json(),
        "execution": candidate.summary(),
        "reference_execution": reference.summary(),
        "timing": {k: round(v, 4) for k, v in timing.items()},
        "tokens": _tokens(selection.meta, generation.meta),
        "files": files,
        "evaluator": EVALUATOR_VERSION,
    }


def lost_record(instance: TaskInstance, reason: str, timing: dict[str, float], *,
                selection: Selection | None = None, generation: Generation | None = None) -> dict[str, Any]:
    """A task the server or the harness lost before it could be graded: nothing is graded, nothing
    is counted, and ``--resume`` does it again."""
    record: dict[str, Any] = {
        **_instance_fields(instance), "stages": [], "overall": False, "first_failure": "infrastructure",
        "error_categories": [], "infrastructure_error": reason,
        "timing": {k: round(v, 4) for k, v in timing.items()},
        "tokens": _tokens(*(s.meta for s in (selection, generation) if s is not None)),
        "evaluator": EVALUATOR_VERSION,
    }
    if selection is not None:
        record["selection"] = selection.to_json()
    if generation is not None:
        record["generation"] = generation.to_json()
    overflow = next((s.meta["context_exceeded"] for s in (selection, generation)
                     if s is not None and s.meta.get("context_exceeded")), None)
    if overflow is not None:
        record["context_exceeded"] = overflow
    return record


def not_started_record(instance: TaskInstance, verdict: Verdict, part_keys: dict[str, str],
                       timing: dict[str, float]) -> dict[str, Any]:
    """The record of an assembly that was not started (a part failed): no LLM call, no run."""
    return {
        **_instance_fields(instance), **verdict.to_json(),
        "parts": part_keys, "timing": {"llm_s": 0.0, "evaluation_s": 0.0, "total_s": timing["parts_wall_s"],
                                       **timing},
        "tokens": {"prompt": 0, "completion": 0, "reasoning": 0}, "evaluator": EVALUATOR_VERSION,
    }


def failed_record(instance: TaskInstance, exc: BaseException) -> dict[str, Any]:
    """A record for a task whose processing raised: recorded, never fatal to the run."""
    text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))[-3000:]
    record = lost_record(instance, f"pipeline error: {type(exc).__name__}: {exc}",
                         {"llm_s": 0.0, "evaluation_s": 0.0, "total_s": 0.0})
    record["traceback"] = text
    return record


def agent_block(agent: AgentResult, first: Verdict) -> dict[str, Any]:
    """The agent's record: transcript, rounds, tools, and the verdict of its first program."""
    return {**agent.to_json(), "first_overall": first.overall, "first_failure": first.first_failure,
            "first_stages": [s.to_json() for s in first.stages]}


def agent_generation(agent: AgentResult) -> Generation:
    """The agent's final answer in the shape of the two-step pipeline's generation record."""
    return Generation(prompt=agent.transcript[0]["content"], answer=agent.transcript[-1].get("content", ""),
                      code=agent.final_code, error=agent.error, infrastructure_error=agent.infrastructure_error,
                      meta={"completion_tokens": agent.completion_tokens, "prompt_tokens": agent.prompt_tokens,
                            "reasoning_tokens": agent.reasoning_tokens,
                            "context_used": agent.prompt_tokens + agent.completion_tokens,
                            **({"context_exceeded": agent.context_exceeded} if agent.context_exceeded else {})})
