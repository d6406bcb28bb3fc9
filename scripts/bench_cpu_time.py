"""The same program through every launcher: CPU time, wall time and solver steps (issue 45).

A program is graded by its CPU time, so the same deterministic program must do the same work
however it is started. This runs one corpus answer (default: the flexible pendulum on a wrong
hinge axis, a Newton solve on the edge of convergence whose step count follows the last bits of
its inputs) through each launcher and prints what it cost there:

* ``plain``: ``python program.py`` in a folder with the part, in this shell's environment;
* ``plain-pinned``: the same with the children's pinned environment (``child_env``);
* ``cold`` / ``warm``: the executor, a fresh interpreter / a child of the fork server;
* ``evaluate_program``: the grading function, which makes the assembly's parts itself;
* ``meceng-evaluate``: the command line, in a process of its own.

Each launcher but the last two gets a part made just before it, as a launcher makes its own (the
making is what ARPACK's random start vector changed). The part's mode basis digest is printed per
line: equal digests, equal parts. Timings are this machine's, under whatever load it has: compare
CPU seconds and steps, not wall seconds. Usage::

    python scripts/bench_cpu_time.py [--answer tests/corpus/X.py] [--launchers plain,cold,...] [--timeout 300]
"""

from __future__ import annotations

import argparse
import asyncio
import hashlib
import json
import os
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from meceng.eval.chain import Tolerances
from meceng.pipeline.evaluation import Evaluator
from meceng.pipeline.rescore import evaluate_program
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.warm import WarmPool

ROOT = Path(__file__).resolve().parents[1]

DEFAULT = ROOT / "tests" / "corpus" / "3b_flexible_pendulum_hinge_about_x.py"
LAUNCHERS = ("plain", "plain-pinned", "cold", "warm", "evaluate_program", "meceng-evaluate")
#: appended to the program in the plain launchers: the steps the solver took
STEPS = "\nprint('bench-steps', mbs.sys['dynamicSolver'].it.currentStepIndex)\n"


def label(path: Path) -> dict[str, str]:
    first = path.read_text().splitlines()[0].removeprefix("# corpus: ")
    return dict(item.split("=", 1) for item in shlex.split(first))


def modes_digest(folder: Path) -> str:
    digests = []
    for part in sorted(folder.glob("*.npz")):
        with np.load(part, allow_pickle=True) as data:
            digests.append(hashlib.sha256(data["modeBasis"][()]["matrix"].tobytes()).hexdigest()[:10])
    return ",".join(digests) or "-"


async def make_parts(instance: TaskInstance, folder: Path, limits: ExecutionLimits) -> dict[str, Path]:
    evaluator = Evaluator(1, limits, Tolerances())
    return await evaluator.ground_truth_parts(instance, folder) if instance.kind == "assembly" else {}


def plain(program: str, folder: Path, env: dict[str, str], timeout: float) -> tuple[float, str, str]:
    """Wall seconds, solver steps and the last output line of ``python program.py`` in ``folder``."""
    (folder / "program.py").write_text(program + STEPS)
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "program.py"], cwd=folder, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        out, _ = proc.communicate(timeout=timeout * 3)
    except subprocess.TimeoutExpired:
        proc.kill()
        out = "killed by the bench's wall bound"
    steps = next((line.split()[1] for line in out.splitlines() if line.startswith("bench-steps")), "failed")
    return time.perf_counter() - t0, steps, out.strip().splitlines()[-1][:80] if out.strip() else ""


def children_cpu() -> float:
    """CPU seconds of this process's reaped children: the plain launchers run one child at a time
    (the fork server, a child too, is reaped only at the end)."""
    import resource

    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def row(launcher: str, cpu: float | None, wall: float, steps: object, digest: str, note: str = "") -> None:
    print(f"{launcher:<17} cpu {'-' if cpu is None else f'{cpu:7.2f}'} s  wall {wall:7.2f} s  steps {steps!s:>7}  "
          f"modes {digest}  {note}", flush=True)


def from_execution(launcher: str, run: Execution, digest: str) -> None:
    steps = len(run.times) if run.times is not None else f"({run.stage})"  # as the record counts them
    row(launcher, run.cpu_time, run.wall_time, steps, digest, run.error_kind or "")


async def one(launcher: str, instance: TaskInstance, program: str, limits: ExecutionLimits, answer: Path,
              pool: WarmPool | None) -> None:
    with tempfile.TemporaryDirectory(prefix="bench-cpu-") as tmp:
        folder = Path(tmp)
        if launcher == "evaluate_program":
            _, run, _ = await evaluate_program(instance, program, limits=limits)
            from_execution(launcher, run, "(its own)")
            return
        if launcher == "meceng-evaluate":
            t0 = time.perf_counter()
            done = subprocess.run([sys.executable, "-m", "meceng.cli", "evaluate", instance.slug, "--seed",
                                   str(instance.seed), "--code", str(answer), "--timeout", f"{limits.timeout_s:g}",
                                   "--json"], capture_output=True, text=True, check=False)
            data = json.loads(done.stdout) if done.stdout.strip().startswith("{") else {"execution": {}}
            run = data["execution"]
            row(launcher, run.get("cpu_s"), run.get("wall_s", time.perf_counter() - t0), run.get("steps"),
                "(its own)", run.get("error_kind") or "")
            return
        files = await make_parts(instance, folder, limits)
        digest = modes_digest(folder)
        if launcher.startswith("plain"):
            env = child_env() if launcher == "plain-pinned" else dict(os.environ)
            before = children_cpu()
            wall, steps, last = await asyncio.to_thread(plain, program, folder, env, limits.timeout_s)
            row(launcher, children_cpu() - before, wall, steps, digest, "" if steps != "failed" else last)
            return
        run = await execute(program, instance.sim.block(), limits, files=files,
                            pool=pool if launcher == "warm" else None)
        from_execution(launcher, run, digest)


async def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--answer", type=Path, default=DEFAULT, help="a corpus answer (its label names the task)")
    parser.add_argument("--launchers", default=",".join(LAUNCHERS), help=f"comma-separated, of {', '.join(LAUNCHERS)}")
    parser.add_argument("--repeat", type=int, default=1, help="runs per launcher")
    parser.add_argument("--timeout", type=float, default=300.0, help="CPU seconds per program (generous: measuring)")
    args = parser.parse_args()
    fields = label(args.answer)
    instance = default_registry().get(fields["task"]).instance(int(fields["seed"]))
    limits = ExecutionLimits(timeout_s=args.timeout)
    program = args.answer.read_text()
    print(f"{args.answer.name}: task {instance.key}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}; "
          f"OMP_NUM_THREADS here: {os.environ.get('OMP_NUM_THREADS', 'unset')}", flush=True)
    pool = WarmPool(child_env())
    await pool.start()  # started before the clock runs
    try:
        for launcher in args.launchers.split(","):
            for _ in range(args.repeat):
                await one(launcher.strip(), instance, program, limits, args.answer, pool)
    finally:
        await pool.close()


if __name__ == "__main__":
    asyncio.run(main())
