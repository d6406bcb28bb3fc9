"""The per-endpoint scheduler: slots, priorities, several endpoints, failing endpoints."""

from __future__ import annotations

import asyncio

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.llm import ChatRequest, LLMSettings, OllamaBackend, PrioritySlots, user_messages


async def test_priority_slots_serve_code_before_selection() -> None:
    slots = PrioritySlots(1)
    await slots.acquire(1)
    order: list[str] = []

    async def waiter(name: str, priority: int) -> None:
        await slots.acquire(priority)
        order.append(name)
        slots.release()

    tasks = [asyncio.ensure_future(waiter("select-a", 1)), asyncio.ensure_future(waiter("select-b", 1))]
    await asyncio.sleep(0)
    tasks.append(asyncio.ensure_future(waiter("code", 0)))
    await asyncio.sleep(0)
    slots.release()
    await asyncio.gather(*tasks)
    assert order == ["code", "select-a", "select-b"]
    assert slots.free == 1


async def test_requests_spread_over_endpoints_and_never_exceed_slots() -> None:
    def slow(body):
        async def answer():
            await asyncio.sleep(0.05)
            return 200, chat_reply("ok"), {}
        return answer()

    async with FakeOllama(slow) as a, FakeOllama(slow) as b:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(a.url, b.url), batch_size=3))
        requests = [ChatRequest(user_messages(f"r{k}"), "select", f"t@{k}") for k in range(24)]
        await asyncio.gather(*(backend.chat(r) for r in requests))
        await backend.aclose()
    assert len(a.requests) + len(b.requests) == 24
    assert min(len(a.requests), len(b.requests)) >= 6  # both servers used
    assert a.max_in_flight <= 3 and b.max_in_flight <= 3


async def test_failing_endpoint_is_taken_out_and_others_carry_the_load() -> None:
    def broken(body):
        return 503, {"error": "down"}, {}

    def healthy(body):
        return 200, chat_reply("ok"), {}

    async with FakeOllama(broken) as bad, FakeOllama(healthy) as good:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(bad.url, good.url), batch_size=2,
                                            backoff_s=0.001, max_attempts=6))
        requests = [ChatRequest(user_messages(f"r{k}"), "select", f"t@{k}") for k in range(20)]
        responses = await asyncio.gather(*(backend.chat(r) for r in requests))
        await backend.aclose()
    assert all(r.content == "ok" for r in responses)
    assert len(bad.requests) <= 12  # only its first share of the burst; retries go elsewhere
    assert all(r.endpoint == good.url for r in responses)
