"""A sweep's runs at the same time (meceng.sweeps.farm): runs on different servers overlap, a shared
server never gets more requests than its slots and never two models mixed, and the verdicts are
those of runs one after another without the reference store."""

from __future__ import annotations

import asyncio
import json
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from fake_ollama import FakeOllama, chat_reply, prompted_instance
from records import normalized

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.sweeps.farm import SweepJob, run_sweep, server_groups
from meceng.tasks import default_registry

ONLY = ("3", "11")
ROOT = Path(__file__).resolve().parents[1]


def job(name: str, model: str, hosts: tuple[str, ...], out: Path = Path("runs"), backend: str = "ollama",
        **changes: Any) -> SweepJob:
    llm = LLMSettings(model=model, backend=backend, hosts=hosts, batch_size=1)
    settings = RunSettings(llm=llm, only=ONLY, variations=1, out=out, run_name=name, workers=2, progress=False,
                           **changes)
    return SweepJob(name, model, settings, 2)


def test_runs_sharing_a_server_are_one_group_with_each_models_runs_together() -> None:
    jobs = [job("m1-a", "m1", ("http://a",)), job("m2-b", "m2", ("http://b",)),
            job("m3-ac", "m3", ("http://a", "http://c")), job("m1-a-again", "m1", ("http://a/",)),
            job("m4-c", "m4", ("http://c",)), job("gold", "gold", ("x",), backend="gold")]
    groups = [[j.name for j in g] for g in server_groups(jobs)]
    assert sorted(groups) == sorted([["m1-a", "m1-a-again", "m3-ac", "m4-c"], ["m2-b"], ["gold"]])
    hosted = [job("gpt-a", "gpt-a", ("https://api.openai.com/v1",), backend="openai"),
              job("gpt-b", "gpt-b", ("https://api.openai.com/v1",), backend="openai"),
              job("gpt-a-again", "gpt-a", ("https://api.openai.com/v1",), backend="openai"),
              job("claude", "claude", ("https://api.anthropic.com",), backend="anthropic")]
    groups = [[j.name for j in g] for g in server_groups(hosted)]  # a hosted API is a server per model
    assert sorted(groups) == [["claude"], ["gpt-a", "gpt-a-again"], ["gpt-b"]]


def gold_responder(log: list[tuple[str, str, int]], latency: float) -> Any:
    registry = default_registry()
    instances = registry.instances(registry.select(None, ONLY), 0, 1)
    counter = iter(range(1_000_000))

    async def respond(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        log.append((body["model"], "start", next(counter)))
        await asyncio.sleep(latency)
        log.append((body["model"], "end", next(counter)))
        prompt = body["messages"][-1]["content"]
        instance = prompted_instance(instances, prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code(instance.reference_program)), {}

    return respond


def overlapping(log: list[tuple[str, str, int]], first: str, second: str) -> bool:
    """Whether a request of model ``second`` was in flight while one of ``first`` was (by event order)."""
    open_first = 0
    for model, what, _ in log:
        if model == first:
            open_first += 1 if what == "start" else -1
        elif model == second and what == "start" and open_first > 0:
            return True
    return False


async def test_runs_on_their_own_servers_overlap_and_a_shared_server_keeps_its_slots(tmp_path: Path) -> None:
    events: list[tuple[str, str, int]] = []
    responder = gold_responder(events, 0.05)
    async with FakeOllama(responder) as a, FakeOllama(responder) as b:
        jobs = [job("m1", "m1", (a.url,), tmp_path), job("m2", "m2", (b.url,), tmp_path),
                job("m3", "m3", (a.url,), tmp_path),
                job("m1-again", "m1", (a.url,), tmp_path, select_template="CI2")]  # fills m1's tail
        results = await run_sweep(jobs, workers=2, display=False)
    assert all("error" not in r for r in results), results
    assert a.max_in_flight == 1 and b.max_in_flight == 1  # batch_size 1: one request at a time per server
    assert overlapping(events, "m1", "m2")  # two servers, two runs at once
    on_a = [model for model, what, _ in events if what == "start" and model in ("m1", "m3")]
    assert on_a == sorted(on_a) and set(on_a) == {"m1", "m3"}  # server a: m1's requests, then m3's
    for result in results:
        assert json.loads(Path(result["run"]).read_text())["summary"]["rates"]["overall"] == 1.0


def comparable(run_json: Path) -> dict[str, Any]:
    run = json.loads(run_json.read_text())
    return normalized({"tasks": run["tasks"], "summary": {k: v for k, v in run["summary"].items() if k != "timing"}},
                      (*("time", "timing", "duration", "started", "stderr_tail", "endpoint"), "wall", "cpu_s"))


async def test_verdicts_equal_with_and_without_store_and_concurrency(tmp_path: Path) -> None:
    def jobs(out: Path) -> list[SweepJob]:
        return [job(f"gold-{t}", "gold", (), out, backend="gold", select_template=t) for t in ("CI1", "CI2")]

    alone = []
    for item in jobs(tmp_path / "alone"):  # one after another, each with its own workers, no store
        alone.append(comparable(await run_benchmark(item.settings)))
    store = tmp_path / "references"
    fresh = await run_sweep(jobs(tmp_path / "fresh"), workers=2, store=store, display=False)
    entries = sorted(p.name for p in store.rglob("*.pkl"))
    # per task instance one ground truth and its twice-the-steps run (behaviour), shared by both runs
    assert len(entries) == 4
    reused = await run_sweep(jobs(tmp_path / "reused"), workers=2, store=store, display=False)
    assert sorted(p.name for p in store.rglob("*.pkl")) == entries  # nothing made again
    for results in (fresh, reused):
        assert [comparable(Path(r["run"])) for r in results] == alone


def start_sweep(out: Path) -> subprocess.Popen[str]:
    # 144 tasks, ~2.5 s of grading after ~2 s of start-up: both signals land well inside the sweep
    args = ["--model", "gold", "--only", "1,2,3,4,9,11", "--variations", "12", "--select-template", "CI1",
            "--select-template", "CI2", "--out", str(out), "--no-progress"]
    # Ctrl-C's default action in the sweep even when this session ignores SIGINT (a CI script started
    # with '&' does, and Python then installs no KeyboardInterrupt handler: the SIGINT stage was lost)
    return subprocess.Popen([sys.executable, str(ROOT / "scripts" / "sweep.py"), *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def lines(folder: Path) -> int:
    return sum(p.read_bytes().count(b"\n") for p in folder.glob("*/journal.jsonl"))


@pytest.mark.slow  # a sweep killed and resumed twice (~80 s); test_resume.py keeps a killed run in the default run
def test_a_killed_or_interrupted_sweep_resumes_every_run(tmp_path: Path) -> None:
    straight = start_sweep(tmp_path / "straight")
    assert straight.wait(timeout=600) == 0, straight.stderr.read() if straight.stderr else ""
    expected = sorted(p.parent.name for p in (tmp_path / "straight").glob("*/run.json"))
    assert len(expected) == 2
    out = tmp_path / "killed"
    for stop, after in ((signal.SIGKILL, 3), (signal.SIGINT, 12)):
        proc = start_sweep(out)
        deadline = time.monotonic() + 300
        while lines(out) < after and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.02)
        proc.send_signal(stop)
        proc.wait(timeout=120)
        assert lines(out) < lines(tmp_path / "straight"), f"the sweep ended before {stop.name} reached it"
    assert not all((out / name / "run.json").exists() for name in expected)
    final = start_sweep(out)
    assert final.wait(timeout=600) == 0, final.stderr.read() if final.stderr else ""
    for name in expected:
        assert comparable(out / name / "run.json") == comparable(tmp_path / "straight" / name / "run.json")
        assert not (out / name / ".lock").exists()
    assert lines(out) == lines(tmp_path / "straight")  # no finished task was done again


def across(name: str, members: tuple[tuple[str, str], ...], out: Path = Path("runs"), **changes: Any) -> SweepJob:
    """A consensus run across models: sample k by members[k mod M], each (model, host) its own server."""
    models = tuple(LLMSettings(model=m, backend="ollama", hosts=(h,), batch_size=1) for m, h in members)
    settings = RunSettings(llm=models[0], only=ONLY, variations=1, out=out, run_name=name, workers=2,
                           progress=False, agent="consensus", samples=2, consensus_models=models, **changes)
    return SweepJob(name, models[0].model, settings, 2)


def test_a_consensus_run_across_models_is_grouped_by_every_models_servers() -> None:
    """Its second model's server is a server it uses: a run on that server is in its group, and a run
    of either of its models waits for it (no model swaps on a server it shares)."""
    jobs = [across("m1-m2", (("m1", "http://a"), ("m2", "http://b"))), job("m2-b", "m2", ("http://b",)),
            job("m3-c", "m3", ("http://c",))]
    groups = sorted([j.name for j in g] for g in server_groups(jobs))
    assert groups == [["m1-m2", "m2-b"], ["m3-c"]], groups
    assert jobs[0].hosts == ("http://a", "http://b") and jobs[0].models == ("m1", "m2")


async def test_a_consensus_run_across_models_keeps_every_servers_slots(tmp_path: Path) -> None:
    """The run's requests to its second model's server share that server's slots with the sweep's
    other runs there: never more in flight than its slots, and the other model's run waits."""
    events: list[tuple[str, str, int]] = []
    responder = gold_responder(events, 0.05)
    async with FakeOllama(responder) as a, FakeOllama(responder) as b:
        jobs = [across("m1-m2", (("m1", a.url), ("m2", b.url)), tmp_path), job("m3-b", "m3", (b.url,), tmp_path)]
        results = await run_sweep(jobs, workers=2, display=False)
    assert all("error" not in r for r in results), results
    assert {model for model, _, _ in events} == {"m1", "m2", "m3"}
    assert b.max_in_flight == 1, b.max_in_flight  # batch_size 1 on b, shared by both runs
    assert not overlapping(events, "m2", "m3") and not overlapping(events, "m3", "m2")
