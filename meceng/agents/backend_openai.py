"""The OpenAI backend: ``/v1/chat/completions`` of OpenAI's API and of compatible servers (vLLM,
SGLang, llama.cpp server).

Hand-written on httpx rather than on the ``openai`` SDK: the scheduler already does what the SDK
would add (retries with Retry-After, per-endpoint slots), the compatible servers answer with
fields the SDK's types do not declare (``reasoning_content``), and a plain client keeps one
error path for every server.
"""

from __future__ import annotations

import json
import time
from typing import Any

import httpx

from meceng.agents.llm import ChatRequest, ChatResponse, LLMError, LLMSettings, ToolCall, parse_retry_after
from meceng.agents.scheduler import TRANSIENT_STATUS, Endpoint, EndpointBackend


class OpenAIBackend(EndpointBackend):
    """An OpenAI-compatible ``/v1/chat/completions`` server (vLLM, SGLang, llama.cpp server).

    Same scheduler as Ollama; ``hosts`` are base URLs ending in ``/v1``. Sends
    ``max_completion_tokens``, ``temperature`` and ``seed`` (neither with ``api_defaults``: OpenAI's
    reasoning models refuse any temperature but their default) and, when thinking is low, medium
    or high, ``reasoning_effort``; reads ``reasoning_content`` / ``reasoning``, ``finish_reason``
    (``length`` = truncated) and the reasoning tokens of ``usage.completion_tokens_details``.
    """

    name = "openai"

    def __init__(self, settings: LLMSettings, api_key: str | None = None) -> None:
        if not api_key and any("api.openai.com" in host for host in settings.hosts):
            raise ValueError(f"OpenAI's API needs a key: set {settings.api_key_env or 'OPENAI_API_KEY'}")
        headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        super().__init__(settings, client_factory=lambda host: httpx.AsyncClient(
            base_url=host.rstrip("/"), timeout=settings.timeout_s, headers=headers))

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        body: dict[str, Any] = {
            "model": self.settings.model, "messages": _wire_messages(request.messages), "stream": False,
            "max_completion_tokens": self.settings.num_predict,
        }
        if not self.settings.api_defaults:
            body["temperature"] = self.settings.temperature
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
            reasoning_tokens=int((usage.get("completion_tokens_details") or {}).get("reasoning_tokens") or 0),
            total_duration_s=wall,
            wall_time_s=wall,
            endpoint=host,
        )

    async def aclose(self) -> None:
        for endpoint in self.endpoints:
            await endpoint.client.aclose()


def _wire_messages(messages: tuple[dict[str, Any], ...]) -> list[dict[str, Any]]:
    """The agent's conversation in OpenAI's form: calls with ids and JSON-string arguments,
    results answering a ``tool_call_id``; a tool message takes text only, so its pictures follow
    the turn's results in a user message of ``image_url`` parts (base64 data URLs)."""
    from meceng.agents.llm import IMAGE_MEDIA_TYPE, pictures_after_tool_results

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
