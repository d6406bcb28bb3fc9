"""The two LLM steps of a task: choose components, then write the program.

Each returns a frozen record with the prompt, the raw answer, what was parsed from it and the
response metadata (tokens, durations, truncation). Infrastructure failures (the server could not
answer) are recorded as such, distinct from a malformed answer of the model.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from meceng.agents.parsing import extract_code, parse_components
from meceng.agents.prompts import code_prompt, gold_code, gold_selection, select_prompt
from meceng.catalog.component import Catalog
from meceng.llm.messages import user_messages
from meceng.llm.types import Backend, ChatRequest, ChatResponse, ContextExceeded, LLMError
from meceng.tasks.base import TaskInstance


@dataclass(frozen=True)
class Selection:
    prompt: str
    answer: str
    names: tuple[str, ...]
    unknown: tuple[str, ...] = ()
    error: str | None = None
    infrastructure_error: str | None = None
    meta: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        return {"prompt": self.prompt, "answer": self.answer, "names": list(self.names),
                "unknown": list(self.unknown), "error": self.error,
                "infrastructure_error": self.infrastructure_error, "meta": self.meta}


@dataclass(frozen=True)
class Generation:
    prompt: str
    answer: str
    code: str | None
    error: str | None = None
    infrastructure_error: str | None = None
    meta: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        return {"prompt": self.prompt, "answer": self.answer, "code": self.code, "error": self.error,
                "infrastructure_error": self.infrastructure_error, "meta": self.meta}


def given_selection(instance: TaskInstance) -> Selection:
    """A repair task's components: those the draft already uses (no request is made)."""
    return Selection(prompt="", answer="", names=instance.required_components, meta={"given": True})


def selection_prompt(instance: TaskInstance, catalog: Catalog, template: str) -> str:
    """The component-selection prompt a model gets for ``instance`` (the pipeline's and
    ``meceng tasks prompt``'s one source)."""
    return select_prompt(template, instance.description, catalog.menu())


def generation_prompt(instance: TaskInstance, catalog: Catalog, names: tuple[str, ...] | list[str],
                      template: str) -> str:
    """The code prompt after the model chose ``names``: the description and the documentation of the
    chosen components with their dependencies."""
    return code_prompt(template, instance.description, catalog.context(names), instance.texts)


async def _ask(backend: Backend, request: ChatRequest) -> tuple[ChatResponse | None, str | None, dict[str, Any]]:
    """The answer, or why there is none and, for a prompt the server's context cannot hold, its
    numbers (the record's ``context_exceeded``)."""
    try:
        return await backend.chat(request), None, {}
    except ContextExceeded as exc:
        return None, str(exc), {"context_exceeded": exc.to_json()}
    except LLMError as exc:
        return None, str(exc), {}


async def choose_components(
    backend: Backend, instance: TaskInstance, catalog: Catalog, template: str = "CI1"
) -> Selection:
    prompt = selection_prompt(instance, catalog, template)
    request = ChatRequest(user_messages(prompt), "select", instance.key,
                          gold=gold_selection(instance.required_components))
    response, failure, lost = await _ask(backend, request)
    if response is None:
        return Selection(prompt, "", (), error=failure, infrastructure_error=failure, meta=lost)
    parsed = parse_components(response.content, catalog.names)
    return Selection(prompt, response.content, parsed.names, parsed.unknown, parsed.error,
                     meta=_meta(response, backend))


async def generate_code(
    backend: Backend, instance: TaskInstance, catalog: Catalog, selection: Selection, template: str = "MBS1",
    prompt: str | None = None,
) -> Generation:
    """The code request; ``prompt`` replaces the template's (a repair task's question)."""
    prompt = prompt or generation_prompt(instance, catalog, selection.names, template)
    request = ChatRequest(user_messages(prompt), "code", instance.key,
                          gold=gold_code(instance.reference_program))
    response, failure, lost = await _ask(backend, request)
    if response is None:
        return Generation(prompt, "", None, error=failure, infrastructure_error=failure, meta=lost)
    extracted = extract_code(response.content)
    error = extracted.error
    if response.truncated and extracted.code is None:
        error = f"{error} (answer truncated: done_reason 'length')"
    return Generation(prompt, response.content, extracted.code, error, meta=_meta(response, backend))


def _meta(response: ChatResponse, backend: Backend) -> dict[str, Any]:
    """Response metadata, the model's thinking text, and whether the context window was full."""
    meta = response.meta()
    meta["thinking"] = response.thinking
    num_ctx = getattr(getattr(backend, "settings", None), "num_ctx", None)
    meta["context_limit_hit"] = bool(num_ctx and response.context_used >= num_ctx)
    return meta
