"""The pipeline with the real Ollama client against a fake Ollama server on 127.0.0.1.

The server answers with ground truths for some tasks and with broken answers for others; each is
graded as the paper's rules say and the run completes.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.backend_ollama import OllamaBackend
from meceng.llm.messages import user_messages
from meceng.llm.types import ChatRequest, LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

SCENARIOS = {
    "single_mass_oscillator": "gold",
    "free_fall_mass_point": "no_code",
    "single_pendulum": "malformed_components",
    "double_mass_oscillator": "wrong_mass",
    "flying_mass_point": "syntax_error",
    "single_mass_oscillator_with_gravity": "endless_loop",
}


def _answer(instance, purpose: str, scenario: str) -> str:
    if purpose == "select":
        if scenario == "malformed_components":
            return "I would use a mass point and a distance constraint <components> MassPoint"
        return gold_selection(instance.required_components)
    program = instance.reference_program
    if scenario == "no_code":
        return "The system is a mass point in free fall; its height is z0 - g t^2 / 2."
    if scenario == "wrong_mass":
        program = re.sub(r"\nmass1 = ([0-9.]+)\n", lambda m: f"\nmass1 = {float(m.group(1)) * 1.5!r}\n", program)
    if scenario == "syntax_error":
        program = program.replace("mbs.Assemble()", "mbs.Assemble(")
    if scenario == "endless_loop":
        program = program.replace("mbs.Assemble()", "while True:\n    pass\nmbs.Assemble()")
    return gold_code(program)


@pytest.fixture
def instances():
    registry = default_registry()
    return {registry.get(slug).instance(0).description: registry.get(slug).instance(0) for slug in SCENARIOS}


async def test_fake_ollama_run_grades_each_answer(tmp_path: Path, instances) -> None:
    def responder(body):
        prompt = body["messages"][-1]["content"]
        instance = next(inst for desc, inst in instances.items() if desc in prompt)
        purpose = "select" if "<components>" in prompt else "code"
        return 200, chat_reply(_answer(instance, purpose, SCENARIOS[instance.slug])), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="fake-model:7b", backend="ollama", hosts=(server.url,), batch_size=2,
                          num_ctx=8192, think=False)
        settings = RunSettings(llm=llm, only=tuple(SCENARIOS), variations=1, seed=0, out=tmp_path,
                               run_name="fake", workers=2, exec_timeout_s=5.0, progress=False)
        run_json = await run_benchmark(settings)

    # the real client sent what Ollama expects
    first = server.requests[0]
    assert first["model"] == "fake-model:7b" and first["stream"] is False
    assert first["options"]["num_ctx"] == 8192 and first["options"]["temperature"] == 0.0
    assert first["think"] is False and "keep_alive" in first
    assert server.max_in_flight <= 2

    run = json.loads(run_json.read_text())
    records = {r["slug"]: r for r in run["tasks"]}
    assert set(records) == set(SCENARIOS)

    def stage(slug, name):
        return next(s for s in records[slug]["stages"] if s["name"] == name)

    assert records["single_mass_oscillator"]["overall"] is True
    assert records["single_mass_oscillator"]["selection"]["meta"]["prompt_tokens"] == 100

    assert records["free_fall_mass_point"]["first_failure"] == "finished_assemble"
    assert "no Python code block" in stage("free_fall_mass_point", "finished_assemble")["detail"]

    assert records["single_pendulum"]["first_failure"] == "choose_components"
    assert records["single_pendulum"]["selection"]["error"]
    assert stage("single_pendulum", "solution_match")["passed"] is True  # later stages still graded

    assert records["double_mass_oscillator"]["first_failure"] == "graph_content_match"
    assert records["double_mass_oscillator"]["error_categories"] == ["inertia and mass"]
    assert stage("double_mass_oscillator", "solution_match")["passed"] is False

    assert records["flying_mass_point"]["first_failure"] == "finished_assemble"
    assert "syntax error" in stage("flying_mass_point", "finished_assemble")["detail"]

    assert records["single_mass_oscillator_with_gravity"]["first_failure"] == "finished_assemble"
    assert "timeout" in stage("single_mass_oscillator_with_gravity", "finished_assemble")["detail"]

    summary = run["summary"]
    assert summary["counted"] == 6 and summary["passed"]["overall"] == 1
    assert summary["error_categories"]["inertia and mass"] == 1
    journal = (tmp_path / "fake" / "journal.jsonl").read_text().splitlines()
    assert len(journal) == 6
    assert (tmp_path / "fake" / "programs" / "single_mass_oscillator" / "seed0_generated.py").exists()


async def test_transient_errors_are_retried_and_permanent_ones_are_not() -> None:
    calls = {"n": 0}

    def flaky(body):
        calls["n"] += 1
        if calls["n"] <= 2:
            return 503, {"error": "server busy, queue full"}, {}
        return 200, chat_reply("<components><component>MassPoint</component></components>"), {}

    request = ChatRequest(user_messages("hello"), "select", "t@0")
    async with FakeOllama(flaky) as server:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(server.url,), backoff_s=0.01))
        response = await backend.chat(request)
        await backend.aclose()
    assert response.attempts == 3 and "MassPoint" in response.content

    def unknown_model(body):
        return 404, {"error": f"model '{body['model']}' not found"}, {}

    async with FakeOllama(unknown_model) as server:
        backend = OllamaBackend(LLMSettings(model="nope", backend="ollama", hosts=(server.url,), backoff_s=0.01))
        from meceng.llm.types import LLMError

        with pytest.raises(LLMError) as info:
            await backend.chat(request)
        await backend.aclose()
    assert info.value.status == 404 and not info.value.transient
    assert len(server.requests) == 1


async def test_truncated_answer_is_flagged() -> None:
    def truncated(body):
        return 200, chat_reply("```python\nimport exudyn as exu\n", done_reason="length", completion_tokens=2048), {}

    async with FakeOllama(truncated) as server:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(server.url,)))
        response = await backend.chat(ChatRequest(user_messages("x"), "code", "t@0"))
        await backend.aclose()
    assert response.truncated and response.meta()["truncated"] is True


async def test_retry_after_is_respected() -> None:
    calls: list[float] = []

    def limited(body):
        import time as _time

        calls.append(_time.monotonic())
        if len(calls) == 1:
            return 429, {"error": "too many requests"}, {"Retry-After": "1"}
        return 200, chat_reply("ok"), {}

    async with FakeOllama(limited) as server:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(server.url,), backoff_s=0.01))
        response = await backend.chat(ChatRequest(user_messages("x"), "select", "t@0"))
        await backend.aclose()
    assert response.content == "ok" and response.attempts == 2
    assert calls[1] - calls[0] >= 0.95  # waited as told, not the 0.01 s backoff


async def test_flaky_server_loses_no_task(tmp_path: Path) -> None:
    """20 % transient errors, 10 % timeouts, some dropped connections and malformed bodies: every
    task ends with a record; tasks the server never answered are infrastructure failures."""
    import asyncio
    import random

    rng = random.Random(7)
    registry = default_registry()
    slugs = ["single_mass_oscillator", "single_pendulum", "flying_mass_point", "double_mass_oscillator",
             "free_fall_mass_point"]
    by_description = {registry.get(s).instance(k).description: registry.get(s).instance(k)
                      for s in slugs for k in range(4)}

    async def responder(body):
        roll = rng.random()
        if roll < 0.2:
            return rng.choice([500, 502, 503]), {"error": "overloaded"}, {}
        if roll < 0.3:
            await asyncio.sleep(1.0)  # longer than the client's timeout
        if roll < 0.33:
            return 200, "{not json", {}
        if roll < 0.36:
            return -1, None, {}  # connection dropped without an answer
        prompt = body["messages"][-1]["content"]
        instance = next(inst for desc, inst in by_description.items() if desc in prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code(instance.reference_program)), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="flaky", backend="ollama", hosts=(server.url,), batch_size=4, timeout_s=0.5,
                          max_attempts=3, backoff_s=0.01)
        settings = RunSettings(llm=llm, only=tuple(slugs), variations=4, seed=0, out=tmp_path, run_name="flaky",
                               workers=2, progress=False)
        run_json = await run_benchmark(settings)
    run = json.loads(run_json.read_text())
    assert len(run["tasks"]) == 20  # none lost
    infra = [t for t in run["tasks"] if t["first_failure"] == "infrastructure"]
    graded = [t for t in run["tasks"] if t["first_failure"] != "infrastructure"]
    assert all(t["infrastructure_error"] for t in infra)
    assert all(t["overall"] for t in graded)  # every answered task is a gold answer and passes
    summary = run["summary"]
    assert summary["infrastructure_failures"] == len(infra) and summary["counted"] == len(graded)
    if graded:
        assert summary["rates"]["overall"] == 1.0  # infrastructure failures are not model failures
    assert len(server.requests) > 40  # retries happened


async def test_full_context_and_thinking_are_recorded() -> None:
    from meceng.agents.steps import choose_components
    from meceng.catalog.catalogs import rigid_catalog

    instance = default_registry().get("single_pendulum").instance(0)

    def full(body):
        reply = chat_reply(gold_selection(instance.required_components), thinking="first the bodies...",
                           prompt_tokens=4000, completion_tokens=200)
        return 200, reply, {}

    async with FakeOllama(full) as server:
        backend = OllamaBackend(LLMSettings(model="m", backend="ollama", hosts=(server.url,), num_ctx=4096))
        selection = await choose_components(backend, instance, rigid_catalog())
        await backend.aclose()
    assert selection.error is None
    assert selection.meta["context_limit_hit"] is True
    assert selection.meta["thinking"] == "first the bodies..." and selection.meta["thinking_chars"] == 19
