"""A fake Ollama server speaking the real HTTP API (``POST /api/chat``) on 127.0.0.1.

The tests script its behaviour with a ``responder(body) -> (status, json, headers)`` callable;
the server records every request body it received. It binds an ephemeral port on loopback only.
Before the responder sees a request, the server refuses (400, in the API's own error shape) what
the real API refuses: on ``/api/chat`` an unknown role or an ``images`` entry that is no base64
picture; on the OpenAI-compatible route a tool answer that does not directly follow the assistant
turn that called it, an unanswered call, a tool message with anything but text, an image part that
is not a base64 data URL of a picture of its media type.
"""

from __future__ import annotations

import asyncio
import base64
import binascii
import json
import re
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


SIGNATURES = {"image/png": b"\x89PNG\r\n\x1a\n", "image/jpeg": b"\xff\xd8\xff", "image/gif": b"GIF8",
              "image/webp": b"RIFF"}
DATA_URL = re.compile(r"data:(?P<media_type>[\w/+.-]+);base64,(?P<data>.*)", re.DOTALL)


def picture_problem(data: Any, media_types: tuple[str, ...] = tuple(SIGNATURES)) -> str | None:
    """What is wrong with a base64 picture that should be of one of ``media_types``; None: nothing."""
    if not isinstance(data, str):
        return "image data must be a base64 string"
    try:
        raw = base64.b64decode(data, validate=True)
    except (binascii.Error, ValueError):
        return "image data is not valid base64"
    if not any(raw.startswith(SIGNATURES[m]) for m in media_types):
        return f"image data is not {' or '.join(media_types)}"
    return None


def ollama_problem(body: dict[str, Any]) -> str | None:
    """What ``/api/chat`` refuses: a role it does not know, images that are not base64 pictures."""
    for n, message in enumerate(body.get("messages") or ()):
        if message.get("role") not in ("system", "user", "assistant", "tool"):
            return f"messages[{n}]: invalid role {message.get('role')!r}"
        if not isinstance(message.get("content", ""), str):
            return f"messages[{n}]: content must be a string"
        for image in message.get("images") or ():
            problem = picture_problem(image, ("image/png", "image/jpeg"))
            if problem:
                return f"messages[{n}]: {problem}"
    return None


def openai_problem(body: dict[str, Any]) -> str | None:
    """What Chat Completions refuses in ``messages``: tool answers out of place or unanswered
    calls, content parts a role does not take, image parts that are not pictures."""
    awaiting: list[str] = []  # the calls of the last assistant turn not answered yet
    after_calls = False  # the previous message is that turn or one of its answers
    for n, message in enumerate(body.get("messages") or ()):
        role = message.get("role")
        if role == "tool":
            if not after_calls or message.get("tool_call_id") not in awaiting:
                return (f"messages[{n}]: messages with role 'tool' must be a response to a preceding message "
                        "with 'tool_calls'")
            awaiting.remove(message["tool_call_id"])
        elif awaiting:
            return ("An assistant message with 'tool_calls' must be followed by tool messages responding to each "
                    f"'tool_call_id'. The following tool_call_ids did not have response messages: {awaiting}")
        if role not in ("system", "developer", "user", "assistant", "tool"):
            return f"messages[{n}]: invalid role {role!r}"
        problem = _parts_problem(message.get("content"), ("text", "image_url") if role == "user" else ("text",))
        if problem:
            return f"messages[{n}] ({role}): {problem}"
        if role == "assistant":
            awaiting = [call["id"] for call in message.get("tool_calls") or ()]
        after_calls = role == "tool" or bool(awaiting)
    if awaiting:
        return f"tool_call_ids without response messages: {awaiting}"
    return None


def _parts_problem(content: Any, kinds: tuple[str, ...]) -> str | None:
    """A message's content: a string, or parts of the kinds its role takes (images as data URLs)."""
    if content is None or isinstance(content, str):
        return None
    if not isinstance(content, list):
        return "content must be a string or a list of content parts"
    for part in content:
        kind = part.get("type")
        if kind not in kinds:
            return f"content part type {kind!r} is not supported here (only {', '.join(kinds)})"
        if kind == "text" and not isinstance(part.get("text"), str):
            return "a text part needs its text"
        if kind == "image_url":
            url = (part.get("image_url") or {}).get("url")
            found = DATA_URL.fullmatch(url) if isinstance(url, str) else None
            if found is None or found["media_type"] not in SIGNATURES:
                return "image_url.url must be a data URL of an image (data:image/png;base64,...)"
            problem = picture_problem(found["data"], (found["media_type"],))
            if problem:
                return problem
    return None


@dataclass
class FakeOllama:
    responder: Responder
    requests: list[dict[str, Any]] = field(default_factory=list)
    headers: list[dict[str, str]] = field(default_factory=list)  # of every request, as received
    max_in_flight: int = 0
    _in_flight: int = 0
    _runner: web.AppRunner | None = None
    url: str = ""
    # what the listing routes say (``meceng doctor``): the models served and their context
    models: tuple[str, ...] = ("fake",)
    context: int = 8192

    async def _chat(self, request: web.Request) -> web.StreamResponse:
        raw = await request.read()
        try:
            body = json.loads(raw)
        except ValueError:
            return web.json_response({"error": "invalid JSON"}, status=400)
        self.requests.append(body)
        self.headers.append({k.lower(): v for k, v in request.headers.items()})
        refused = self.refuse(request)
        if refused is None:
            refused = self.check(request.path, body)
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

    async def _listing(self, request: web.Request) -> web.StreamResponse:
        """Ollama's version and tags; the OpenAI-compatible model list as vLLM gives it."""
        if request.path == "/api/version":
            return web.json_response({"version": "0.12.0"})
        if request.path == "/api/tags":
            return web.json_response({"models": [{"name": m if ":" in m else f"{m}:latest"} for m in self.models]})
        return web.json_response({"object": "list", "data": [{"id": m, "object": "model",
                                                              "max_model_len": self.context} for m in self.models]})

    async def _show(self, request: web.Request) -> web.StreamResponse:
        name = (await request.json()).get("model", "")
        if name.split(":")[0] not in {m.split(":")[0] for m in self.models}:
            return web.json_response({"error": f"model '{name}' not found"}, status=404)
        return web.json_response({"model_info": {"llama.context_length": self.context}})

    async def _model(self, request: web.Request) -> web.StreamResponse:
        refused = self.refuse(request)
        if refused is not None:
            return refused
        name = request.match_info["name"]
        if name not in self.models:
            return web.json_response({"type": "error", "error": {"type": "not_found_error",
                                                                  "message": f"model: {name}"}}, status=404)
        return web.json_response({"type": "model", "id": name, "display_name": name,
                                  "created_at": "2026-01-01T00:00:00Z"})

    def refuse(self, request: web.Request) -> web.StreamResponse | None:
        """An answer given before the responder sees the request (authentication); None: go on."""
        return None

    def check(self, path: str, body: dict[str, Any]) -> web.StreamResponse | None:
        """The 400 the real API gives a request it refuses; None: the request is well formed."""
        if path == "/api/chat" and (problem := ollama_problem(body)):
            return web.json_response({"error": problem}, status=400)
        if path == "/v1/chat/completions" and (problem := openai_problem(body)):
            return web.json_response({"error": {"message": problem, "type": "invalid_request_error",
                                                "param": "messages", "code": None}}, status=400)
        return None

    async def __aenter__(self) -> FakeOllama:
        app = web.Application()
        app.router.add_post("/api/chat", self._chat)
        app.router.add_post("/v1/chat/completions", self._chat)  # the OpenAI-compatible route
        app.router.add_post("/v1/messages", self._chat)  # Anthropic's Messages API
        app.router.add_get("/api/version", self._listing)
        app.router.add_get("/api/tags", self._listing)
        app.router.add_post("/api/show", self._show)
        app.router.add_get("/v1/models/{name}", self._model)  # Anthropic's Models API
        app.router.add_get("/v1/models", self._listing)
        self._runner = web.AppRunner(app)
        await self._runner.setup()
        # a listen backlog as large as a real server's (uvicorn: 2048): with aiohttp's 128, a burst of
        # 256 new connections waits out the kernel's SYN retries (1 s, 3 s) for the rest
        site = web.TCPSite(self._runner, "127.0.0.1", 0, backlog=2048)
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
