"""The Anthropic backend: the Messages API through the official ``anthropic`` SDK.

The SDK's async client does the wire work (headers, API version, typed answers); the shared
scheduler does the rest, as for every backend: slots per endpoint, retries of 408/429/5xx and
529 ("overloaded") after the server's ``retry-after``, no retry of other 4xx. The SDK's own
retries are switched off so that a request is retried in one place only.

What is sent: ``max_tokens`` from the answer limit; with thinking on, extended thinking with a
token budget (``True``: three quarters of the answer limit; ``low``/``medium``/``high``: a quarter,
a half, three quarters; at least 1024, which the API requires, with ``max_tokens`` raised to
leave 1024 for the answer); tools as ``tool_use`` definitions. No temperature or seed: the API
version the SDK speaks (2026-10-21) refuses every sampling parameter, so Claude always runs with
its default sampling — the settings of such a run say ``api_defaults``.
"""

from __future__ import annotations

import time
from typing import Any

import anthropic

from meceng.llm.messages import IMAGE_MEDIA_TYPE
from meceng.llm.scheduler import KEEPALIVE_S, TRANSIENT_STATUS, Endpoint, EndpointBackend
from meceng.llm.types import ChatRequest, ChatResponse, LLMError, LLMSettings, ToolCall, parse_retry_after

MIN_THINKING_BUDGET = 1024
BUDGET_SHARE = {True: 0.75, "low": 0.25, "medium": 0.5, "high": 0.75}


def thinking_budget(settings: LLMSettings) -> tuple[int, dict[str, Any] | None]:
    """``max_tokens`` and the ``thinking`` parameter for the run's answer limit and thinking setting."""
    if settings.think in (False, None):
        return settings.num_predict, ({"type": "disabled"} if settings.think is False else None)
    budget = max(MIN_THINKING_BUDGET, int(settings.num_predict * BUDGET_SHARE.get(settings.think, 0.75)))
    return max(settings.num_predict, budget + MIN_THINKING_BUDGET), {"type": "enabled", "budget_tokens": budget}


class AnthropicBackend(EndpointBackend):
    """Anthropic's ``/v1/messages``; ``hosts`` are base URLs (``https://api.anthropic.com``)."""

    name = "anthropic"

    def __init__(self, settings: LLMSettings, api_key: str | None) -> None:
        if not api_key:
            variable = settings.api_key_env or "ANTHROPIC_API_KEY"
            raise ValueError(f"the anthropic backend needs an API key: set {variable}")
        super().__init__(settings, client_factory=lambda host, connections: anthropic.AsyncAnthropic(
            api_key=api_key, base_url=host.rstrip("/"), max_retries=0, timeout=settings.timeout_s,
            http_client=_http_client(connections, settings.timeout_s)))

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        max_tokens, thinking = thinking_budget(self.settings)
        system, messages = _wire_messages(request.messages)
        params: dict[str, Any] = {"model": self.settings.model, "max_tokens": max_tokens, "messages": messages}
        if system:
            params["system"] = system
        if thinking is not None:
            params["thinking"] = thinking
        if request.tools:
            params["tools"] = [{"name": t["name"], "description": t.get("description", ""),
                                "input_schema": t.get("parameters", {"type": "object"})} for t in request.tools]
        t0 = time.perf_counter()
        try:
            message = await endpoint.client.messages.create(**params)
        except anthropic.APIStatusError as exc:
            status = exc.status_code
            transient = status in TRANSIENT_STATUS
            self._note_failure(endpoint, transient)
            raise LLMError(f"anthropic error {status}: {_error_text(exc)}", transient=transient, status=status,
                           retry_after=parse_retry_after(exc.response.headers.get("retry-after"))) from exc
        except anthropic.APIConnectionError as exc:  # also the timeouts
            self._note_silence(endpoint)
            raise LLMError(f"connection to {endpoint.host} failed: {type(exc).__name__}: {exc}",
                           transient=True) from exc
        except anthropic.APIResponseValidationError as exc:
            self._note_failure(endpoint, True)
            raise LLMError(f"malformed response from {endpoint.host}: {exc}", transient=True) from exc
        return message.model_dump(), time.perf_counter() - t0

    def _convert(self, raw: Any, wall: float, host: str) -> ChatResponse:
        texts, thoughts, calls, signature = [], [], [], ""
        for block in raw.get("content") or ():
            kind = block.get("type")
            if kind == "text":
                texts.append(block.get("text") or "")
            elif kind == "thinking":
                thoughts.append(block.get("thinking") or "")
                signature = block.get("signature") or signature
            elif kind == "tool_use":
                calls.append(ToolCall(name=block.get("name", ""), arguments=dict(block.get("input") or {}),
                                      id=block.get("id", "")))
        usage = raw.get("usage") or {}
        prompt = sum(int(usage.get(k) or 0) for k in ("input_tokens", "cache_creation_input_tokens",
                                                       "cache_read_input_tokens"))
        return ChatResponse(
            content="".join(texts), thinking="\n".join(thoughts), signature=signature, tool_calls=tuple(calls),
            done_reason=raw.get("stop_reason"), prompt_tokens=prompt,
            completion_tokens=int(usage.get("output_tokens") or 0),
            reasoning_tokens=int((usage.get("output_tokens_details") or {}).get("thinking_tokens") or 0),
            total_duration_s=wall, wall_time_s=wall, endpoint=host,
        )

    async def aclose(self) -> None:
        for endpoint in self.endpoints:
            await endpoint.client.close()


def _http_client(connections: int, timeout_s: float) -> Any:
    """The SDK's client on its aiohttp transport (``DefaultAioHttpClient``; the SDK vendors the
    transport) with a pool of one connection per slot, kept alive: on the SDK's default httpx
    client, httpcore scans its whole pool on every request event, which at 256 slots costs the
    harness tens of ms of CPU per request (measured on the OpenAI backend, issue 35). ``Limits`` is
    taken from the SDK's default so that it is the class of the httpx the SDK runs on."""
    limits = type(anthropic.DEFAULT_CONNECTION_LIMITS)(max_connections=connections,
                                                        max_keepalive_connections=connections,
                                                        keepalive_expiry=KEEPALIVE_S)
    return anthropic.DefaultAioHttpClient(limits=limits, timeout=timeout_s)


def _error_text(exc: anthropic.APIStatusError) -> str:
    """The API's ``{"type": "error", "error": {"type": ..., "message": ...}}`` as one line."""
    body = exc.body if isinstance(exc.body, dict) else {}
    error = body.get("error") if isinstance(body.get("error"), dict) else None
    if error:
        return f"{error.get('type', 'error')}: {error.get('message', '')}"
    return str(exc.message)[:300]


def _wire_messages(messages: tuple[dict[str, Any], ...]) -> tuple[str, list[dict[str, Any]]]:
    """The agent's conversation in Anthropic's form: the system text apart; an assistant turn as
    content blocks (signed thinking first, text, ``tool_use``); tool results as ``tool_result``
    blocks of one user turn (the API wants consecutive results together), a result's pictures
    inside its block."""
    system: list[str] = []
    wire: list[dict[str, Any]] = []
    for message in messages:
        role = message["role"]
        if role == "system":
            system.append(str(message["content"]))
        elif role == "tool":
            block = {"type": "tool_result", "tool_use_id": message["tool_call_id"], "content": _result_content(message)}
            if wire and wire[-1]["role"] == "user" and isinstance(wire[-1]["content"], list):
                wire[-1]["content"].append(block)
            else:
                wire.append({"role": "user", "content": [block]})
        elif role == "assistant":
            blocks: list[dict[str, Any]] = []
            if message.get("signature"):
                blocks.append({"type": "thinking", "thinking": message.get("thinking", ""),
                               "signature": message["signature"]})
            if message.get("content"):
                blocks.append({"type": "text", "text": message["content"]})
            blocks.extend({"type": "tool_use", "id": c["id"], "name": c["name"], "input": c["arguments"]}
                          for c in message.get("tool_calls") or ())
            wire.append({"role": "assistant", "content": blocks or [{"type": "text", "text": ""}]})
        else:
            wire.append({"role": "user", "content": message["content"]})
    return "\n\n".join(system), wire


def _result_content(message: dict[str, Any]) -> str | list[dict[str, Any]]:
    """A tool result's content: its text, or with pictures a list of blocks — the text (the API
    refuses an empty text block, so none then) and one base64 ``image`` block per picture, which a
    ``tool_result`` may hold as a user turn does."""
    if not message.get("images"):
        return message["content"]
    blocks: list[dict[str, Any]] = [{"type": "text", "text": message["content"]}] if message["content"] else []
    blocks.extend({"type": "image", "source": {"type": "base64", "media_type": IMAGE_MEDIA_TYPE, "data": image}}
                  for image in message["images"])
    return blocks
