"""The per-endpoint scheduler: slots, priorities, several endpoints, failing endpoints."""

from __future__ import annotations

import asyncio

from fake_ollama import FakeOllama, chat_reply

from meceng.llm.backend_ollama import OllamaBackend
from meceng.llm.messages import user_messages
from meceng.llm.scheduler import PrioritySlots
from meceng.llm.types import ChatRequest, LLMSettings


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

    from meceng.agents.prompts import gold_code, gold_selection
    from meceng.llm.backend_openai import OpenAIBackend
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
    assert body["model"] == "served-model" and body["max_completion_tokens"] == body["max_tokens"] == 1234
    assert body["seed"] == 7 and body["reasoning_effort"] == "low" and body["stream"] is False
    run = json.loads(run_json.read_text())
    task = run["tasks"][0]
    assert task["overall"] is True
    assert task["selection"]["meta"]["attempts"] == 2  # the 429 was retried
    assert task["selection"]["meta"]["prompt_tokens"] == 100


async def test_a_silent_server_ends_the_run_without_waiting_out_every_request(tmp_path) -> None:
    """A server that accepts connections and never answers (llama.cpp's after a failed decode):
    once a few requests in a row got no answer, the rest are refused unsent, so the run ends with
    every task lost after a couple of timeouts instead of one timeout per request and attempt."""
    import json

    from meceng.llm.backend_openai import OpenAIBackend
    from meceng.pipeline import RunSettings, run_benchmark

    release = asyncio.Event()

    async def silent(body):
        await release.wait()  # answers only when the test is over, to a client long gone
        return 200, chat_reply("too late"), {}

    slugs = ("single_mass_oscillator", "single_pendulum", "free_fall_mass_point", "flying_mass_point")
    async with FakeOllama(silent) as server:
        llm = LLMSettings(model="m", backend="openai", hosts=(server.url + "/v1",), batch_size=2, timeout_s=0.3,
                          max_attempts=3, backoff_s=0.01)
        settings = RunSettings(llm=llm, only=slugs, variations=2, out=tmp_path, run_name="silent", progress=False,
                               workers=1)
        try:
            run = json.loads((await run_benchmark(settings, backend=OpenAIBackend(llm))).read_text())
        finally:
            release.set()
    tasks = run["tasks"]
    assert len(tasks) == 8 and all(t["first_failure"] == "infrastructure" for t in tasks)
    assert any("not sent" in t["infrastructure_error"] for t in tasks)
    # 8 selections x 3 attempts would be 24 requests sent; the silence stops it after the first few
    assert len(server.requests) <= 2 * llm.batch_size + 1


async def test_a_busy_server_is_retried_not_refused() -> None:
    """503s are answers: a server that says it is busy stays in use and its requests succeed."""
    calls = {"n": 0}

    def busy_then_fine(body):
        calls["n"] += 1
        if calls["n"] <= 6:
            return 503, {"error": "queue full"}, {}
        return 200, chat_reply("ok"), {}

    async with FakeOllama(busy_then_fine) as server:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(server.url,), batch_size=1,
                                            backoff_s=0.001, max_attempts=8))
        responses = await asyncio.gather(*(backend.chat(ChatRequest(user_messages(f"r{k}"), "select", f"t@{k}"))
                                           for k in range(2)))
        await backend.aclose()
    assert [r.content for r in responses] == ["ok", "ok"] and len(server.requests) == 8
