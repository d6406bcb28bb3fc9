#!/usr/bin/env python
"""Sweep figures (``meceng.sweeps.farm``), measured side by side in one run:

1. concurrency: 4 models on 4 fake Ollama servers (one model each, one request at a time, a fixed
   latency); each model's run alone, then the 4 as one sweep: the sweep's wall over the longest
   single run's wall (1.0 = the servers never wait for each other);
2. the reference store: the evaluation CPU (harness process and every program it ran) of a
   4-model level-3a sweep with a new store and with the store a previous sweep filled, against
   the same sweep without it. The 4 models answer with the ground truth (the gold backend under 4
   names), so each program costs what its reference costs: the store can remove at most the
   references' half of the CPU, (M + 1) / 2M = 0.625 of it stays with a new store, 0.5 with a
   filled one (a real model's level-3a programs mesh their part too, failing or not);
3. rescore of a gold run (1,000 tasks at 20 variations): as before (cold interpreters, grading on
   threads of the parent) against now (the warm fork server, the grading pool).

    python scripts/bench_farm.py [--latency 1.0] [--variations 1] [--json FILE]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import resource
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from fake_ollama import FakeOllama, chat_reply, prompted_instance

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, rescore, run_benchmark
from meceng.sweeps.farm import SweepJob, run_sweep
from meceng.tasks.registry import default_registry

RIGID = ("1", "2", "3", "4", "9", "11", "12", "19", "23", "29", "35", "43")
PARTS = ("bearing_block_part", "flexible_beam_part", "crank_part_simple", "rod_part_simple")
MODELS = 4


def _jobs(out: Path, urls: list[str], only: tuple[str, ...], levels: tuple[str, ...], variations: int,
          workers: int) -> list[SweepJob]:
    jobs = []
    for k, url in enumerate(urls):
        llm = LLMSettings(model=f"bench-{k}", backend="ollama" if url else "gold", hosts=(url or "gold",),
                          batch_size=1)
        settings = RunSettings(llm=llm, levels=levels, only=only, variations=variations, out=out,
                               run_name=f"bench-{k}", workers=workers, progress=False)
        jobs.append(SweepJob(f"bench-{k}", llm.model, settings, len(only) * variations))
    return jobs


async def concurrency(latency: float, variations: int, workers: int, singles: int = MODELS) -> dict[str, Any]:
    """Each model alone (the first ``singles`` of them: the runs are alike but for their server),
    then all together, against 4 servers of one slot each."""
    registry = default_registry()
    instances = registry.instances(registry.select(None, RIGID), 0, variations)

    async def respond(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        await asyncio.sleep(latency)
        prompt = body["messages"][-1]["content"]
        instance = prompted_instance(instances, prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code(instance.reference_program)), {}

    servers = [FakeOllama(respond) for _ in range(MODELS)]
    for server in servers:
        await server.__aenter__()
    try:
        urls = [s.url for s in servers]
        single = []
        with tempfile.TemporaryDirectory() as out:
            for job in _jobs(Path(out), urls, RIGID, ("1", "2"), variations, workers)[:singles]:
                t0 = time.perf_counter()
                await run_sweep([job], workers, display=False)
                single.append(time.perf_counter() - t0)
        with tempfile.TemporaryDirectory() as out:
            t0 = time.perf_counter()
            results = await run_sweep(_jobs(Path(out), urls, RIGID, ("1", "2"), variations, workers), workers,
                                      display=False)
            sweep = time.perf_counter() - t0
            assert all(json.loads(Path(r["run"]).read_text())["summary"]["rates"]["overall"] == 1.0
                       for r in results), results
        assert all(s.max_in_flight == 1 for s in servers)
    finally:
        for server in servers:
            await server.__aexit__(None, None, None)
    return {"single_run_walls_s": single, "sweep_wall_s": sweep, "requests_per_run": 2 * len(instances),
            "latency_s": latency, "sweep_over_longest_run": sweep / max(single)}


def _cpu() -> float:
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


async def store_cpu(variations: int, workers: int, parts: tuple[str, ...] = PARTS) -> dict[str, Any]:
    """CPU seconds of a 4-model level-3a gold sweep of ``parts`` without the reference store, with a
    new store, and once more with the store the second sweep filled (a later sweep writing to the
    same place). The fork server is waited for when a sweep ends, so its programs' CPU is counted."""
    figures: dict[str, Any] = {}
    with tempfile.TemporaryDirectory() as scratch:
        store = Path(scratch) / "references"
        for label, use_store in (("without", False), ("with", True), ("filled", True)):
            with tempfile.TemporaryDirectory() as out:
                jobs = _jobs(Path(out), [""] * MODELS, parts, ("3a",), variations, workers)
                cpu, t0 = _cpu(), time.perf_counter()
                results = await run_sweep(jobs, workers, store=store if use_store else None, display=False)
                figures[f"{label}_store_cpu_s"] = _cpu() - cpu
                figures[f"{label}_store_wall_s"] = time.perf_counter() - t0
                verdicts = [[(t["key"] if "key" in t else t["slug"], t["overall"]) for t in
                             json.loads(Path(r["run"]).read_text())["tasks"]] for r in results]
                figures[f"{label}_store_verdicts"] = verdicts
    assert figures["with_store_verdicts"] == figures["without_store_verdicts"] == figures["filled_store_verdicts"], \
        "the store changed a verdict"
    figures["tasks"] = MODELS * len(parts) * variations
    figures["store_cpu_ratio"] = figures["with_store_cpu_s"] / figures["without_store_cpu_s"]
    figures["filled_store_cpu_ratio"] = figures["filled_store_cpu_s"] / figures["without_store_cpu_s"]
    # each model's program costs what its reference costs (gold): M candidates and 1 reference
    # against M and M is this sweep's floor with a new store, M and 0 against M and M with a filled one
    figures["floor_new_store"] = (MODELS + 1) / (2 * MODELS)
    figures["floor_filled_store"] = MODELS / (2 * MODELS)
    return figures


RESCORES = (("before", "subprocess", False), ("fork_threads", "fork", False), ("now", "fork", True))


async def rescore_figures(variations: int, workers: int, passes: tuple[str, ...] = ("before", "fork_threads", "now")
                          ) -> dict[str, Any]:
    """A gold level 1-2 run (``variations`` a task model: 50 tasks each), rescored as before this
    issue (a cold interpreter a program, grading on the parent's threads), with the fork server alone,
    and as now (the fork server and the grading pool), the ``passes`` named; wall and the parent's
    own CPU a task."""
    figures: dict[str, Any] = {}
    with tempfile.TemporaryDirectory() as out:
        llm = LLMSettings(model="gold", backend="gold")
        settings = RunSettings(llm=llm, variations=variations, out=Path(out), run_name="gold", workers=workers,
                               progress=False)
        run_json = await run_benchmark(settings)
        figures["tasks"] = len(json.loads(run_json.read_text())["tasks"])
        for label, executor, pool in (r for r in RESCORES if r[0] in passes):
            own, t0 = resource.getrusage(resource.RUSAGE_SELF), time.perf_counter()
            await rescore(run_json.parent, workers=workers, grading_pool=pool, executor=executor)
            wall = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_SELF)
            figures[f"{label}_s"] = wall
            figures[f"{label}_parent_cpu_ms_per_task"] = 1000 * (
                after.ru_utime - own.ru_utime + after.ru_stime - own.ru_stime) / figures["tasks"]
            summary = json.loads(run_json.read_text())["summary"]
            assert summary["rates"]["overall"] == 1.0, "a gold program failed in the rescore"
    figures["now_over_before"] = figures["now_s"] / figures["before_s"]
    return figures


async def main_async(latency: float, variations: int, workers: int) -> dict[str, Any]:
    conc = await concurrency(latency, variations, workers)
    print(f"sweep concurrency: {MODELS} models on {MODELS} servers (1 slot, {latency:g} s per request, "
          f"{conc['requests_per_run']} requests a run): single runs "
          + ", ".join(f"{w:.1f}" for w in conc["single_run_walls_s"])
          + f" s, sweep {conc['sweep_wall_s']:.1f} s -> sweep / longest run {conc['sweep_over_longest_run']:.3f}",
          flush=True)
    store = await store_cpu(1, workers)
    print(f"reference store: level-3a sweep of {MODELS} models x {len(PARTS)} parts: evaluation CPU without the "
          f"store {store['without_store_cpu_s']:.1f} s, with a new store {store['with_store_cpu_s']:.1f} s -> "
          f"{store['store_cpu_ratio']:.3f} (floor {store['floor_new_store']:.3f}), with the filled store "
          f"{store['filled_store_cpu_s']:.1f} s -> {store['filled_store_cpu_ratio']:.3f} "
          f"(floor {store['floor_filled_store']:.3f}); verdicts identical", flush=True)
    again = await rescore_figures(20, workers)
    print(f"rescore of a {again['tasks']}-task gold run: before (cold interpreters, grading on the parent's threads) "
          f"{again['before_s']:.1f} s ({again['before_parent_cpu_ms_per_task']:.1f} ms parent CPU a task), fork "
          f"server and threads {again['fork_threads_s']:.1f} s, now (fork server, grading pool) {again['now_s']:.1f} s "
          f"({again['now_parent_cpu_ms_per_task']:.1f} ms) -> {again['now_over_before']:.2f}", flush=True)
    return {"sweep_concurrency": conc, "reference_store": store, "rescore": again}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--latency", type=float, default=1.0,
                        help="seconds per request (real servers: selection ~1.5 s, code ~6 s; far below that "
                             "the 4 runs' evaluation on this machine's cores is what is measured)")
    parser.add_argument("--variations", type=int, default=1)
    parser.add_argument("--workers", type=int, default=None)
    parser.add_argument("--json", type=Path, default=None)
    args = parser.parse_args(argv)
    import os

    results = asyncio.run(main_async(args.latency, args.variations, args.workers or os.cpu_count() or 1))
    if args.json:
        args.json.write_text(json.dumps(results, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
