"""A fake Ollama server speaking the real HTTP API (``POST /api/chat``) on 127.0.0.1.

The tests script its behaviour with a ``responder(body) -> (status, json, headers)`` callable;
the server records every request body it received. It binds an ephemeral port on loopback only.
"""

from __future__ import annotations

import asyncio
import json
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from typing import Any

from aiohttp import web

Responder = Callable[[dict[str, Any]], Awaitable[tuple[int, Any, dict[str, str]]] | tuple[int, Any, dict[str, str]]]


def chat_reply(content: str, model: str = "fake", done_reason: str = "stop", thinking: str | None = None,
               prompt_tokens: int = 100, completion_tokens: int = 50) -> dict[str, Any]:
    """A non-streaming /api/chat response body as Ollama sends it."""
    message: dict[str, Any] = {"role": "assistant", "content": content}
    if thinking is not None:
        message["thinking"] = thinking
    return {
        "model": model,
        "created_at": "2026-11-21T00:00:00.000000Z",
        "message": message,
        "done": True,
        "done_reason": done_reason,
        "total_duration": 1_500_000_000,
        "load_duration": 100_000_000,
        "prompt_eval_count": prompt_tokens,
        "prompt_eval_duration": 200_000_000,
        "eval_count": completion_tokens,
        "eval_duration": 1_000_000_000,
    }


@dataclass
class FakeOllama:
    responder: Responder
    requests: list[dict[str, Any]] = field(default_factory=list)
    headers: list[dict[str, str]] = field(default_factory=list)  # of every request, as received
    max_in_flight: int = 0
    _in_flight: int = 0
    _runner: web.AppRunner | None = None
    url: str = ""

    async def _chat(self, request: web.Request) -> web.StreamResponse:
        raw = await request.read()
        try:
            body = json.loads(raw)
        except ValueError:
            return web.json_response({"error": "invalid JSON"}, status=400)
        self.requests.append(body)
        self.headers.append({k.lower(): v for k, v in request.headers.items()})
        refused = self.refuse(request)
        if refused is not None:
            return refused
        self._in_flight += 1
        self.max_in_flight = max(self.max_in_flight, self._in_flight)
        try:
            result = self.responder(body)
            if asyncio.iscoroutine(result):
                result = await result
            status, payload, headers = result
        finally:
            self._in_flight -= 1
        if status == -1:  # drop the connection without an answer
            assert request.transport is not None
            request.transport.close()
            return web.Response(status=500)
        if isinstance(payload, str):
            return web.Response(status=status, text=payload, content_type="application/json", headers=headers)
        return web.json_response(payload, status=status, headers=headers)

    def refuse(self, request: web.Request) -> web.StreamResponse | None:
        """An answer given before the responder sees the request (authentication); None: go on."""
        return None

    async def __aenter__(self) -> FakeOllama:
        app = web.Application()
        app.router.add_post("/api/chat", self._chat)
        app.router.add_post("/v1/chat/completions", self._chat)  # the OpenAI-compatible route
        app.router.add_post("/v1/messages", self._chat)  # Anthropic's Messages API
        self._runner = web.AppRunner(app)
        await self._runner.setup()
        site = web.TCPSite(self._runner, "127.0.0.1", 0)
        await site.start()
        port = site._server.sockets[0].getsockname()[1]  # type: ignore[union-attr]
        self.url = f"http://127.0.0.1:{port}"
        return self

    async def __aexit__(self, *exc: object) -> None:
        if self._runner is not None:
            await self._runner.cleanup()


def prompted_instance(instances: list[Any], prompt: str) -> Any:
    """The task instance whose description the prompt holds; an assembly's prompt also holds its
    parts' descriptions, so the longest match is the one asked about."""
    return max((i for i in instances if i.description in prompt), key=lambda i: len(i.description))


def openai_reply(content: str, finish_reason: str = "stop", reasoning: str | None = None,
                 prompt_tokens: int = 100, completion_tokens: int = 50) -> dict[str, Any]:
    """A non-streaming /v1/chat/completions response body as vLLM / llama.cpp send it."""
    message: dict[str, Any] = {"role": "assistant", "content": content}
    if reasoning is not None:
        message["reasoning_content"] = reasoning
    return {"id": "chatcmpl-1", "object": "chat.completion", "created": 0, "model": "fake",
            "choices": [{"index": 0, "message": message, "finish_reason": finish_reason}],
            "usage": {"prompt_tokens": prompt_tokens, "completion_tokens": completion_tokens,
                      "total_tokens": prompt_tokens + completion_tokens}}
