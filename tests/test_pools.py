"""Connection pools sized to the batch: at ``--batch-size 256`` every backend has 256 requests in
flight at once on one server (httpx's default pool of 100 connections used to cap the OpenAI
backend at 100, whatever the batch size; the OpenAI and Anthropic backends now run on aiohttp)."""

from __future__ import annotations

import asyncio
import contextlib
from typing import Any

import pytest
from fake_anthropic import FakeAnthropic, anthropic_reply
from fake_ollama import FakeOllama, chat_reply, openai_reply

from meceng.llm.backend_anthropic import AnthropicBackend
from meceng.llm.backend_ollama import OllamaBackend
from meceng.llm.backend_openai import OpenAIBackend
from meceng.llm.messages import user_messages
from meceng.llm.scheduler import EndpointBackend
from meceng.llm.types import ChatRequest, LLMSettings

BATCH = 256
HOLD_S = 3.0  # how long the server holds a request waiting for the batch to fill


class Gate:
    """Holds every request until ``size`` are in the server at once (or ``HOLD_S`` passed), so that
    the server's ``max_in_flight`` is what the client can have open together, not what happened to
    overlap."""

    def __init__(self, size: int, reply: dict[str, Any]) -> None:
        self.size, self.reply, self.arrived = size, reply, 0
        self.full = asyncio.Event()

    async def __call__(self, body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        self.arrived += 1
        if self.arrived >= self.size:
            self.full.set()
        with contextlib.suppress(TimeoutError):
            await asyncio.wait_for(self.full.wait(), HOLD_S)
        return 200, self.reply, {}


def make(kind: str, url: str) -> EndpointBackend:
    common: dict[str, Any] = {"model": "m", "batch_size": BATCH, "backoff_s": 0.01, "timeout_s": 30.0}
    if kind == "openai":
        return OpenAIBackend(LLMSettings(backend="openai", hosts=(url + "/v1",), **common))
    if kind == "anthropic":
        return AnthropicBackend(LLMSettings(backend="anthropic", hosts=(url,), **common), api_key="sk-ant-test")
    return OllamaBackend(LLMSettings(backend="ollama", hosts=(url,), **common))


REPLIES = {"openai": openai_reply("ok"), "anthropic": anthropic_reply("ok"), "ollama": chat_reply("ok")}


@pytest.mark.parametrize("kind", ["openai", "anthropic", "ollama"])
async def test_batch_size_256_has_256_requests_in_flight(kind: str) -> None:
    gate = Gate(BATCH, REPLIES[kind])
    server_type = FakeAnthropic if kind == "anthropic" else FakeOllama
    async with server_type(gate) as server:
        backend = make(kind, server.url)
        try:
            answers = await asyncio.gather(*(backend.chat(ChatRequest(user_messages(f"q{n}"), "code", f"t@{n}"))
                                             for n in range(BATCH + 44)))
        finally:
            await backend.aclose()
    assert all(a.content == "ok" for a in answers) and len(server.requests) == BATCH + 44
    assert server.max_in_flight == BATCH, f"{kind}: at most {server.max_in_flight} requests in flight"
