"""A program is graded by its CPU time, not by the machine's load (issue 45).

Reaching the CPU limit is the program's timeout; the wall clock only bounds a run, and a run it
stops with CPU time to spare is an infrastructure failure that ``--resume`` does again. The
numerical libraries' threads, the hash seed and ARPACK's start vector are pinned, so the same
program does the same work in a cold and in a warm child. Limits here are a few seconds; how long
things take is measured by scripts/bench_cpu_time.py, never asserted.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path

from fake_ollama import FakeOllama, chat_reply, prompted_instance

from meceng.agents.prompts import gold_code, gold_selection
from meceng.eval.limits import execution_limits, limit_rows
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.pipeline.rescore import evaluate_program
from meceng.report.build import build_report
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.pinning import PINNED_ENV
from meceng.tools.warm import WarmPool

SLUG = "single_mass_oscillator"


def gold() -> str:
    return default_registry().get(SLUG).instance(0).reference_program


def with_before_assemble(program: str, code: str) -> str:
    """``code`` run right before the program's ``mbs.Assemble()``."""
    assert "mbs.Assemble()" in program
    return program.replace("mbs.Assemble()", f"{code}\nmbs.Assemble()", 1)


async def test_a_program_past_its_cpu_limit_is_the_programs_timeout() -> None:
    instance = default_registry().get(SLUG).instance(0)
    code = with_before_assemble(gold(), "while True:\n    pass")
    verdict, candidate, _ = await evaluate_program(instance, code, limits=ExecutionLimits(timeout_s=2))
    assert candidate.error_kind == "timeout" and "CPU time limit" in (candidate.error or ""), candidate.error
    assert candidate.cpu_time is not None and candidate.cpu_time >= 1.5
    assert verdict.infrastructure_error is None and verdict.first_failure == "finished_assemble"


async def test_a_program_stopped_by_the_wall_clock_with_cpu_to_spare_is_not_graded() -> None:
    instance = default_registry().get(SLUG).instance(0)
    code = "import time\ntime.sleep(60)\n" + gold()
    limits = ExecutionLimits(timeout_s=2, wall_timeout_s=3)
    verdict, candidate, _ = await evaluate_program(instance, code, limits=limits)
    assert candidate.error_kind == "wall_timeout" and candidate.lost_to_machine, candidate.error
    assert candidate.cpu_time is not None and candidate.cpu_time < 2
    assert verdict.first_failure == "infrastructure" and not verdict.overall


@contextmanager
def one_busy_core(loops: int) -> Iterator[None]:
    """This process, what it starts, and ``loops`` busy loops all on one core: a program gets about
    1 / (loops + 1) of it, however many cores the machine has. Each loop is a session of its own, as
    an inference server is: the scheduler (autogroup) shares a core between sessions first, and the
    program's child is a session of its own too."""
    before = os.sched_getaffinity(0)
    core = min(before)
    os.sched_setaffinity(0, {core})
    busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"], start_new_session=True) for _ in range(loops)]
    try:
        yield
    finally:
        for process in busy:
            process.kill()
            process.wait()
        os.sched_setaffinity(0, before)


async def test_under_load_a_program_under_its_cpu_limit_passes() -> None:
    """~1.2 s of CPU (imports, ~0.7 s of pure Python, the solve) under a 4 s CPU limit, on a core it
    shares with four busy loops: ~7 s on the wall clock here, which a 4 s wall-clock limit failed."""
    instance = default_registry().get(SLUG).instance(0)
    code = with_before_assemble(gold(), "_work = sum(i * i for i in range(15_000_000))")
    with one_busy_core(loops=4):
        verdict, candidate, _ = await evaluate_program(instance, code, limits=ExecutionLimits(timeout_s=4))
    assert candidate.error_kind is None and candidate.solved, candidate.error
    assert candidate.cpu_time is not None and candidate.cpu_time < 4
    assert verdict.overall, verdict.first_failure
    summary = candidate.summary()
    assert summary["cpu_s"] == round(candidate.cpu_time, 4) and summary["wall_s"] == round(candidate.wall_time, 4)


PINNED = f"""
import os, hashlib
import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import eigsh
n = 300
laplace = sp.diags([-np.ones(n - 1), 2 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1], format="csc")
values, vectors = eigsh(laplace, k=4, sigma=0, which="LM")
print("modes", hashlib.sha256(vectors.tobytes()).hexdigest())
print("env", {{k: os.environ.get(k) for k in {sorted(PINNED_ENV)!r}}})
print("hash", hash("meceng"))
"""


def _printed(stdout: str) -> dict[str, str]:
    return dict(line.split(" ", 1) for line in stdout.splitlines() if line.split(" ", 1)[0] in ("modes", "env", "hash"))


async def test_cold_and_warm_children_are_pinned_alike() -> None:
    """ARPACK starts from a random vector unless told otherwise: the same part's modes came out
    another way at every making (and an assembly on them took 12 to 42,000 steps)."""
    pool = WarmPool(child_env())
    try:
        runs = [await execute(PINNED, "", ExecutionLimits(timeout_s=30, guard=False), check=False, pool=p)
                for p in (None, None, pool, pool)]
    finally:
        await pool.close()
    printed = [_printed(run.stdout_tail) for run in runs]
    assert all(p.keys() == {"modes", "env", "hash"} for p in printed), [run.stdout_tail for run in runs]
    assert all(p == printed[0] for p in printed), printed
    assert printed[0]["env"] == repr(dict(sorted(PINNED_ENV.items())))


def test_the_report_counts_executions_at_each_limit(tmp_path: Path) -> None:
    records = [
        {"execution": {"stage": "finished_assemble", "error_kind": "timeout", "cpu_s": 60.2, "wall_s": 61.0},
         "reference_execution": {"stage": "solved", "error_kind": None, "cpu_s": 1.0, "wall_s": 1.1}},
        {"execution": {"stage": "started", "error_kind": "wall_timeout", "cpu_s": 3.0, "wall_s": 190.0},
         "reference_execution": {"stage": "solved", "error_kind": None, "cpu_s": 1.0, "wall_s": 1.2}},
        {"execution": {"stage": "no_code", "error_kind": "no_code"}},  # nothing ran
        {"execution": {"stage": "solved", "error_kind": None, "wall_time": 0.5}},  # a record before issue 45
    ]
    counts = execution_limits(records)
    assert (counts["executions"], counts["cpu_limit"], counts["wall_bound"]) == (5, 1, 1)
    assert counts["cpu_s_max"] == 60.2 and counts["wall_s_max"] == 190.0
    assert limit_rows([("run", records)])[0][:4] == ["run", "5", "1", "1"]


class SleepsFirst:
    """A model that writes the ground truth with a 4 s sleep in front (wall time, no CPU)."""

    def __init__(self, instances: list) -> None:
        self.instances = instances

    def __call__(self, body: dict) -> tuple[int, dict, dict]:
        prompt = body["messages"][-1]["content"]
        instance = prompted_instance(self.instances, prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code("import time\ntime.sleep(4)\n" + instance.reference_program)), {}


async def test_a_run_lost_to_the_wall_clock_is_counted_apart_and_resumed(tmp_path: Path, monkeypatch) -> None:
    """A busy machine, played by a wall-clock bound shorter than the program's sleep: the task is
    lost, not failed; resumed with room on the wall clock, the same (cached) program passes."""
    registry = default_registry()
    instances = registry.instances(registry.select(("1",), (SLUG,)), 0, 1)
    async with FakeOllama(SleepsFirst(instances)) as server:
        llm = LLMSettings(model="fake:1b", backend="ollama", hosts=(server.url,), max_attempts=1, batch_size=1)
        settings = RunSettings(llm=llm, levels=("1",), only=(SLUG,), variations=1, out=tmp_path, run_name="run",
                               progress=False, workers=2, exec_timeout_s=1)
        monkeypatch.setattr("meceng.tools.execution.WALL_MARGIN_S", 0.0)  # bound: 3 x 1 s CPU = 3 s
        path = await run_benchmark(settings)
        run = json.loads(path.read_text())
        (record,) = run["tasks"]
        assert record["first_failure"] == "infrastructure" and "wall-clock" in record["infrastructure_error"]
        execution = record["execution"]
        assert execution["error_kind"] == "wall_timeout" and execution["cpu_s"] < 1 <= execution["wall_s"]
        assert record["reference_execution"]["cpu_s"] is not None
        limits = run["summary"]["limits"]
        assert (limits["executions"], limits["cpu_limit"], limits["wall_bound"]) == (2, 0, 1)
        assert run["summary"]["counted"] == 0
        report = build_report([path], tmp_path / "report")
        assert "| 2 | 0 | 1 |" in report["markdown"].read_text()

        monkeypatch.setattr("meceng.tools.execution.WALL_MARGIN_S", 10.0)  # bound: 13 s
        resumed = await run_benchmark(replace(settings, resume=True))
    (record,) = json.loads(resumed.read_text())["tasks"]
    assert record["overall"], record["first_failure"]
    assert record["execution"]["error_kind"] is None and record["execution"]["cpu_s"] < 1
