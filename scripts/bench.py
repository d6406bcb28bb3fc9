#!/usr/bin/env python
"""Throughput figures of the harness on this machine, measured side by side in one run.

1. isolation overhead per program, warm fork server vs cold interpreter (empty program and a
   typical level 1 task), and the ratio;
2. evaluation throughput (tasks/s) on 1 core and on all cores, the scaling ratio beside the
   machine's own for a pure-CPU loop;
3. scheduler efficiency against a fake Ollama (its own process) with N slots and a fixed latency of
   2 s and 0.5 s: achieved requests/s divided by N / latency, for N = 1, 4, 16, 64, 256;
4. pipelining: wall time of a run with simulated LLM latency divided by
   max(LLM-only time, evaluation-only time), evaluation only grading exactly as the run grades
   (behaviour included); beside it, as figures of their own, what behaviour adds per task (the motion
   recording, the converged ground truth's extra runs, the comparison) and what the preflight costs
   a run (the run is timed without it);
5. server scale (``bench_scale.py``): a 1000-task level 1-2 run against a 64-slot server with
   realistic latencies, its wall over its LLM-only time, the harness's CPU per task and peak memory;
6. the harness's CPU per request through the OpenAI backend against a real server (llama.cpp's,
   ``bench_real_server.py``, needs the ``servers`` extra) beside the fake one;
7. a sweep (``bench_farm.py``): 4 models on 4 one-slot servers at a fixed latency, the sweep's wall
   over the longest single run's wall;
8. the reference store: a 4-model level-3a sweep's evaluation CPU with the store over without;
9. ``rescore`` of a 1000-task gold run, as before (cold interpreters, grading on the parent's threads)
   against now (the warm fork server, the grading pool).

    python scripts/bench.py [--json FILE] [--quick]
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import os
import statistics
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import bench_farm
import bench_real_server
import bench_scale

from meceng.agents.steps import choose_components, generate_code
from meceng.catalog.catalogs import rigid_catalog
from meceng.eval.behaviour import compare_behaviour, tolerance_for
from meceng.eval.chain import Tolerances
from meceng.llm.backend_ollama import OllamaBackend
from meceng.llm.types import LLMSettings
from meceng.pipeline import Evaluator, RunSettings, run_benchmark
from meceng.pipeline.grading import GradingPool
from meceng.pipeline.preflight import check_stack
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.recording import MOTION_SAMPLES
from meceng.tools.warm import WarmPool

FIRST_TWELVE = ("1", "2", "3", "4", "9", "11", "12", "19", "23", "29", "35", "43")
#: The pipelined run's size in both the quick and the full bench: a run's head (the first answers
#: before the first program) and tail (the last program after the last answer) cannot overlap, and
#: a 12-task run made them the figure (1.39 for 1.8 s of LLM and 1.9 s of evaluation)
PIPELINED_VARIATIONS = 4


async def isolation_overhead(repeats: int) -> dict[str, float]:
    instance = default_registry().get("single_mass_oscillator").instance(0)
    pool = WarmPool(child_env())
    await pool.start()
    out: dict[str, float] = {}
    try:
        for label, program in (("empty", ""), ("l1_task", instance.reference_program)):
            for mode, use in (("warm", pool), ("cold", None)):
                times = []
                for _ in range(repeats):
                    t0 = time.perf_counter()
                    await execute(program, instance.sim.block(), check=False, pool=use)
                    times.append(time.perf_counter() - t0)
                out[f"{label}_{mode}_ms"] = 1000 * statistics.median(times)
    finally:
        await pool.close()
    out["cold_over_warm_overhead"] = out["empty_cold_ms"] / out["empty_warm_ms"]
    out["l1_cold_over_warm"] = out["l1_task_cold_ms"] / out["l1_task_warm_ms"]
    return out


async def _evaluate_all(instances, workers: int, count_start: bool = False) -> float:
    """Grade every instance's ground truth as a candidate, as a run does: the programs on the fork
    server's workers, grading in the grading pool beside them. ``count_start``: the time includes
    starting the fork server and the grading pool, which a run pays too (the pipelining baseline);
    without it, the steady state of a run under way (the throughput figures)."""
    t_start = time.perf_counter()
    pool = WarmPool(child_env())
    await pool.start()
    grading = GradingPool(workers)
    await grading.warm()  # the pool's processes started and warm, as in a run that is under way
    evaluator = Evaluator(workers, ExecutionLimits(), Tolerances(), rigid_catalog(), pool, grading=grading)
    t0 = t_start if count_start else time.perf_counter()
    try:
        verdicts = await asyncio.gather(*(evaluator.evaluate(i, i.reference_program, i.required_components, None)
                                          for i in instances))
    finally:
        await pool.close()
        grading.close()
    assert all(v[0].overall for v in verdicts), "a gold program failed during the benchmark"
    return time.perf_counter() - t0


def _burn(n: int) -> float:
    t0 = time.perf_counter()
    x = 0
    for i in range(n):
        x += i * i
    return time.perf_counter() - t0


def _loop_rate(processes: int, seconds: float) -> float:
    """Loops a second of a pure-CPU loop in ``processes`` processes, each running ~``seconds``."""
    import multiprocessing as mp

    n = max(1, int(seconds * 12_000_000))
    with mp.get_context("fork").Pool(processes) as pool:
        t0 = time.perf_counter()
        pool.map(_burn, [n] * processes)
        return processes / (time.perf_counter() - t0)


def _run_job(job: str) -> None:
    """One program in a child forked from this pool process, as the fork server forks one."""
    from meceng.tools.warm import child_main

    pid = os.fork()
    if pid == 0:
        child_main(job, _BARE["env"], _BARE["limits"])
    os.waitpid(pid, 0)


_BARE: dict[str, Any] = {}


def _bare_start(env: dict[str, str], limits: dict[str, int]) -> None:
    from meceng.tools import forkserver

    forkserver._preload()
    _BARE.update(env=env, limits=limits)


def _programs_rate(instances: list[Any], processes: int) -> float:
    """Both programs of every task (the reference and the checked one, as a task runs them), each
    in a child forked by one of ``processes`` plain pool processes: the same children's work with
    no harness around it (no event loop, no grading, no fork server protocol)."""
    import multiprocessing as mp

    from meceng.tools.executor import _write_job, rlimits_of

    limits = ExecutionLimits()
    rlimits = rlimits_of(limits)
    with tempfile.TemporaryDirectory() as root:
        jobs = []
        for k, instance in enumerate(instances):
            for check in (False, True):
                scratch = Path(root) / f"{k}-{check}"
                scratch.mkdir()
                job, _ = _write_job(scratch, instance.reference_program, instance.sim.block(),
                                    replace(limits, inspect_times=(instance.sim.end_time,)), check)
                jobs.append(str(job))
        with mp.get_context("fork").Pool(processes, initializer=_bare_start, initargs=(child_env(), rlimits)) as pool:
            t0 = time.perf_counter()
            pool.map(_run_job, jobs, chunksize=1)
            return len(jobs) / (time.perf_counter() - t0)


async def _tasks_rate(instances: list[Any], workers: int) -> float:
    return len(instances) / await _evaluate_all(instances, workers)


class _on_cores:
    """Run this process and every process it starts meanwhile on the first ``count`` cores. The
    affinity is a thread's: every thread of the process is moved (a worker thread of asyncio's
    executor made while pinned would stay pinned, and fork its pool processes pinned)."""

    def __init__(self, count: int, every: set[int]) -> None:
        self.count, self.every = count, every

    @staticmethod
    def _move(cores: set[int]) -> None:
        for tid in os.listdir("/proc/self/task"):
            with contextlib.suppress(ProcessLookupError):  # a thread that just ended
                os.sched_setaffinity(int(tid), cores)

    def __enter__(self) -> None:
        self._move(set(sorted(self.every)[: self.count]))

    def __exit__(self, *exc: object) -> None:
        self._move(self.every)


async def throughput(variations: int, rounds: int = 3) -> dict[str, Any]:
    """Evaluation throughput on 1 core (1 worker; the fork server, its children, the grading pool and
    this process pinned to one core) and on every core (a worker per core), beside what the machine
    gives in the same round for a pure-CPU loop and for the same programs without the harness,
    1 process on 1 core against a process per core. A shared VM's cores come and go (the loop's
    own scaling read 1.4x-2.2x here within minutes), so the ratios are taken within each round and
    the median of the rounds is reported. Also the old figure: 1 worker on every core (its parent
    and grading pool then use the other cores for free, so it is not a 1-core figure)."""
    registry = default_registry()
    instances = registry.instances(registry.select(None, FIRST_TWELVE), 1000, variations)
    cores = os.cpu_count() or 1
    every = os.sched_getaffinity(0)
    rows = []
    for _ in range(rounds):
        row: dict[str, float] = {}
        # the loop first: the programs' network namespaces are torn down by the kernel after they
        # end, on whichever core is free, and would slow a loop measured right after them
        for name, measure in (
                ("loop", lambda n: asyncio.to_thread(_loop_rate, n, 2.0)),
                ("programs", lambda n: asyncio.to_thread(_programs_rate, instances, n)),
                ("eval", lambda n: _tasks_rate(instances, n))):
            await asyncio.sleep(1.0)
            with _on_cores(1, every):
                row[f"{name}_1"] = await measure(1)
            await asyncio.sleep(1.0)
            row[f"{name}_n"] = await measure(cores)
        row["eval_1worker"] = await _tasks_rate(instances, 1)
        for name in ("eval", "programs", "loop"):
            row[f"{name}_scaling"] = row[f"{name}_n"] / row[f"{name}_1"]
        row["over_loop"] = row["eval_scaling"] / row["loop_scaling"]
        row["over_programs"] = row["eval_scaling"] / row["programs_scaling"]
        rows.append(row)

    def median(key: str) -> float:
        return statistics.median(r[key] for r in rows)

    return {"tasks": len(instances), "cores": cores, "rounds": rounds,
            "tasks_per_s_1core": median("eval_1"), f"tasks_per_s_{cores}cores": median("eval_n"),
            "tasks_per_s_1worker_all_cores": median("eval_1worker"),
            "scaling_all_cores": median("eval_scaling"), "hardware_scaling": median("loop_scaling"),
            "programs_scaling": median("programs_scaling"), "scaling_over_hardware": median("over_loop"),
            "scaling_over_programs": median("over_programs"), "samples": rows}


async def behaviour_cost(instances: list[Any]) -> dict[str, float]:
    """What behaviour adds to grading, per task, on one worker (the programs one after another on the
    warm fork server, so each figure is one program's wall): the child's recording of every body's
    motion (the ground truth with and without it), the converged ground truth's runs beyond the
    nominal one (at least the run with twice the steps; once per instance, then in the reference
    store) and the comparison in the parent."""
    pool = WarmPool(child_env())
    await pool.start()
    evaluator = Evaluator(1, ExecutionLimits(), Tolerances(), rigid_catalog(), pool)
    plain_s = recorded_s = converged_s = compare_s = 0.0
    try:
        for instance in instances:
            plain = ExecutionLimits(inspect_times=(instance.sim.end_time,))
            t0 = time.perf_counter()
            await execute(instance.reference_program, instance.sim.block(), plain, check=False, pool=pool)
            plain_s += time.perf_counter() - t0
            t0 = time.perf_counter()
            truth = await evaluator.references.get(instance)
            recorded_s += time.perf_counter() - t0
            t0 = time.perf_counter()
            await evaluator.converged.get(instance)
            converged_s += time.perf_counter() - t0
            t0 = time.perf_counter()
            compare_behaviour(truth.motion, truth.motion, tolerance_for(instance.slug))
            compare_s += time.perf_counter() - t0
    finally:
        await pool.close()
    n = len(instances)
    return {"tasks": n, "motion_samples": MOTION_SAMPLES, "run_ms": 1000 * plain_s / n,
            "recording_ms": 1000 * (recorded_s - plain_s) / n, "converged_truth_ms": 1000 * converged_s / n,
            "comparison_ms": 1000 * compare_s / n}


async def preflight_cost(instances: list[Any], cores: int) -> float:
    """The preflight a run makes before its first request (the probe program and the cheapest ground
    truth of each kind), on a fresh fork server and grading pool as a run's: seconds per run."""
    pool = WarmPool(child_env())
    grading = GradingPool(cores)
    evaluator = Evaluator(cores, ExecutionLimits(), Tolerances(), rigid_catalog(), pool, grading=grading)
    try:
        t0 = time.perf_counter()
        checks = await check_stack(instances, evaluator)
        wall = time.perf_counter() - t0
    finally:
        await pool.close()
        grading.close()
    assert all(c.ok for c in checks), [c for c in checks if not c.ok]
    return wall


def _machine_cpu_s() -> float:
    """The whole machine's busy CPU seconds so far (user, nice, system, irq and softirq of
    ``/proc/stat``): what a section cost every process on the machine, the kernel's included."""
    fields = [int(x) for x in Path("/proc/stat").read_text().split("\n", 1)[0].split()[1:8]]
    user, nice, system, _idle, _iowait, irq, softirq = fields
    return (user + nice + system + irq + softirq) / os.sysconf("SC_CLK_TCK")


async def pipelining(latency: float, variations: int, rounds: int, behaviour_tasks: int) -> dict[str, Any]:
    """A run's wall over max(LLM only, evaluation only), the run without its preflight and both
    starting their fork server and grading pool (a run starts them while its first requests are out:
    that overlap is part of what the figure measures). The evaluation and the run are measured in
    ``rounds`` pairs in alternating order, each after a pause: whichever came second in a pair was
    slower (ratios 1.21 with the run second, 1.05 with it first, minutes apart; not the kernel's
    teardown of the programs' network namespaces, ~1 ms of CPU each). The figure is the median of
    the pairs' ratios: on this 2-core VM the same evaluation varies by 10-20 % from one minute to the
    next (11-19 s, its CPU seconds by as much), so one slow pair must not be the figure. Beside it,
    the machine's busy CPU seconds of the run over the evaluation's: what the run adds as work,
    which the wall's noise hides."""
    registry = default_registry()
    models = registry.select(None, FIRST_TWELVE)
    instances = registry.instances(models, 2000, variations)
    slots = 2
    cores = os.cpu_count() or 1
    # The server in its own process, as in section 3: in the harness's event loop its request handling
    # would take the CPU the grading workers need, and count as the harness's
    with bench_scale.FakeServer("--slots", "64", "--only", ",".join(FIRST_TWELVE), "--variations", str(variations),
                                "--seed", "2000", "--latency", str(latency)) as server:
        llm = LLMSettings(model="bench", backend="ollama", hosts=(server.url,), batch_size=slots)
        catalog = rigid_catalog()
        backend = OllamaBackend(llm)
        t0 = time.perf_counter()

        async def llm_only(instance):
            selection = await choose_components(backend, instance, catalog)
            await generate_code(backend, instance, catalog, selection)

        await asyncio.gather(*(llm_only(i) for i in instances))
        llm_time = time.perf_counter() - t0
        await backend.aclose()
        settings = RunSettings(llm=llm, only=FIRST_TWELVE, variations=variations, seed=2000, run_name="bench",
                               workers=cores, progress=False, preflight=False)
        parent_cpu: list[float] = []

        async def pipelined() -> tuple[float, float]:
            await asyncio.sleep(3.0)
            with tempfile.TemporaryDirectory() as out:
                t0, cpu0, machine0 = time.perf_counter(), time.process_time(), _machine_cpu_s()
                run_json = await run_benchmark(replace(settings, out=Path(out)))
                wall = time.perf_counter() - t0
                parent_cpu.append(time.process_time() - cpu0)
                machine = _machine_cpu_s() - machine0
                assert json.loads(run_json.read_text())["summary"]["rates"]["overall"] == 1.0
            return wall, machine

        async def evaluation() -> tuple[float, float]:
            await asyncio.sleep(3.0)
            machine0 = _machine_cpu_s()
            wall = await _evaluate_all(instances, cores, count_start=True)
            return wall, _machine_cpu_s() - machine0

        pairs, cpu_pairs = [], []
        for k in range(rounds):
            if k % 2 == 0:
                eval_time, eval_cpu = await evaluation()
                wall, run_cpu = await pipelined()
            else:
                wall, run_cpu = await pipelined()
                eval_time, eval_cpu = await evaluation()
            pairs.append((eval_time, wall, wall / max(llm_time, eval_time)))
            cpu_pairs.append(run_cpu / eval_cpu)
    preflight_s = await preflight_cost(instances, cores)
    behaviour = await behaviour_cost(instances[:behaviour_tasks])
    return {"tasks": len(instances), "llm_only_s": llm_time,
            "evaluation_only_s": statistics.median(p[0] for p in pairs),
            "pipelined_s": statistics.median(p[1] for p in pairs),
            "pipelining_ratio": statistics.median(p[2] for p in pairs), "pairs": pairs,
            "run_over_evaluation_cpu": statistics.median(cpu_pairs), "cpu_pairs": cpu_pairs,
            "preflight_s": preflight_s, "behaviour": behaviour,
            "parent_cpu_ms_per_task": 1000 * statistics.mean(parent_cpu) / len(instances)}


def stamp(t0: float) -> str:
    """The bench's own time so far, before each figure: which section costs the run its minutes."""
    return f"[{time.perf_counter() - t0:5.0f} s] "


async def main_async(quick: bool) -> dict[str, object]:
    results: dict[str, object] = {}
    t0 = time.perf_counter()
    iso = await isolation_overhead(5 if quick else 15)
    print(stamp(t0) + f"1. isolation overhead (median per program): empty program cold {iso['empty_cold_ms']:.0f} ms, "
          f"warm {iso['empty_warm_ms']:.1f} ms -> cold/warm {iso['cold_over_warm_overhead']:.1f}x; "
          f"L1 task cold {iso['l1_task_cold_ms']:.0f} ms, warm {iso['l1_task_warm_ms']:.1f} ms "
          f"-> {iso['l1_cold_over_warm']:.1f}x", flush=True)
    tp = await throughput(2 if quick else 4, 1 if quick else 3)
    cores = tp["cores"]
    print(stamp(t0) + f"2. evaluation throughput ({tp['tasks']} gold tasks, median of {tp['rounds']} rounds): 1 core "
          f"{tp['tasks_per_s_1core']:.2f} tasks/s, {cores} cores {tp[f'tasks_per_s_{cores}cores']:.2f} tasks/s -> "
          f"scaling {tp['scaling_all_cores']:.2f}x; in the same rounds the machine gives {tp['hardware_scaling']:.2f}x "
          f"for a pure-CPU loop and {tp['programs_scaling']:.2f}x for the same programs without the harness -> "
          f"{tp['scaling_over_hardware']:.2f} of the loop's, {tp['scaling_over_programs']:.2f} of the programs' "
          f"(1 worker on all cores: {tp['tasks_per_s_1worker_all_cores']:.2f} tasks/s)", flush=True)
    sched = {}
    for latency in (2.0, 0.5):
        sched[f"{latency:g}s"] = await asyncio.to_thread(
            bench_scale.scheduler_efficiency, latency, (1, 4, 16, 64, 256), 3 if quick else 10)
        figures = sched[f"{latency:g}s"]
        print(stamp(t0) + f"3. scheduler efficiency at {latency:g} s latency (achieved req/s / (N / latency) "
              "after a first wave "
              "that opens the connections, server in its own process): "
              + ", ".join(f"N={n}: {v:.3f}" for n, v in figures["efficiency"].items())
              + "; the first wave's set-up: "
              + ", ".join(f"{v:.2f} s" for v in figures["first_wave_extra_s"].values()), flush=True)
    # five pairs in the full bench: its three gave 1.04, 1.12, 1.16 on a day the quick bench's three gave
    # 1.06, 1.01, 0.96; two more pairs cost ~80 s, which the quick bench's 8 minutes cannot spare
    pipe = await pipelining(latency=0.15, variations=PIPELINED_VARIATIONS, rounds=3 if quick else 5,
                            behaviour_tasks=24)
    b = pipe["behaviour"]
    print(stamp(t0) + f"4. pipelining ({pipe['tasks']} tasks, the medians of {len(pipe['pairs'])} pairs, their ratios "
          + ", ".join(f"{p[2]:.2f}" for p in pipe["pairs"]) + f"): LLM only {pipe['llm_only_s']:.1f} s, "
          "evaluation only (behaviour "
          f"included) {pipe['evaluation_only_s']:.1f} s, pipelined run {pipe['pipelined_s']:.1f} s -> ratio "
          f"{pipe['pipelining_ratio']:.2f}; the machine's CPU seconds, run over evaluation: "
          f"{pipe['run_over_evaluation_cpu']:.2f}, the harness's own {pipe['parent_cpu_ms_per_task']:.0f} ms a task; "
          f"the run's preflight, timed on its own: {pipe['preflight_s']:.1f} s a run; "
          f"behaviour per task (one worker, {b['tasks']} tasks): the ground truth {b['run_ms']:.0f} ms, its motion "
          "recording "
          f"+{b['recording_ms']:.0f} ms, the converged ground truth's runs +{b['converged_truth_ms']:.0f} ms (once "
          f"per instance), the comparison {b['comparison_ms']:.1f} ms", flush=True)
    scale_args = bench_scale.build_parser().parse_args(
        ["--variations", "1", "--scale", "0.3"] if quick else ["--variations", "10"])
    print(stamp(t0) + "5. server scale:", flush=True)
    scale = await asyncio.to_thread(bench_scale.server_scale, scale_args)
    print(stamp(t0) + "5. " + bench_scale.report(scale), flush=True)
    real = await asyncio.to_thread(bench_real_server.real_server_overhead, 12 if quick else 24)
    print(stamp(t0) + "6. " + bench_real_server.report(real), flush=True)
    results.update(
        cold_over_warm_overhead=iso["cold_over_warm_overhead"], scaling_all_cores=tp["scaling_all_cores"],
        hardware_scaling=tp["hardware_scaling"], scaling_over_hardware=tp["scaling_over_hardware"],
        scaling_over_programs=tp["scaling_over_programs"],
        scheduler_efficiency=sched, pipelining_ratio=pipe["pipelining_ratio"], cores=cores,
        server_scale=scale, run_over_llm_only=scale["run_over_llm_only"],
        parent_cpu_ms_per_task=scale["parent_cpu_ms_per_task"], parent_peak_rss_mb=scale["parent_peak_rss_mb"],
        real_server_overhead=real,
        details={"isolation": iso, "throughput": tp, "pipelining": pipe},
        bench_wall_s=time.perf_counter() - t0,
    )
    results["farm"] = await farm_figures(quick, t0)
    results["bench_wall_s"] = time.perf_counter() - t0
    print(f"bench finished in {results['bench_wall_s']:.0f} s")
    return results


async def farm_figures(quick: bool, t0: float) -> dict[str, object]:
    """7-9: a sweep of 4 models on 4 servers, the reference store, rescore with and without the
    grading pool (``bench_farm.py``)."""
    cores = os.cpu_count() or 1
    latency = 1.0  # shorter, 4 one-slot runs on 2 cores are bound by their evaluation, not their servers
    conc = await bench_farm.concurrency(latency, 1, cores, singles=1 if quick else bench_farm.MODELS)
    print(stamp(t0) + f"7. sweep: 4 models on 4 one-slot servers ({latency:g} s a request) -> sweep wall / longest run "
          f"{conc['sweep_over_longest_run']:.3f}", flush=True)
    store = await bench_farm.store_cpu(1, cores, bench_farm.PARTS[:2] if quick else bench_farm.PARTS)
    print(stamp(t0) + f"8. reference store: level-3a evaluation CPU of a 4-model sweep with / without the store "
          f"{store['store_cpu_ratio']:.3f} (floor {store['floor_new_store']:.3f}); with the store a sweep filled "
          f"{store['filled_store_cpu_ratio']:.3f} (floor {store['floor_filled_store']:.3f})", flush=True)
    rescore = await bench_farm.rescore_figures(1 if quick else 4, cores,
                                               ("before", "now") if quick else ("before", "fork_threads", "now"))
    print(stamp(t0) + f"9. rescore of a {rescore['tasks']}-task run: before (cold interpreters, grading on the "
          "parent's "
          f"threads) {rescore['before_s']:.0f} s, now (fork server, grading pool) {rescore['now_s']:.0f} s", flush=True)
    return {"sweep_over_longest_run": conc["sweep_over_longest_run"], "store_cpu_ratio": store["store_cpu_ratio"],
            "rescore": rescore, "details": {"sweep": conc, "store": store}}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--json", type=Path, default=None, help="write the figures to this file")
    parser.add_argument("--quick", action="store_true", help="fewer repetitions (for a smoke test)")
    args = parser.parse_args(argv)
    results = asyncio.run(main_async(args.quick))
    if args.json:
        args.json.write_text(json.dumps(results, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
