"""The OpenAI-compatible backend: ``/v1/chat/completions`` (vLLM, SGLang, llama.cpp server)."""

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
