"""The ``scripted`` backend: a model whose error rate is known, for measuring ``--agent consensus``.

``--model scripted:p=0.5`` answers a code request with the ground truth with probability ``p`` and
otherwise with one of the task's labelled repair drafts (a reference program with one seeded fault,
``tasks/drafts.py``), drawn at random; ``--model scripted-same:p=0.5`` draws its wrong answers
always from the same draft of the task, the case where every wrong sample carries the same fault
and consensus cannot see it (``scripted-same:p=0.5:d=N``: that draft is the task's N-th, so several
such models in one consensus run each repeat a fault of their own). The selection request is
answered with the required components (the drafts keep them). Every draw is seeded by (run seed,
task, sample), so a run is reproduced exactly and the samples of one task are independent.

A backend of its own rather than a script: it runs through ``meceng run`` as a user's model would
(the same flow, records, report and viewer). The drafts come from the task room, which this room
may not import, so the pipeline hands them in (``pipeline/scripted.py``).
"""

from __future__ import annotations

import hashlib
import random
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from meceng.llm.types import ChatRequest, ChatResponse, LLMError

PATTERN = re.compile(r"^scripted(?P<same>-same)?:p=(?P<p>[0-9.]+)(?::d=(?P<d>[0-9]+))?$")


@dataclass(frozen=True)
class ScriptedDraft:
    """A wrong answer the scripted model may give: the draft's id, its label and its program."""

    id: str
    label: str
    program: str


@dataclass(frozen=True)
class ScriptedModel:
    p: float  # the probability of the ground truth
    same_fault: bool  # every wrong answer of a task is one draft: its first, or draft ``draft``
    draft: int = 0  # scripted-same:p=P:d=N: the same-fault draft is the task's N-th (mod its drafts)


def parse_scripted(model: str) -> ScriptedModel:
    """``scripted:p=0.5``, ``scripted-same:p=0.5`` or ``scripted-same:p=0.5:d=1`` (its same fault the
    task's draft 1: models of a consensus run across models that each repeat a fault of their own);
    anything else is refused with the form."""
    match = PATTERN.match(model)
    if (match is None or not 0.0 <= float(match["p"]) <= 1.0
            or (match["d"] is not None and match["same"] is None)):
        raise ValueError(f"scripted model {model!r}: write scripted:p=P or scripted-same:p=P[:d=N] with 0 <= P <= 1")
    return ScriptedModel(float(match["p"]), match["same"] is not None, int(match["d"] or 0))


def _rng(seed: int | None, task_key: str, sample: int | None) -> random.Random:
    text = f"{seed}|{task_key}|{sample}"
    return random.Random(int.from_bytes(hashlib.sha256(text.encode()).digest()[:8], "big"))


class ScriptedBackend:
    """Answers with the ground truth (``request.gold``) with probability p, else with a draft."""

    name = "scripted"

    def __init__(self, model: str, seed: int | None, drafts: Mapping[str, Sequence[ScriptedDraft]]) -> None:
        self.model = parse_scripted(model)
        self.seed = seed
        self.drafts = drafts  # task key -> its drafts

    def answer(self, task_key: str, sample: int | None, gold: str) -> tuple[str, str]:
        """(the answer's text, what it is: 'reference' or the draft's id and label)."""
        rng = _rng(self.seed, task_key, sample)
        drafts = self.drafts.get(task_key, ())
        if rng.random() < self.model.p:
            return gold, "reference"
        if not drafts:  # a task whose ground truth admits no fault: a wrong answer without a program
            return "I cannot write this program.", "no program (the task has no draft)"
        draft = (drafts[self.model.draft % len(drafts)] if self.model.same_fault
                 else drafts[rng.randrange(len(drafts))])
        what = f"draft {draft.id} [{draft.label}]"
        return f"```python\n# scripted sample: {what}\n{draft.program.rstrip()}\n```", what

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.gold is None:
            raise LLMError(f"no gold answer for {request.purpose} of {request.task_key}", transient=False)
        if request.purpose != "code":
            return ChatResponse(content=request.gold, done_reason="stop", endpoint="scripted")
        content, what = self.answer(request.task_key, request.sample, request.gold)
        return ChatResponse(content=content, done_reason="stop", endpoint=f"scripted: {what}")

    async def aclose(self) -> None:
        return None
