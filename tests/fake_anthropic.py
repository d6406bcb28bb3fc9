"""Anthropic's Messages API as a fake on 127.0.0.1: the answer and error bodies, status codes and
headers the real API sends, and its key check (401 ``authentication_error`` without a valid key).
The routes and the scripted responder are FakeOllama's."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from aiohttp import web
from fake_ollama import FakeOllama


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


@dataclass
class FakeAnthropic(FakeOllama):
    key: str = "sk-ant-test"

    def refuse(self, request: web.Request) -> web.StreamResponse | None:
        given = request.headers.get("x-api-key") or request.headers.get("authorization", "").removeprefix("Bearer ")
        if given != self.key:
            status, body, headers = anthropic_error(401, "authentication_error", "invalid x-api-key")
            return web.json_response(body, status=status, headers=headers)
        return None
