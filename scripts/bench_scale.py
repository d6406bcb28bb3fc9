#!/usr/bin/env python
"""Server-scale figures: a 1000-task level 1-2 run against a fake server with 64 slots in its own
process (``bench_server.py``), measured three ways side by side, each in a fresh harness process:

- LLM only: both LLM steps of every task, no evaluation — how long the server needs when the
  harness never makes it wait;
- evaluation only: every ground truth graded with the run's workers, no LLM;
- the run itself (``run_benchmark``), with the harness process's own CPU seconds (children not
  included: they are the evaluation) and its peak resident memory.

    python scripts/bench_scale.py [--slots 64] [--variations 20] [--scale 1.0] [--json FILE]
    python scripts/bench_scale.py --harness run --url URL ...     # one harness process (internal)
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from meceng.agents.steps import choose_components, generate_code
from meceng.catalog.catalogs import rigid_catalog
from meceng.eval.chain import Tolerances
from meceng.llm.factory import make_backend
from meceng.llm.messages import user_messages
from meceng.llm.types import ChatRequest, LLMSettings
from meceng.pipeline import Evaluator, RunSettings, run_benchmark
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

HERE = Path(__file__).resolve().parent
LEVELS = ("1", "2")


def _llm(url: str, slots: int) -> LLMSettings:
    return LLMSettings(model="bench", backend="ollama", hosts=(url,), batch_size=slots, timeout_s=600.0)


async def _llm_only(url: str, slots: int, variations: int, seed: int) -> dict[str, Any]:
    registry = default_registry()
    instances = registry.instances(registry.select(LEVELS, None), seed, variations)
    backend = make_backend(_llm(url, slots))
    catalog = rigid_catalog()

    async def one(instance: Any) -> bool:
        selection = await choose_components(backend, instance, catalog)
        generation = await generate_code(backend, instance, catalog, selection)
        return generation.code is not None

    try:
        done = await asyncio.gather(*(one(i) for i in instances))
    finally:
        await backend.aclose()
    return {"tasks": len(instances), "answered": sum(done)}


async def _evaluation_only(workers: int, variations: int, seed: int) -> dict[str, Any]:
    registry = default_registry()
    instances = registry.instances(registry.select(LEVELS, None), seed, variations)
    pool = WarmPool(child_env())
    await pool.start()
    evaluator = Evaluator(workers, ExecutionLimits(), Tolerances(), pool=pool)
    try:
        verdicts = await asyncio.gather(*(evaluator.evaluate(i, i.reference_program, i.required_components, None)
                                          for i in instances))
    finally:
        await pool.close()
    return {"tasks": len(instances), "passed": sum(v[0].overall for v in verdicts)}


async def _run(url: str, slots: int, workers: int, variations: int, seed: int) -> dict[str, Any]:
    with tempfile.TemporaryDirectory() as out:
        settings = RunSettings(llm=_llm(url, slots), levels=LEVELS, variations=variations, seed=seed, out=Path(out),
                               run_name="scale", workers=workers, progress=False)
        run_json = await run_benchmark(settings)
        summary = json.loads(run_json.read_text())["summary"]
        folder_mb = sum(f.stat().st_size for f in Path(out).rglob("*") if f.is_file()) / 2**20
    return {"tasks": summary["tasks"], "overall": summary["rates"]["overall"],
            "infrastructure_failures": summary["infrastructure_failures"], "run_folder_mb": folder_mb}


def harness(mode: str, url: str, slots: int, workers: int, variations: int, seed: int) -> dict[str, Any]:
    """One measurement in this process: wall, own CPU seconds, peak resident memory."""
    t0 = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_SELF)
    if mode == "llm-only":
        facts = asyncio.run(_llm_only(url, slots, variations, seed))
    elif mode == "evaluation-only":
        facts = asyncio.run(_evaluation_only(workers, variations, seed))
    else:
        facts = asyncio.run(_run(url, slots, workers, variations, seed))
    after = resource.getrusage(resource.RUSAGE_SELF)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {**facts, "wall_s": time.perf_counter() - t0, "parent_cpu_s": cpu,
            "parent_peak_rss_mb": after.ru_maxrss / 1024}


class FakeServer:
    """``bench_server.py`` in its own process, for as long as the ``with`` block lasts."""

    def __init__(self, *args: str) -> None:
        self.args = args
        self.url = ""

    def __enter__(self) -> FakeServer:
        self.proc = subprocess.Popen([sys.executable, str(HERE / "bench_server.py"), *self.args],
                                     stdout=subprocess.PIPE, text=True)
        assert self.proc.stdout is not None
        self.url = self.proc.stdout.readline().split()[-1]
        return self

    def __exit__(self, *exc: object) -> None:
        self.proc.terminate()
        self.proc.wait(timeout=30)


async def _efficiency(url: str, slots: int, latency: float, waves: int) -> tuple[float, float]:
    """(efficiency over ``waves`` waves, the first wave's extra seconds). A first wave opens the N
    connections and is timed on its own (its wall over the latency is the set-up, which a run pays
    once); the efficiency is the steady state after it, so a short run's fewer waves do not make the
    set-up the figure."""
    backend = make_backend(_llm(url, slots))
    warm = [ChatRequest(user_messages(f"warm {k}"), "select", f"w@{k}") for k in range(slots)]
    requests = [ChatRequest(user_messages(f"request {k}"), "select", f"t@{k}") for k in range(slots * waves)]
    try:
        t0 = time.perf_counter()
        await asyncio.gather(*(backend.chat(r) for r in warm))
        first = time.perf_counter() - t0
        t0 = time.perf_counter()
        await asyncio.gather(*(backend.chat(r) for r in requests))
        wall = time.perf_counter() - t0
    finally:
        await backend.aclose()
    return (len(requests) / wall) / (slots / latency), first - latency


def scheduler_efficiency(latency: float, slots: tuple[int, ...] = (1, 4, 16, 64, 256),
                         waves: int = 10) -> dict[str, dict[str, float]]:
    """Achieved requests/s over what N slots of ``latency`` seconds allow, for ``waves`` x N requests
    after a first wave that opens the N connections, the server in its own process (in the
    harness's event loop it would charge its own CPU to the harness): ``efficiency`` per N, and
    ``first_wave_extra_s``, the first wave's wall over the latency (the set-up; ~0.25 s at N = 256)."""
    out: dict[str, dict[str, float]] = {"efficiency": {}, "first_wave_extra_s": {}}
    for n in slots:
        with FakeServer("--slots", str(n), "--fixed-latency", str(latency)) as server:
            efficiency, extra = asyncio.run(_efficiency(server.url, n, latency, waves))
        out["efficiency"][str(n)] = efficiency
        out["first_wave_extra_s"][str(n)] = extra
    return out


def _measure(mode: str, url: str, args: argparse.Namespace) -> dict[str, Any]:
    command = [sys.executable, str(Path(__file__).resolve()), "--harness", mode, "--url", url,
               "--slots", str(args.slots), "--workers", str(args.workers), "--variations", str(args.variations),
               "--seed", str(args.seed)]
    proc = subprocess.run(command, capture_output=True, text=True, timeout=3600)
    if proc.returncode != 0:
        raise RuntimeError(f"harness {mode} failed: {proc.stderr[-3000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def server_scale(args: argparse.Namespace) -> dict[str, Any]:
    with FakeServer("--slots", str(args.slots), "--levels", ",".join(LEVELS), "--variations", str(args.variations),
                    "--seed", str(args.seed), "--scale", str(args.scale)) as server:
        llm_only = _measure("llm-only", server.url, args)
        sys.stdout.write(f"   LLM only: {llm_only['wall_s']:.1f} s for {llm_only['tasks']} tasks\n")
        evaluation = _measure("evaluation-only", server.url, args)
        sys.stdout.write(f"   evaluation only: {evaluation['wall_s']:.1f} s ({args.workers} workers)\n")
        sys.stdout.flush()
        run = _measure("run", server.url, args)
    tasks = run["tasks"]
    return {
        "tasks": tasks, "slots": args.slots, "workers": args.workers, "llm_only_s": llm_only["wall_s"],
        "evaluation_only_s": evaluation["wall_s"], "run_wall_s": run["wall_s"],
        "run_over_llm_only": run["wall_s"] / llm_only["wall_s"],
        "pipelining_ratio": run["wall_s"] / max(llm_only["wall_s"], evaluation["wall_s"]),
        "parent_cpu_ms_per_task": 1000 * run["parent_cpu_s"] / tasks, "parent_peak_rss_mb": run["parent_peak_rss_mb"],
        "llm_only_parent_cpu_ms_per_task": 1000 * llm_only["parent_cpu_s"] / tasks,
        "overall": run["overall"], "infrastructure_failures": run["infrastructure_failures"],
        "run_folder_mb": run["run_folder_mb"],
    }


def report(figures: dict[str, Any]) -> str:
    return (f"{figures['tasks']}-task level 1-2 run, {figures['slots']} server slots, {figures['workers']} workers: "
            f"LLM only {figures['llm_only_s']:.1f} s, evaluation only {figures['evaluation_only_s']:.1f} s, "
            f"run {figures['run_wall_s']:.1f} s -> run / LLM only {figures['run_over_llm_only']:.3f}, "
            f"pipelining ratio {figures['pipelining_ratio']:.3f}; parent CPU "
            f"{figures['parent_cpu_ms_per_task']:.1f} ms/task (LLM steps alone "
            f"{figures['llm_only_parent_cpu_ms_per_task']:.1f}), "
            f"parent peak RSS {figures['parent_peak_rss_mb']:.0f} MB, "
            f"overall {100 * figures['overall']:.0f} %, run folder {figures['run_folder_mb']:.1f} MB")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--slots", type=int, default=64)
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--variations", type=int, default=20, help="per task model (50 level 1-2 models)")
    parser.add_argument("--seed", type=int, default=3000)
    parser.add_argument("--scale", type=float, default=1.0, help="multiplies every server latency")
    parser.add_argument("--json", type=Path, default=None)
    parser.add_argument("--harness", choices=("llm-only", "evaluation-only", "run"), help=argparse.SUPPRESS)
    parser.add_argument("--url", help=argparse.SUPPRESS)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.harness:
        facts = harness(args.harness, args.url, args.slots, args.workers, args.variations, args.seed)
        sys.stdout.write(json.dumps(facts) + "\n")
        return 0
    figures = server_scale(args)
    sys.stdout.write(report(figures) + "\n")
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
