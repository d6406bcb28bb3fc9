"""Response cache: every answered LLM request, appended to a JSONL file as it arrives.

Keyed by (backend, model, messages, options, think, seed), so a resumed run repeats no LLM call
it has already paid for. Lines are written whole and flushed at once, so a killed run loses none;
they are fsynced only at close (an fsync per answer blocked the event loop ~2 ms each, at 128
answers/s a quarter of its time; a power cut costs at most a few answers asked again). A line cut
by a kill is ignored.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
from pathlib import Path
from typing import Any

from meceng.jsonl import read_jsonl
from meceng.llm.types import Backend, ChatRequest, ChatResponse, LLMSettings, ToolCall


def request_key(settings: LLMSettings, request: ChatRequest) -> str:
    payload = {
        "backend": settings.backend, "model": settings.model, "messages": list(request.messages),
        "options": settings.options(request.sample), "think": settings.think, "purpose": request.purpose,
        "tools": list(request.tools),
    }
    if request.sample is not None:  # only then: the keys of every earlier run's answers stay as they were
        payload["sample"] = request.sample
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


class ResponseCache:
    def __init__(self, path: Path) -> None:
        self.path = path
        self.entries: dict[str, dict[str, Any]] = {row["key"]: row["response"] for row in read_jsonl(path)}
        self._file = open(path, "a", encoding="utf-8")  # noqa: SIM115 - kept open for the run
        self.hits = 0
        self.misses = 0

    def get(self, key: str) -> ChatResponse | None:
        entry = self.entries.get(key)
        if entry is None:
            return None
        self.hits += 1
        calls = tuple(ToolCall(**c) for c in entry.get("tool_calls", ()))
        return ChatResponse(**{**entry, "tool_calls": calls})

    def put(self, key: str, response: ChatResponse) -> None:
        self.misses += 1
        entry = dataclasses.asdict(response)
        self.entries[key] = entry
        self._file.write(json.dumps({"key": key, "response": entry}) + "\n")
        self._file.flush()

    def close(self) -> None:
        if not self._file.closed:
            self._file.flush()
            os.fsync(self._file.fileno())
            self._file.close()


class CachedBackend:
    """Wraps a backend: answered requests come from the cache, new answers go into it."""

    def __init__(self, inner: Backend, cache: ResponseCache, settings: LLMSettings) -> None:
        self.inner = inner
        self.cache = cache
        self.settings = settings
        self.name = inner.name

    async def chat(self, request: ChatRequest) -> ChatResponse:
        key = request_key(self.settings, request)
        cached = self.cache.get(key)
        if cached is not None:
            return cached
        response = await self.inner.chat(request)
        self.cache.put(key, response)
        return response

    async def aclose(self) -> None:
        await self.inner.aclose()
        self.cache.close()
