"""The per-endpoint scheduler: slots, priorities, several endpoints, failing endpoints."""

from __future__ import annotations

import asyncio

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.backend_ollama import OllamaBackend
from meceng.agents.llm import ChatRequest, LLMSettings, user_messages
from meceng.agents.scheduler import PrioritySlots


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


async def test_openai_compatible_backend(tmp_path) -> None:
    import json

    from fake_ollama import openai_reply

    from meceng.agents.backend_openai import OpenAIBackend
    from meceng.agents.prompts import gold_code, gold_selection
    from meceng.pipeline import RunSettings, run_benchmark
    from meceng.tasks.registry import default_registry

    instance = default_registry().get("single_pendulum").instance(0)
    calls = {"n": 0}

    def responder(body):
        calls["n"] += 1
        if calls["n"] == 1:
            return 429, {"error": {"message": "slow down"}}, {"Retry-After": "0"}
        prompt = body["messages"][-1]["content"]
        if "<components>" in prompt:
            return 200, openai_reply(gold_selection(instance.required_components), reasoning="thinking..."), {}
        return 200, openai_reply(gold_code(instance.reference_program)), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="served-model", backend="openai", hosts=(server.url + "/v1",), think="low",
                          num_predict=1234, seed=7, backoff_s=0.01)
        settings = RunSettings(llm=llm, only=("single_pendulum",), variations=1, out=tmp_path, run_name="oa",
                               progress=False)
        run_json = await run_benchmark(settings, backend=OpenAIBackend(llm))
    body = server.requests[-1]
    assert body["model"] == "served-model" and body["max_completion_tokens"] == 1234
    assert body["seed"] == 7 and body["reasoning_effort"] == "low" and body["stream"] is False
    run = json.loads(run_json.read_text())
    task = run["tasks"][0]
    assert task["overall"] is True
    assert task["selection"]["meta"]["attempts"] == 2  # the 429 was retried
    assert task["selection"]["meta"]["prompt_tokens"] == 100
