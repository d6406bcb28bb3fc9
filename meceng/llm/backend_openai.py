"""The OpenAI backend: ``/v1/chat/completions`` of OpenAI's API and of compatible servers (vLLM,
SGLang, llama.cpp's servers, LM Studio, Ollama's ``/v1``).

Hand-written rather than on the ``openai`` SDK: the scheduler already does what the SDK would add
(retries with Retry-After, per-endpoint slots), the compatible servers answer with fields the
SDK's types do not declare (``reasoning_content``), and a plain client keeps one error path for
every server. On aiohttp, as the Ollama backend, not httpx: httpcore's pool scans its connections
for every request event (for each idle connection, all of them), so a pool as large as a GPU
server's slots cost the harness 52 ms of CPU per request at 256 slots and kept a fake server with
256 slots of 2 s at 6 % of its throughput (httpx's default pool of 100: 21 %, capped at 100 in
flight); aiohttp: 0.4 ms and 94 % (issue 35).
"""

from __future__ import annotations

import json
import re
import time
from typing import Any

import aiohttp

from meceng.llm.messages import IMAGE_MEDIA_TYPE, pictures_after_tool_results
from meceng.llm.scheduler import KEEPALIVE_S, TRANSIENT_STATUS, Endpoint, EndpointBackend
from meceng.llm.types import (
    ChatRequest,
    ChatResponse,
    ContextExceeded,
    LLMError,
    LLMSettings,
    ToolCall,
    parse_retry_after,
)
from meceng.logs import get_logger

log = get_logger(__name__)

# OpenAI's own API (and Azure's copy of it): the answer limit is max_completion_tokens, and its
# reasoning models refuse the deprecated max_tokens
OPENAI_API_HOSTS = ("api.openai.com", "openai.azure.com")


def answer_limit_fields(host: str, limit: int) -> dict[str, int]:
    """The request fields that carry the answer limit to this host.

    OpenAI's API takes ``max_completion_tokens`` only. Compatible servers differ (docs/servers.md):
    vLLM and SGLang read both fields (``max_completion_tokens`` first), llama.cpp's C++ server both
    since 2026, llama-cpp-python's server, LM Studio and Ollama's ``/v1`` only ``max_tokens``. An
    ignored limit lets every answer run to the end of the context, so both go to every other server
    (with the same value, whichever a server reads gives the run's limit).
    """
    if any(name in host for name in OPENAI_API_HOSTS):
        return {"max_completion_tokens": limit}
    return {"max_tokens": limit, "max_completion_tokens": limit}


class OpenAIBackend(EndpointBackend):
    """An OpenAI-compatible ``/v1/chat/completions`` server (vLLM, SGLang, llama.cpp server).

    Same scheduler as Ollama; ``hosts`` are base URLs ending in ``/v1``. Sends the answer limit as
    each server reads it (``answer_limit_fields``), ``temperature`` and ``seed`` (neither with
    ``api_defaults``: OpenAI's reasoning models refuse any temperature but their default) and, when
    thinking is low, medium or high, ``reasoning_effort``; reads ``reasoning_content`` /
    ``reasoning``, ``finish_reason`` (``length`` = truncated) and the reasoning tokens of
    ``usage.completion_tokens_details``. A prompt the server's context cannot hold is a
    ``ContextExceeded``, logged once per run with its numbers.
    """

    name = "openai"

    def __init__(self, settings: LLMSettings, api_key: str | None = None) -> None:
        if not api_key and any("api.openai.com" in host for host in settings.hosts):
            raise ValueError(f"OpenAI's API needs a key: set {settings.api_key_env or 'OPENAI_API_KEY'}")
        self._headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        super().__init__(settings)
        self._session: aiohttp.ClientSession | None = None
        self._overflow_told = False

    def _http(self) -> aiohttp.ClientSession:
        """The shared session, made inside the running loop at the first request (after a sweep's
        ``share_slots``): one connection per slot on each host, kept alive between requests."""
        if self._session is None:
            pool = max(e.capacity for e in self.endpoints)
            self._session = aiohttp.ClientSession(
                headers=self._headers,
                connector=aiohttp.TCPConnector(limit=pool * len(self.endpoints), limit_per_host=pool,
                                               keepalive_timeout=KEEPALIVE_S),
                timeout=aiohttp.ClientTimeout(total=self.settings.timeout_s))
        return self._session

    def request_body(self, host: str, request: ChatRequest) -> dict[str, Any]:
        """The JSON body of one request to ``host``."""
        body: dict[str, Any] = {
            "model": self.settings.model, "messages": _wire_messages(request.messages), "stream": False,
            **answer_limit_fields(host, self.settings.num_predict),
        }
        if not self.settings.api_defaults:
            body["temperature"] = self.settings.temperature
            seed = self.settings.sample_seed(request.sample)
            if seed is not None:
                body["seed"] = seed
        if isinstance(self.settings.think, str):
            body["reasoning_effort"] = self.settings.think
        if request.tools:
            body["tools"] = [{"type": "function", "function": tool} for tool in request.tools]
        return body

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        body = self.request_body(endpoint.host, request)
        t0 = time.perf_counter()
        try:
            async with self._http().post(f"{endpoint.host}/chat/completions", json=body) as response:
                payload = await response.read()
                status, retry_after = response.status, response.headers.get("retry-after")
        except (aiohttp.ClientError, OSError, TimeoutError) as exc:
            self._note_silence(endpoint)
            raise LLMError(f"connection to {endpoint.host} failed: {type(exc).__name__}: {exc}",
                           transient=True) from exc
        text = payload.decode(errors="replace")
        if status >= 400:
            overflow = context_exceeded(status, text, endpoint.host, self.settings.num_predict)
            if overflow is not None:
                self._tell_overflow(overflow, request)
                raise overflow
            transient = status in TRANSIENT_STATUS
            self._note_failure(endpoint, transient)
            raise LLMError(f"server error {status}: {text[:300]}", transient=transient, status=status,
                           retry_after=parse_retry_after(retry_after))
        try:
            data = json.loads(payload)
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
        completion_tokens = int(usage.get("completion_tokens") or 0)
        done_reason = choice.get("finish_reason")
        if completion_tokens >= self.settings.num_predict:
            # cut by the limit whatever the server calls it: llama-cpp-python says "tool_calls" for a
            # forced call whose arguments the limit cut off mid-JSON
            done_reason = "length"
        return ChatResponse(
            tool_calls=tuple(calls),
            content=message.get("content") or "",
            thinking=message.get("reasoning_content") or message.get("reasoning") or "",
            done_reason=done_reason,
            prompt_tokens=int(usage.get("prompt_tokens") or 0),
            completion_tokens=completion_tokens,
            reasoning_tokens=int((usage.get("completion_tokens_details") or {}).get("reasoning_tokens") or 0),
            total_duration_s=wall,
            wall_time_s=wall,
            endpoint=host,
        )

    def _tell_overflow(self, overflow: ContextExceeded, request: ChatRequest) -> None:
        """Once per run at warning level (every task would say the same), then quietly."""
        level = log.debug if self._overflow_told else log.warning
        self._overflow_told = True
        level("prompt does not fit the server's context", task=request.task_key, purpose=request.purpose,
              **overflow.to_json())

    async def aclose(self) -> None:
        if self._session is not None:
            await self._session.close()
            self._session = None


# how the servers word it: OpenAI, vLLM and llama-cpp-python ("maximum context length is 4096 tokens.
# However, you requested 5700 tokens (5636 in the messages, 64 in the completion)"), newer vLLM
# ("request has 3000 input tokens"), SGLang ("3000 tokens from the input messages"), llama.cpp's
# C++ server (type exceed_context_size_error with n_prompt_tokens and n_ctx)
_OVERFLOW_WORDS = re.compile(r"context[ _](length|size|window)", re.IGNORECASE)
_CONTEXT_NUMBER = re.compile(r"(?:maximum context length|context length|context window)\D{0,20}?(\d+)",
                             re.IGNORECASE)
_PROMPT_NUMBER = re.compile(r"(\d+) (?:tokens )?(?:in the messages|input tokens|tokens from the input)"
                            r"|the input \((\d+) tokens\)", re.IGNORECASE)


def context_exceeded(status: int, text: str, host: str, answer_limit: int) -> ContextExceeded | None:
    """The server's refusal of a prompt too long for its context, with the numbers it gave; None
    for any other error."""
    if status not in (400, 413):
        return None
    try:
        body = json.loads(text)
    except ValueError:
        body = None
    error = body.get("error", body) if isinstance(body, dict) else None
    error = error if isinstance(error, dict) else {}
    message = str(error.get("message") or text)
    marked = error.get("code") == "context_length_exceeded" or error.get("type") == "exceed_context_size_error"
    if not marked and not _OVERFLOW_WORDS.search(message):
        return None
    context = error.get("n_ctx") or _first_number(_CONTEXT_NUMBER, message)
    prompt = error.get("n_prompt_tokens") or _first_number(_PROMPT_NUMBER, message)
    needed = f"{int(prompt) + answer_limit:,}" if prompt else f"the prompt's tokens + {answer_limit:,}"
    said = (f"the prompt does not fit the server's context: {_count(prompt)} prompt tokens + {answer_limit:,} answer "
            f"limit > {_count(context)} context at {host}; a server with a context of at least {needed} tokens "
            f"can answer it (server said: {message[:200]})")
    return ContextExceeded(said, prompt_tokens=int(prompt) if prompt else None,
                           context=int(context) if context else None, answer_limit=answer_limit, host=host,
                           status=status)


def _first_number(pattern: re.Pattern[str], text: str) -> int | None:
    match = pattern.search(text)
    if match is None:
        return None
    return int(next(group for group in match.groups() if group))


def _count(value: int | None) -> str:
    return f"{int(value):,}" if value else "?"


def _wire_messages(messages: tuple[dict[str, Any], ...]) -> list[dict[str, Any]]:
    """The agent's conversation in OpenAI's form: calls with ids and JSON-string arguments,
    results answering a ``tool_call_id``; a tool message takes text only, so its pictures follow
    the turn's results in a user message of ``image_url`` parts (base64 data URLs)."""
    wire = []
    for message in pictures_after_tool_results(messages):
        if message["role"] == "tool":
            wire.append({"role": "tool", "tool_call_id": message["tool_call_id"], "content": message["content"]})
        elif message["role"] == "assistant":
            turn: dict[str, Any] = {"role": "assistant", "content": message["content"]}
            if message.get("tool_calls"):
                turn["tool_calls"] = [{"id": c["id"], "type": "function",
                                       "function": {"name": c["name"], "arguments": json.dumps(c["arguments"])}}
                                      for c in message["tool_calls"]]
            wire.append(turn)
        elif message.get("images"):
            wire.append({"role": message["role"], "content": [
                {"type": "text", "text": message["content"]},
                *({"type": "image_url", "image_url": {"url": f"data:{IMAGE_MEDIA_TYPE};base64,{image}"}}
                  for image in message["images"])]})
        else:
            wire.append(message)
    return wire
