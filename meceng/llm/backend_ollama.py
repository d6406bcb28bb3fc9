"""The Ollama backend: ``/api/chat`` (``stream: false``) over one aiohttp session for all hosts.

aiohttp rather than the ``ollama`` package's httpx client: that cost 3-15 ms of the harness's CPU
per request and kept a 256-slot server at 22 % of its throughput (httpcore's pool scans every
connection per request and keeps 20 alive); aiohttp costs ~0.5 ms (``scripts/bench_scale.py``).
"""

from __future__ import annotations

import json
import time
from typing import Any

import aiohttp

from meceng.llm.messages import pictures_after_tool_results
from meceng.llm.scheduler import KEEPALIVE_S, TRANSIENT_STATUS, Endpoint, EndpointBackend
from meceng.llm.types import ChatRequest, ChatResponse, LLMError, LLMSettings, ToolCall, parse_retry_after


class OllamaBackend(EndpointBackend):
    """Ollama's ``/api/chat``, spread over one or more hosts."""

    name = "ollama"

    def __init__(self, settings: LLMSettings) -> None:
        super().__init__(settings)
        self._session: aiohttp.ClientSession | None = None

    def _http(self) -> aiohttp.ClientSession:
        """The shared session, made inside the running loop: one connection per slot on each host
        (the slots bound the requests; the pool keeps their connections alive between requests)."""
        if self._session is None:
            pool = max(e.capacity for e in self.endpoints)
            self._session = aiohttp.ClientSession(
                connector=aiohttp.TCPConnector(limit=pool * len(self.endpoints), limit_per_host=pool,
                                               keepalive_timeout=KEEPALIVE_S),
                timeout=aiohttp.ClientTimeout(total=self.settings.timeout_s))
        return self._session

    def _convert(self, raw: Any, wall: float, host: str) -> ChatResponse:
        return _from_ollama(raw, wall, host)

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        body: dict[str, Any] = {
            "model": self.settings.model, "messages": _wire_messages(request.messages), "stream": False,
            "options": self.settings.options(request.sample), "keep_alive": self.settings.keep_alive,
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
            self._note_silence(endpoint)
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

    async def aclose(self) -> None:
        if self._session is not None:
            await self._session.close()
            self._session = None


def _wire_messages(messages: tuple[dict[str, Any], ...]) -> list[dict[str, Any]]:
    """The agent's conversation in Ollama's form: calls as ``function`` objects with argument
    dicts, results named by ``tool_name``; the results' pictures as the ``images`` (base64) of a
    user message after them, where every vision model's template shows them."""
    wire = []
    for message in pictures_after_tool_results(messages):
        if message["role"] == "tool":
            wire.append({"role": "tool", "tool_name": message["name"], "content": message["content"]})
        elif message["role"] == "assistant":
            turn: dict[str, Any] = {"role": "assistant", "content": message["content"]}
            if message.get("tool_calls"):
                turn["tool_calls"] = [{"function": {"name": c["name"], "arguments": c["arguments"]}}
                                      for c in message["tool_calls"]]
            wire.append(turn)
        else:
            wire.append(message)
    return wire


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
