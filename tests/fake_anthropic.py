"""Anthropic's Messages API as a fake on 127.0.0.1: the answer and error bodies, status codes and
headers the real API sends, its key check (401 ``authentication_error`` without a valid key) and
its checks of ``messages`` (400 ``invalid_request_error``): every ``tool_use`` answered by a
``tool_result`` in the next user turn, results only for the calls of the turn before, a result's
content a string or text and base64 ``image`` blocks whose data is a picture of its media type.
The routes and the scripted responder are FakeOllama's."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from aiohttp import web
from fake_ollama import SIGNATURES, FakeOllama, picture_problem


def anthropic_reply(content: str = "", *, thinking: str | None = None, tool_uses: tuple[dict[str, Any], ...] = (),
                    stop_reason: str = "end_turn", input_tokens: int = 120, output_tokens: int = 60,
                    thinking_tokens: int | None = None) -> dict[str, Any]:
    """A non-streaming ``/v1/messages`` answer; ``tool_uses`` are ``{"id", "name", "input"}``."""
    blocks: list[dict[str, Any]] = []
    if thinking is not None:
        blocks.append({"type": "thinking", "thinking": thinking, "signature": "c2lnbmVkLXRoaW5raW5n"})
    if content:
        blocks.append({"type": "text", "text": content})
    blocks.extend({"type": "tool_use", **use} for use in tool_uses)
    usage: dict[str, Any] = {"input_tokens": input_tokens, "output_tokens": output_tokens,
                             "cache_creation_input_tokens": 0, "cache_read_input_tokens": 0}
    if thinking_tokens is not None:
        usage["output_tokens_details"] = {"thinking_tokens": thinking_tokens}
    return {"id": "msg_01FAKE", "type": "message", "role": "assistant", "model": "claude-x", "content": blocks,
            "stop_reason": stop_reason, "stop_sequence": None, "usage": usage}


def anthropic_error(status: int, kind: str, message: str) -> tuple[int, dict[str, Any], dict[str, str]]:
    """An error as the API answers it, e.g. ``(529, overloaded_error)`` or ``(429, rate_limit_error)``."""
    return status, {"type": "error", "error": {"type": kind, "message": message},
                    "request_id": "req_01FAKE"}, {"request-id": "req_01FAKE"}


def anthropic_problem(body: dict[str, Any]) -> str | None:
    """What ``/v1/messages`` refuses in ``messages``, as the API words it where it matters."""
    calls: list[str] = []  # the tool_use ids of the assistant turn before
    for n, message in enumerate(body.get("messages") or ()):
        role, content = message.get("role"), message.get("content")
        if role not in ("user", "assistant"):
            return f"messages.{n}.role: Input should be 'user' or 'assistant'"
        blocks = content if isinstance(content, list) else []
        results = [b.get("tool_use_id") for b in blocks if b.get("type") == "tool_result"]
        if calls and (role != "user" or set(calls) - set(results)):
            return (f"messages.{n}: `tool_use` ids were found without `tool_result` blocks immediately after: "
                    f"{', '.join(sorted(set(calls) - set(results)))}")
        if set(results) - set(calls):
            return f"messages.{n}: unexpected `tool_use_id` found in `tool_result` blocks: {sorted(set(results))}"
        for k, block in enumerate(blocks):
            problem = _block_problem(block, ("text", "image", "tool_result") if role == "user" else
                                     ("text", "thinking", "tool_use"))
            if problem:
                return f"messages.{n}.content.{k}: {problem}"
        calls = [b["id"] for b in blocks if b.get("type") == "tool_use"] if role == "assistant" else []
    return None


def _block_problem(block: dict[str, Any], kinds: tuple[str, ...]) -> str | None:
    kind = block.get("type")
    if kind not in kinds:
        return f"unexpected block type {kind!r}"
    if kind == "text" and not block.get("text"):
        return "text content blocks must be non-empty"
    if kind == "image":
        source = block.get("source") or {}
        if source.get("type") != "base64" or source.get("media_type") not in SIGNATURES:
            return "image source must be {type: base64, media_type: image/jpeg|png|gif|webp, data}"
        problem = picture_problem(source.get("data"), (source["media_type"],))
        return f"image: {problem}" if problem else None
    if kind == "tool_result" and isinstance(block.get("content"), list):
        for k, inner in enumerate(block["content"]):
            problem = _block_problem(inner, ("text", "image"))
            if problem:
                return f"content.{k}: {problem}"
    elif kind == "tool_result" and not isinstance(block.get("content", ""), str):
        return "tool_result content must be a string or a list of text and image blocks"
    return None


@dataclass
class FakeAnthropic(FakeOllama):
    key: str = "sk-ant-test"

    def refuse(self, request: web.Request) -> web.StreamResponse | None:
        given = request.headers.get("x-api-key") or request.headers.get("authorization", "").removeprefix("Bearer ")
        if given != self.key:
            status, body, headers = anthropic_error(401, "authentication_error", "invalid x-api-key")
            return web.json_response(body, status=status, headers=headers)
        return None

    def check(self, path: str, body: dict[str, Any]) -> web.StreamResponse | None:
        problem = anthropic_problem(body) if path == "/v1/messages" else None
        if problem is None:
            return super().check(path, body)
        status, error, headers = anthropic_error(400, "invalid_request_error", problem)
        return web.json_response(error, status=status, headers=headers)
