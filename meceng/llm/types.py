"""What every language-model backend shares: settings, requests, answers, errors, the protocol.

``ollama`` talks to one or more Ollama servers (``/api/chat``, ``stream: false``) over aiohttp;
``openai`` to OpenAI's API or an OpenAI-compatible server (vLLM, SGLang); ``anthropic`` to
Anthropic's Messages API; ``gold`` answers every request with the ground truth, which proves the
harness end to end on a machine without a model (like SWE-bench's gold patches).

The one message format the agent loop writes is in ``messages.py`` (each backend translates it to
its wire format); the per-endpoint scheduler (slots, retries) in ``scheduler.py``; the backends in
``backend_*.py``; ``factory.py`` picks one, so that types <- backends <- factory is one way.

API keys are read from the environment when a backend is made and are never part of the
settings, so no run file can hold one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol


def parse_retry_after(value: str | None) -> float | None:
    """Seconds from a Retry-After header (delta-seconds or HTTP date); None if absent or bad."""
    if not value:
        return None
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    from email.utils import parsedate_to_datetime

    try:
        when = parsedate_to_datetime(value)
    except (TypeError, ValueError):
        return None
    import datetime as dt

    return max(0.0, (when - dt.datetime.now(dt.UTC)).total_seconds())


@dataclass(frozen=True)
class LLMSettings:
    """LLM settings of a run (paper section 2.2.1, first group)."""

    model: str = "gold"
    backend: str = "gold"
    hosts: tuple[str, ...] = ("http://127.0.0.1:11434",)
    temperature: float = 0.0
    seed: int | None = 42
    think: bool | str | None = False
    num_ctx: int = 4096
    num_predict: int = 2048
    keep_alive: str | float | None = "30m"
    batch_size: int = 4
    timeout_s: float = 600.0
    max_attempts: int = 4
    backoff_s: float = 1.0
    # hosted APIs "with default API settings" (paper, Tables 2 and 6): neither temperature nor seed is
    # sent (OpenAI's reasoning models refuse temperature 0 with a 400)
    api_defaults: bool = False
    # the environment variable holding the API key (None: the backend's conventional one); the name
    # is a setting, the key never is
    api_key_env: str | None = None
    # the model takes images: the agent's ``snapshot`` tool answers with a picture (Anthropic image
    # blocks, OpenAI ``image_url`` parts, Ollama ``images``); otherwise with a text description
    vision: bool = False

    def __post_init__(self) -> None:
        # Anthropic's API (version 2026-10-21) takes no sampling parameters: whoever makes the
        # settings (command line, sweep spec, a resumed run), such a run has the API's defaults
        if self.backend == "anthropic" and not self.api_defaults:
            object.__setattr__(self, "api_defaults", True)

    def options(self, sample: int | None = None) -> dict[str, Any]:
        """Ollama's sampling options; with ``api_defaults`` the model's own temperature and a
        random seed (the paper's thinking runs use each model's default temperature). ``sample``:
        the index of one of several independent answers to one prompt (``--agent consensus``)."""
        opts: dict[str, Any] = {"num_ctx": self.num_ctx, "num_predict": self.num_predict}
        if not self.api_defaults:
            opts["temperature"] = self.temperature
            seed = self.sample_seed(sample)
            if seed is not None:
                opts["seed"] = seed
        return opts

    def sample_seed(self, sample: int | None) -> int | None:
        """The seed sent for sample ``sample`` of a prompt: the run's seed, offset by the sample's
        index so that independent samples are drawn with distinct seeds (None: no seed is sent)."""
        if self.seed is None:
            return None
        return self.seed + (sample or 0)

    def to_json(self) -> dict[str, Any]:
        return {
            "model": self.model, "backend": self.backend, "hosts": list(self.hosts),
            "temperature": self.temperature, "seed": self.seed, "think": self.think,
            "num_ctx": self.num_ctx, "num_predict": self.num_predict, "keep_alive": self.keep_alive,
            "batch_size": self.batch_size, "timeout_s": self.timeout_s, "max_attempts": self.max_attempts,
            "api_defaults": self.api_defaults, "api_key_env": self.api_key_env, "vision": self.vision,
        }


@dataclass(frozen=True)
class ChatRequest:
    """One chat call. ``gold`` is the expected answer; only the gold backend reads it."""

    messages: tuple[dict[str, Any], ...]
    purpose: str
    task_key: str
    gold: str | None = None
    tools: tuple[dict[str, Any], ...] = ()  # JSON-schema function definitions for native tool calling
    # one of several independent answers to the same prompt (``--agent consensus``): the backend
    # offsets its sampling seed by it and the response cache keys on it; None: the only answer
    sample: int | None = None

    @property
    def prompt(self) -> str:
        return "\n\n".join(str(m.get("content", "")) for m in self.messages)


@dataclass(frozen=True)
class ToolCall:
    """A function call the model asked for; ``id`` is the OpenAI call id (empty for Ollama)."""

    name: str
    arguments: dict[str, Any]
    id: str = ""

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "arguments": self.arguments, "id": self.id}


@dataclass(frozen=True)
class ChatResponse:
    content: str
    thinking: str = ""
    done_reason: str | None = "stop"
    prompt_tokens: int = 0
    completion_tokens: int = 0
    total_duration_s: float = 0.0
    load_duration_s: float = 0.0
    eval_duration_s: float = 0.0
    wall_time_s: float = 0.0
    attempts: int = 1
    endpoint: str = ""
    tool_calls: tuple[ToolCall, ...] = ()
    reasoning_tokens: int = 0  # of completion_tokens, where the API says (OpenAI's reasoning models)
    signature: str = ""  # Anthropic's signature of the thinking, sent back with it in a tool-use turn

    @property
    def truncated(self) -> bool:
        return self.done_reason in ("length", "max_tokens")

    @property
    def context_used(self) -> int:
        return self.prompt_tokens + self.completion_tokens

    def meta(self) -> dict[str, Any]:
        return {
            "done_reason": self.done_reason,
            "truncated": self.truncated,
            "prompt_tokens": self.prompt_tokens,
            "completion_tokens": self.completion_tokens,
            "reasoning_tokens": self.reasoning_tokens,
            "context_used": self.context_used,
            "total_duration_s": round(self.total_duration_s, 4),
            "load_duration_s": round(self.load_duration_s, 4),
            "eval_duration_s": round(self.eval_duration_s, 4),
            "wall_time_s": round(self.wall_time_s, 4),
            "attempts": self.attempts,
            "endpoint": self.endpoint,
            "thinking_chars": len(self.thinking),
        }


class LLMError(Exception):
    """A request that could not be answered: an infrastructure failure, not a model failure."""

    def __init__(self, message: str, *, transient: bool, status: int | None = None,
                 retry_after: float | None = None) -> None:
        super().__init__(message)
        self.transient = transient
        self.status = status
        self.retry_after = retry_after


class ContextExceeded(LLMError):
    """The server refused a prompt that its context cannot hold together with the answer limit.

    Neither the model's failure (it never saw the prompt) nor a passing one (the same server will
    refuse the same prompt every time): the task is not graded, the run says so once with the
    numbers, and ``--resume`` asks again only on a server the user names (``--host``).
    """

    def __init__(self, message: str, *, prompt_tokens: int | None, context: int | None, answer_limit: int,
                 host: str, status: int | None = 400) -> None:
        super().__init__(message, transient=False, status=status)
        self.prompt_tokens = prompt_tokens
        self.context = context
        self.answer_limit = answer_limit
        self.host = host

    def to_json(self) -> dict[str, Any]:
        return {"prompt_tokens": self.prompt_tokens, "context": self.context, "answer_limit": self.answer_limit,
                "host": self.host}


class Backend(Protocol):
    name: str

    async def chat(self, request: ChatRequest) -> ChatResponse: ...

    async def aclose(self) -> None: ...


BACKENDS = ("ollama", "openai", "anthropic", "gold", "scripted")
#: backends that answer in this process, with no server to probe or preflight for
LOCAL_BACKENDS = ("gold", "scripted")
DEFAULT_HOSTS = {"ollama": "http://127.0.0.1:11434", "openai": "https://api.openai.com/v1",
                 "anthropic": "https://api.anthropic.com", "gold": "gold", "scripted": "scripted"}
KEY_VARIABLES = {"openai": "OPENAI_API_KEY", "anthropic": "ANTHROPIC_API_KEY"}


def backend_for(model: str, asked: str | None) -> str:
    """The backend a model name needs: ``gold`` and the scripted models (``scripted:p=P``,
    ``scripted-same:p=P``, ``designer``) answer in this process whatever backend was asked; others take the one
    asked, Ollama by default."""
    if model == "gold":
        return "gold"
    if model.startswith("scripted") or model == "designer":
        return "scripted"
    return asked or "ollama"


def api_key(settings: LLMSettings) -> str | None:
    """The key from the environment variable the settings name, or the backend's conventional one."""
    import os

    variable = settings.api_key_env or KEY_VARIABLES.get(settings.backend)
    return os.environ.get(variable) if variable else None
