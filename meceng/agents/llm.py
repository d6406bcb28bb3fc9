"""Language-model backends behind one async interface, and the per-endpoint scheduler.

``ollama`` talks to one or more Ollama servers (``/api/chat``, ``stream: false``) over aiohttp;
``gold`` answers every request with the ground truth, which proves the harness end to end on a
machine without a model (like SWE-bench's gold patches).

The scheduler keeps at most ``batch_size`` requests in flight per endpoint (Ollama queues
silently beyond its parallel slots, then answers 503) and retries transient failures —
connection errors, timeouts, 408/429/5xx — with exponential backoff. Other 4xx errors (unknown
model, unsupported option) are permanent and never retried.
"""

from __future__ import annotations

import asyncio
import heapq
import json
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import aiohttp
import httpx
from tenacity import AsyncRetrying, RetryCallState, retry_if_exception, stop_after_attempt, wait_exponential

from meceng.logs import get_logger

log = get_logger(__name__)

TRANSIENT_STATUS = frozenset({408, 425, 429, 500, 502, 503, 504})



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

    def options(self) -> dict[str, Any]:
        opts: dict[str, Any] = {
            "temperature": self.temperature,
            "num_ctx": self.num_ctx,
            "num_predict": self.num_predict,
        }
        if self.seed is not None:
            opts["seed"] = self.seed
        return opts

    def to_json(self) -> dict[str, Any]:
        return {
            "model": self.model, "backend": self.backend, "hosts": list(self.hosts),
            "temperature": self.temperature, "seed": self.seed, "think": self.think,
            "num_ctx": self.num_ctx, "num_predict": self.num_predict, "keep_alive": self.keep_alive,
            "batch_size": self.batch_size, "timeout_s": self.timeout_s, "max_attempts": self.max_attempts,
        }


@dataclass(frozen=True)
class ChatRequest:
    """One chat call. ``gold`` is the expected answer; only the gold backend reads it."""

    messages: tuple[dict[str, Any], ...]
    purpose: str
    task_key: str
    gold: str | None = None
    tools: tuple[dict[str, Any], ...] = ()  # JSON-schema function definitions for native tool calling

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

    @property
    def truncated(self) -> bool:
        return self.done_reason == "length"

    @property
    def context_used(self) -> int:
        return self.prompt_tokens + self.completion_tokens

    def meta(self) -> dict[str, Any]:
        return {
            "done_reason": self.done_reason,
            "truncated": self.truncated,
            "prompt_tokens": self.prompt_tokens,
            "completion_tokens": self.completion_tokens,
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


class Backend(Protocol):
    name: str

    async def chat(self, request: ChatRequest) -> ChatResponse: ...

    async def aclose(self) -> None: ...


class GoldBackend:
    """Answers with the ground truth: the required components and the reference program."""

    name = "gold"

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.gold is None:
            raise LLMError(f"no gold answer for {request.purpose} of {request.task_key}", transient=False)
        return ChatResponse(content=request.gold, done_reason="stop", endpoint="gold")

    async def aclose(self) -> None:
        return None


class PrioritySlots:
    """A semaphore that serves waiters by priority, then arrival.

    Code-generation requests (priority 0) of tasks that already chose their components go before
    selection requests (priority 1) of new tasks: tasks finish depth-first, so their evaluation
    overlaps the remaining inference instead of waiting for every selection to be done.
    """

    def __init__(self, capacity: int) -> None:
        self.free = capacity
        self._waiters: list[tuple[int, int, asyncio.Future[None]]] = []
        self._seq = 0

    async def acquire(self, priority: int) -> None:
        if self.free > 0 and not self._waiters:
            self.free -= 1
            return
        future: asyncio.Future[None] = asyncio.get_running_loop().create_future()
        self._seq += 1
        heapq.heappush(self._waiters, (priority, self._seq, future))
        try:
            await future
        except asyncio.CancelledError:
            if future.done() and not future.cancelled():
                self.release()  # the slot was handed over just as we were cancelled
            else:
                self._waiters = [w for w in self._waiters if w[2] is not future]
                heapq.heapify(self._waiters)
            raise

    def release(self) -> None:
        while self._waiters:
            _, _, future = heapq.heappop(self._waiters)
            if not future.done():
                future.set_result(None)  # hand the slot over directly
                return
        self.free += 1


PRIORITY = {"code": 0, "select": 1}


@dataclass
class Endpoint:
    host: str
    client: Any
    slots: PrioritySlots
    capacity: int
    in_flight: int = 0
    failures: int = 0
    disabled_until: float = 0.0

    @property
    def free(self) -> int:
        return self.capacity - self.in_flight


def _is_transient(exc: BaseException) -> bool:
    return isinstance(exc, LLMError) and exc.transient


class OllamaBackend:
    """Ollama's ``/api/chat``, spread over one or more hosts.

    The wire is aiohttp, one session (keep-alive pool) for all hosts: the ``ollama`` package's
    httpx client cost 3-15 ms of the harness's CPU per request and kept a 256-slot server at 22 %
    of its throughput (httpcore's pool scans every connection per request); aiohttp costs ~0.5 ms.
    ``client_factory`` gives each endpoint a client of its own instead (OpenAI-compatible servers).
    """

    name = "ollama"

    def __init__(self, settings: LLMSettings, client_factory: Any = None) -> None:
        self.settings = settings
        self.endpoints = [
            Endpoint(host=h.rstrip("/"), client=client_factory(h) if client_factory else None,
                     slots=PrioritySlots(settings.batch_size), capacity=settings.batch_size)
            for h in settings.hosts
        ]
        self._pick_lock = asyncio.Lock()
        self._session: aiohttp.ClientSession | None = None

    def _http(self) -> aiohttp.ClientSession:
        """The shared session, made inside the running loop; the slots bound its connections."""
        if self._session is None:
            self._session = aiohttp.ClientSession(
                connector=aiohttp.TCPConnector(limit=0, keepalive_timeout=60),
                timeout=aiohttp.ClientTimeout(total=self.settings.timeout_s))
        return self._session

    async def chat(self, request: ChatRequest) -> ChatResponse:
        attempts = 0
        backoff = wait_exponential(multiplier=self.settings.backoff_s, max=60)

        def wait(state: RetryCallState) -> float:
            exc = state.outcome.exception() if state.outcome else None
            if isinstance(exc, LLMError) and exc.retry_after is not None:
                return min(exc.retry_after, 120.0)  # the server said when; believe it, within reason
            return backoff(state)

        retrying = AsyncRetrying(
            retry=retry_if_exception(_is_transient),
            stop=stop_after_attempt(self.settings.max_attempts),
            wait=wait,
            reraise=True,
        )
        async for attempt in retrying:
            with attempt:
                attempts += 1
                response = await self._chat_once(request)
                return _with_attempts(response, attempts)
        raise AssertionError("unreachable")  # pragma: no cover

    def _choose(self) -> Endpoint:
        now = time.monotonic()
        usable = [e for e in self.endpoints if e.disabled_until <= now] or self.endpoints
        return max(usable, key=lambda e: (e.free, -e.failures))

    async def _chat_once(self, request: ChatRequest) -> ChatResponse:
        async with self._pick_lock:
            endpoint = self._choose()
            endpoint.in_flight += 1
        await endpoint.slots.acquire(PRIORITY.get(request.purpose, 1))
        try:  # the slot is held for exactly one request
            raw, wall = await self._send(endpoint, request)
        finally:
            endpoint.slots.release()
            endpoint.in_flight -= 1
        endpoint.failures = 0
        return self._convert(raw, wall, endpoint.host)

    def _convert(self, raw: Any, wall: float, host: str) -> ChatResponse:
        return _from_ollama(raw, wall, host)

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        body: dict[str, Any] = {
            "model": self.settings.model, "messages": list(request.messages), "stream": False,
            "options": self.settings.options(), "keep_alive": self.settings.keep_alive,
        }
        if self.settings.think is not None:
            body["think"] = self.settings.think
        if request.tools:
            body["tools"] = [{"type": "function", "function": tool} for tool in request.tools]
        t0 = time.perf_counter()
        try:
            async with self._http().post(f"{endpoint.host}/api/chat", json=body) as response:
                payload = await response.read()
                status, retry_after = response.status, parse_retry_after(response.headers.get("Retry-After"))
        except (aiohttp.ClientError, OSError, TimeoutError) as exc:
            self._note_failure(endpoint, True)
            raise LLMError(f"connection to {endpoint.host} failed: {type(exc).__name__}: {exc}",
                           transient=True) from exc
        if status >= 400:
            transient = status in TRANSIENT_STATUS
            self._note_failure(endpoint, transient)
            raise LLMError(f"ollama error {status}: {_error_text(payload)}", transient=transient, status=status,
                           retry_after=retry_after)
        try:
            raw = json.loads(payload)
            raw["message"]["content"]
        except (ValueError, KeyError, TypeError) as exc:  # malformed body from the server
            self._note_failure(endpoint, True)
            raise LLMError(f"malformed response from {endpoint.host}: {type(exc).__name__}: {exc}",
                           transient=True) from exc
        return raw, time.perf_counter() - t0

    def _note_failure(self, endpoint: Endpoint, transient: bool) -> None:
        if transient:
            endpoint.failures += 1
            if endpoint.failures >= 3:
                endpoint.disabled_until = time.monotonic() + min(60.0, 5.0 * endpoint.failures)
                log.warning("endpoint taken out", host=endpoint.host, failures=endpoint.failures)

    async def aclose(self) -> None:
        if self._session is not None:
            await self._session.close()
            self._session = None


def _error_text(payload: bytes) -> str:
    """Ollama's error body is ``{"error": "..."}``; anything else is shown as it came."""
    try:
        return str(json.loads(payload)["error"])
    except (ValueError, KeyError, TypeError):
        return payload.decode(errors="replace")[:300]


def _ns(value: Any) -> float:
    return float(value or 0) / 1e9


def _from_ollama(raw: dict[str, Any], wall: float, host: str) -> ChatResponse:
    message = raw["message"]
    calls = tuple(
        ToolCall(name=str(c.get("function", {}).get("name", "")), arguments=dict(c.get("function", {}).get("arguments")
                                                                                  or {}))
        for c in (message.get("tool_calls") or ())
    )
    return ChatResponse(
        tool_calls=calls,
        content=message.get("content") or "",
        thinking=message.get("thinking") or "",
        done_reason=raw.get("done_reason"),
        prompt_tokens=int(raw.get("prompt_eval_count") or 0),
        completion_tokens=int(raw.get("eval_count") or 0),
        total_duration_s=_ns(raw.get("total_duration")),
        load_duration_s=_ns(raw.get("load_duration")),
        eval_duration_s=_ns(raw.get("eval_duration")),
        wall_time_s=wall,
        endpoint=host,
    )


def _with_attempts(response: ChatResponse, attempts: int) -> ChatResponse:
    if attempts == 1:
        return response
    from dataclasses import replace

    return replace(response, attempts=attempts)


class OpenAIBackend(OllamaBackend):
    """An OpenAI-compatible ``/v1/chat/completions`` server (vLLM, SGLang, llama.cpp server).

    Same scheduler as Ollama; ``hosts`` are base URLs ending in ``/v1``. Sends
    ``max_completion_tokens``, ``temperature``, ``seed`` and, when thinking is set, ``reasoning_effort``;
    reads ``reasoning_content`` / ``reasoning`` and ``finish_reason`` (``length`` = truncated).
    """

    name = "openai"

    def __init__(self, settings: LLMSettings, api_key: str | None = None) -> None:
        headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        super().__init__(settings, client_factory=lambda host: httpx.AsyncClient(
            base_url=host.rstrip("/"), timeout=settings.timeout_s, headers=headers))

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        body: dict[str, Any] = {
            "model": self.settings.model, "messages": list(request.messages), "stream": False,
            "temperature": self.settings.temperature, "max_completion_tokens": self.settings.num_predict,
        }
        if self.settings.seed is not None:
            body["seed"] = self.settings.seed
        if isinstance(self.settings.think, str):
            body["reasoning_effort"] = self.settings.think
        if request.tools:
            body["tools"] = [{"type": "function", "function": tool} for tool in request.tools]
        t0 = time.perf_counter()
        try:
            response = await endpoint.client.post("/chat/completions", json=body)
        except (httpx.TransportError, TimeoutError) as exc:
            self._note_failure(endpoint, True)
            raise LLMError(f"connection to {endpoint.host} failed: {type(exc).__name__}: {exc}",
                           transient=True) from exc
        if response.status_code >= 400:
            transient = response.status_code in TRANSIENT_STATUS
            self._note_failure(endpoint, transient)
            raise LLMError(f"server error {response.status_code}: {response.text[:300]}", transient=transient,
                           status=response.status_code,
                           retry_after=parse_retry_after(response.headers.get("retry-after")))
        try:
            data = response.json()
            data["choices"][0]["message"]
        except (ValueError, KeyError, IndexError, TypeError) as exc:
            self._note_failure(endpoint, True)
            raise LLMError(f"malformed response from {endpoint.host}: {exc}", transient=True) from exc
        return data, time.perf_counter() - t0

    def _convert(self, raw: Any, wall: float, host: str) -> ChatResponse:
        choice = raw["choices"][0]
        message = choice["message"]
        usage = raw.get("usage") or {}
        calls = []
        for call in message.get("tool_calls") or ():
            function = call.get("function", {})
            try:
                arguments = json.loads(function.get("arguments") or "{}")
            except ValueError:
                arguments = {"_unparsed": function.get("arguments")}
            calls.append(ToolCall(name=function.get("name", ""), arguments=arguments, id=call.get("id", "")))
        return ChatResponse(
            tool_calls=tuple(calls),
            content=message.get("content") or "",
            thinking=message.get("reasoning_content") or message.get("reasoning") or "",
            done_reason=choice.get("finish_reason"),
            prompt_tokens=int(usage.get("prompt_tokens") or 0),
            completion_tokens=int(usage.get("completion_tokens") or 0),
            total_duration_s=wall,
            wall_time_s=wall,
            endpoint=host,
        )

    async def aclose(self) -> None:
        for endpoint in self.endpoints:
            await endpoint.client.aclose()
        await super().aclose()


def make_backend(settings: LLMSettings) -> Backend:
    if settings.backend == "gold":
        return GoldBackend()
    if settings.backend == "ollama":
        return OllamaBackend(settings)
    if settings.backend == "openai":
        import os

        return OpenAIBackend(settings, api_key=os.environ.get("MECENG_OPENAI_API_KEY"))
    raise ValueError(f"unknown backend {settings.backend!r} (choose gold, ollama or openai)")


def user_messages(*texts: str) -> tuple[dict[str, str], ...]:
    return tuple({"role": "user", "content": t} for t in texts)


__all__: Sequence[str] = [
    "Backend", "ChatRequest", "ChatResponse", "GoldBackend", "LLMError", "LLMSettings", "OllamaBackend",
    "make_backend", "user_messages",
]
