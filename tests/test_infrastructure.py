"""A server's failure is never counted as the model's: a selection lost to the server ends its task
before any code request, a part lost to the server makes its assembly lost, and ``--resume`` with a
healthy server then ends with the same records as a run that never failed."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any

from fake_ollama import FakeOllama, chat_reply, prompted_instance
from records import normalized

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.pipeline.rundir import record_key
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry

VOLATILE = ("time", "timing", "duration", "started", "stderr_tail", "endpoint", "_s")


def _instances(slugs: tuple[str, ...], variations: int) -> list[TaskInstance]:
    registry = default_registry()
    top = registry.instances(registry.select(("1", "2", "3a", "3b"), slugs), 0, variations)
    return [*top, *(part for inst in top for _, part in inst.parts)]


class FailingFirst:
    """Answers like a model that writes the ground truth, after failing the first ``failures`` requests
    with an Ollama error body (503, as a server whose queue is full)."""

    def __init__(self, instances: list[TaskInstance], failures: int) -> None:
        self.instances = instances
        self.failures = failures
        self.seen = 0

    def __call__(self, body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        self.seen += 1
        if self.seen <= self.failures:
            return 503, {"error": "server busy, please try again"}, {}
        prompt = body["messages"][-1]["content"]
        instance = prompted_instance(self.instances, prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code(instance.reference_program)), {}


def _settings(url: str, tmp_path: Path, name: str, slugs: tuple[str, ...], variations: int,
              levels: tuple[str, ...]) -> RunSettings:
    llm = LLMSettings(model="fake:1b", backend="ollama", hosts=(url,), max_attempts=1, batch_size=1)
    return RunSettings(llm=llm, levels=levels, only=slugs, variations=variations, out=tmp_path, run_name=name,
                       progress=False, workers=2)


def _comparable(path: Path) -> dict[str, Any]:
    run = json.loads(path.read_text())  # stage details carry float noise (a mean distance of 4e-19 m)
    kept = ("overall", "first_failure", "error_categories", "selection", "generation", "files", "parts")
    return {record_key(r): normalized({"stages": [(s["name"], s["passed"]) for s in r["stages"]],
                                       **{k: r.get(k) for k in kept}}, VOLATILE)
            for r in run["tasks"]}


async def test_a_lost_selection_sends_no_code_request_and_resume_completes(tmp_path: Path) -> None:
    slugs = ("single_mass_oscillator", "free_fall_mass_point")
    instances = _instances(slugs, 2)
    broken = FailingFirst(instances, failures=2)
    async with FakeOllama(broken) as server:
        path = await run_benchmark(_settings(server.url, tmp_path, "run", slugs, 2, ("1",)))
        run = json.loads(path.read_text())
        lost = [t for t in run["tasks"] if t["first_failure"] == "infrastructure"]
        assert len(lost) == 2 and all("503" in t["infrastructure_error"] for t in lost)
        assert all("generation" not in t and t["stages"] == [] for t in lost)
        # 4 tasks, 2 selections lost: 4 selection requests and only 2 code requests
        assert len(server.requests) == 6
        assert sum("<components>" not in r["messages"][-1]["content"] for r in server.requests) == 2
        summary = run["summary"]
        assert summary["infrastructure_failures"] == 2 and summary["counted"] == 2 and summary["rates"]["overall"] == 1

        resumed = await run_benchmark(replace(_settings(server.url, tmp_path, "run", slugs, 2, ("1",)), resume=True))
    tasks = json.loads(resumed.read_text())["tasks"]
    assert len(tasks) == 4 and all(t["overall"] for t in tasks)


async def test_a_part_lost_to_the_server_makes_its_assembly_lost_and_resume_repairs_both(tmp_path: Path) -> None:
    slugs = ("cantilever_beam",)
    instances = _instances(slugs, 1)
    async with FakeOllama(FailingFirst(instances, failures=0)) as healthy:
        never_failed = await run_benchmark(_settings(healthy.url, tmp_path, "healthy", slugs, 1, ("3b",)))
    # the part phase: the part's selection is the first request; its loss must reach the assembly
    broken = FailingFirst(instances, failures=1)
    async with FakeOllama(broken) as server:
        path = await run_benchmark(_settings(server.url, tmp_path, "broken", slugs, 1, ("3b",)))
        tasks = json.loads(path.read_text())["tasks"]
        part, assembly = tasks
        assert part["origin"] and part["first_failure"] == "infrastructure"
        assert assembly["first_failure"] == "infrastructure"
        assert "part flexible_beam" in assembly["infrastructure_error"]
        assert len(server.requests) == 1  # no LLM call for the assembly
        summary = json.loads(path.read_text())["summary"]
        assert summary["levels"]["3b"]["counted"] == 0 and summary["levels"]["3a"]["counted"] == 0

        resumed = await run_benchmark(replace(_settings(server.url, tmp_path, "broken", slugs, 1, ("3b",)),
                                              resume=True))
    assert _comparable(resumed) == _comparable(never_failed)
    assert all(t["overall"] for t in json.loads(resumed.read_text())["tasks"])


async def test_a_lost_task_cancels_its_prefetched_reference() -> None:
    """The reference starts while the model answers; when the answer is lost, nobody will grade
    against it, and it must not outlive the run (it once started a fork server after the run closed)."""
    import asyncio

    from meceng.pipeline.evaluation import ReferenceCache

    cancelled = asyncio.Event()

    async def slow_reference(instance: TaskInstance) -> Any:
        try:
            await asyncio.sleep(60)
        except asyncio.CancelledError:
            cancelled.set()
            raise

    instance = _instances(("single_mass_oscillator",), 1)[0]
    cache = ReferenceCache(slow_reference)
    task = cache.start(instance)
    await asyncio.sleep(0)
    cache.discard(instance.key)
    await asyncio.wait_for(cancelled.wait(), timeout=5)
    assert task.cancelled() or task.done()
    assert cache.start(instance) is not task  # a later request runs it afresh
    cache.discard(instance.key)
