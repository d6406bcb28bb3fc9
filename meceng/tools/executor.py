"""Runs one program in its own child process and reads back what the harness recorded.

Every program gets a fresh scratch directory (its cwd), its own session / process group (so a
timeout kills the program and every process it started), resource limits, a stripped and pinned
environment (``pinning``) and bounded capture of stdout/stderr. A segfault or a kill is a
verdict, not a crash of the run: the stage the program had reached is read from the harness's
``stage.log``.

The program's limit is CPU time, enforced by the kernel (RLIMIT_CPU: SIGXCPU, then SIGKILL); the
wall clock only bounds the run (``ExecutionLimits.wall_s``). Which of the two stopped it is read
from the child's own rusage (``wait4``): the CPU limit is the program's timeout, the wall clock
with CPU time to spare is the machine's (``wall_timeout``, an infrastructure failure).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import resource
import secrets
import shutil
import signal
import sys
import tempfile
import time
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import structlog

from meceng.syntax import parsing
from meceng.tools.cold import run_cold
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.pinning import PINNED_ENV
from meceng.tools.warm import WarmPool

log = structlog.get_logger(__name__)

#: Environment variables passed to the child; everything else (API keys, tokens) is dropped.
ENV_KEEP = ("PATH", "HOME", "LANG", "LC_ALL", "PYTHONPATH", "VIRTUAL_ENV", "TMPDIR", "SYSTEMROOT")


def child_env() -> dict[str, str]:
    """The child's environment: what it needs from ours, headless plotting, and the pins that make
    its work independent of the launcher (one thread per numerical library, a fixed hash seed)."""
    env = {k: os.environ[k] for k in ENV_KEEP if k in os.environ}
    env.update(MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1", PYTHONUNBUFFERED="1", **PINNED_ENV)
    return env


#: seconds between the CPU limit's SIGXCPU and the kernel's SIGKILL (a program may catch SIGXCPU)
CPU_GRACE_S = 2


def rlimits_of(limits: ExecutionLimits) -> dict[str, int]:
    """The kernel limits of a child (the warm child sets them itself, after the fork)."""
    return {"memory": limits.memory_bytes, "cpu": limits.cpu_limit_s, "cpu_hard": limits.cpu_limit_s + CPU_GRACE_S,
            "file": limits.file_bytes}


def _limit_child(limits: ExecutionLimits) -> None:
    """Runs in the child between fork and exec: resource limits only (no library calls here)."""
    resource.setrlimit(resource.RLIMIT_AS, (limits.memory_bytes, limits.memory_bytes))
    resource.setrlimit(resource.RLIMIT_CPU, (limits.cpu_limit_s, limits.cpu_limit_s + CPU_GRACE_S))
    resource.setrlimit(resource.RLIMIT_FSIZE, (limits.file_bytes, limits.file_bytes))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


async def execute(
    program: str,
    sim_block: str,
    limits: ExecutionLimits | None = None,
    scratch_root: Path | None = None,
    check: bool = True,
    pool: WarmPool | None = None,
    files: Mapping[str, Path] | None = None,
    slots: asyncio.Semaphore | None = None,
) -> Execution:
    """Statically check, then run ``program`` with ``sim_block`` as its solver block.

    With a ``pool`` the child is forked from the warm fork server, otherwise a cold interpreter
    is started; both get the same isolation. ``files`` are put into the program's working
    directory under the given names (the saved parts an assembly loads). ``slots`` bound the
    children alive at once: a slot is held only while the child lives (writing the job and reading
    the results are the parent's work, not a worker's).
    """
    limits = limits or ExecutionLimits()
    # the static check (``check``) runs in the child, before the program: see runner._refused
    scratch = Path(tempfile.mkdtemp(prefix="meceng-", dir=scratch_root))
    try:
        for name, source in (files or {}).items():
            # a copy, not a link: the program may write in its directory, the saved part stays intact
            shutil.copyfile(source, scratch / Path(name).name)
        if pool is not None:
            return await _run_warm(scratch, program, sim_block, limits, pool, check, slots)
        return await _run_in(scratch, program, sim_block, limits, check, slots)
    finally:
        if not limits.keep_scratch:
            shutil.rmtree(scratch, ignore_errors=True)


async def _run_in(scratch: Path, program: str, sim_block: str, limits: ExecutionLimits, check: bool,
                  slots: asyncio.Semaphore | None) -> Execution:
    job, token = _write_job(scratch, program, sim_block, limits, check)
    async with slots or contextlib.nullcontext():
        run = await run_cold((sys.executable, "-m", "meceng.tools.runner", str(job)), scratch, child_env(),
                             lambda: _limit_child(limits), limits.wall_s, limits.output_bytes)
    return _collect(scratch, run.returncode, run.wall_killed, run.stdout, run.stderr, run.wall_s, run.cpu_s,
                    limits, token)


def _write_job(scratch: Path, program: str, sim_block: str, limits: ExecutionLimits,
               check: bool) -> tuple[Path, str]:
    job = scratch / "job.json"
    token = secrets.token_hex(16)
    job.write_text(json.dumps({"program": program, "sim_block": sim_block, "token": token, "check": check,
                               "guard": limits.guard, "isolate_network": limits.isolate_network,
                               "mode": limits.mode, "n_modes": limits.n_modes,
                               "save_fem": limits.save_fem_to is not None,
                               "inspect_times": None if limits.inspect_times is None else list(limits.inspect_times),
                               "inspect_loads": limits.inspect_loads,
                               "motion": None if limits.motion_grid is None else
                               {"end": limits.motion_grid[0], "samples": limits.motion_grid[1]},
                               "sensor_rows": limits.sensor_rows}))
    (scratch / "program.py").write_text(program)
    return job, token


def _read_bounded_file(path: Path, limit: int) -> bytes:
    if not path.exists():
        return b""
    size = path.stat().st_size
    half = max(limit // 2, 1)
    with path.open("rb") as f:
        if size <= limit:
            return f.read()
        head = f.read(half)
        f.seek(size - half)
        return head + f"\n[... {size - 2 * half} bytes dropped ...]\n".encode() + f.read()


async def _run_warm(scratch: Path, program: str, sim_block: str, limits: ExecutionLimits,
                    pool: WarmPool, check: bool, slots: asyncio.Semaphore | None) -> Execution:
    job, token = _write_job(scratch, program, sim_block, limits, check)
    async with slots or contextlib.nullcontext():
        t0 = time.perf_counter()
        returncode, wall_killed, cpu = await pool.run(job, child_env(), rlimits_of(limits), limits.wall_s)
        wall = time.perf_counter() - t0
    stdout = _read_bounded_file(scratch / "stdout.txt", limits.output_bytes)
    stderr = _read_bounded_file(scratch / "stderr.txt", limits.output_bytes)
    # reading the result, trajectory and part files: off the event loop
    return await asyncio.to_thread(_collect, scratch, returncode, wall_killed, stdout, stderr, wall, cpu, limits,
                                   token)


def stopped_by_limit(returncode: int | None, wall_killed: bool, cpu: float | None, wall: float,
                     limits: ExecutionLimits) -> tuple[str, str] | None:
    """(error_kind, error) when a limit ended the run, else None.

    SIGXCPU is the kernel's CPU limit; SIGKILL with the CPU time past the limit its hard limit (a
    program that caught SIGXCPU). The wall clock with CPU time to spare stopped a program that
    waited (for a core on a busy machine, or in a sleep): the machine's failure, never graded."""
    over = cpu is not None and cpu >= limits.cpu_limit_s
    spent = f"{cpu:.1f} s of CPU" if cpu is not None else "CPU time unknown"
    if returncode == -signal.SIGXCPU or (over and (wall_killed or returncode == -signal.SIGKILL)):
        return "timeout", (f"timeout: the CPU time limit of {limits.timeout_s:g} s was reached ({spent} in "
                           f"{wall:.1f} s; process group killed)")
    if wall_killed:
        log.warning("execution.wall_timeout", wall_s=round(wall, 2), cpu_s=cpu, cpu_limit_s=limits.timeout_s)
        return "wall_timeout", (f"wall-clock timeout: stopped at {limits.wall_s:g} s with {spent}, under the "
                                f"CPU limit of {limits.timeout_s:g} s: the machine was too busy or the program "
                                "waited (an infrastructure failure, not the program's)")
    return None


def _collect(
    scratch: Path,
    returncode: int | None,
    wall_killed: bool,
    stdout: bytes,
    stderr: bytes,
    wall: float,
    cpu: float | None,
    limits: ExecutionLimits,
    token: str,
) -> Execution:
    out = stdout.decode(errors="replace")
    err = stderr.decode(errors="replace")
    stage_log = scratch / "stage.log"
    stages = stage_log.read_text().split() if stage_log.exists() else []
    last_stage = stages[-1] if stages else "started"
    common = {"stdout_tail": out[-4000:], "stderr_tail": err[-4000:], "returncode": returncode,
              "wall_time": wall, "cpu_time": cpu}
    stopped = stopped_by_limit(returncode, wall_killed, cpu, wall, limits)
    if stopped is not None:
        return Execution(stage=last_stage, error=stopped[1], error_kind=stopped[0], **common)
    # only the harness knows the token: a result file the program forged is ignored
    result_path = scratch / f"result-{token}.json"
    if not result_path.exists():
        if returncode is not None and returncode < 0:
            name = signal.Signals(-returncode).name if -returncode in signal.valid_signals() else str(-returncode)
            error = f"program crashed with signal {name}"
        else:
            error = f"program ended without a result (exit code {returncode})"
        return Execution(stage=last_stage, error=error, error_kind="crash", **common)
    try:
        result = json.loads(result_path.read_text())
    except (OSError, ValueError) as exc:
        return Execution(stage=last_stage, error=f"unreadable result: {exc}", error_kind="no_result", **common)
    if result.get("error_kind") == "safety":  # refused by the static check: the program never ran
        return Execution(stage="refused", error=result.get("error"), error_kind="safety", wall_time=wall,
                         cpu_time=cpu)
    times = trajectory = None
    traj_path = scratch / f"trajectory-{token}.npy"
    if traj_path.exists():
        with parsing():  # numpy parses the header with ast.literal_eval
            data = np.load(traj_path)
        times, trajectory = data[:, 0], data[:, 1:]
    part = result.get("part")
    surface = fine_surface = None
    part_path = scratch / f"part-{token}.npz"
    if part is not None and part_path.exists():
        with parsing(), np.load(part_path) as data:
            surface = (data["vertices"], data["triangles"])
            if "fine_vertices" in data:
                fine_surface = (data["fine_vertices"], data["fine_triangles"])
    motion = result.get("motion")
    motion_path = scratch / f"motion-{token}.npz"
    if isinstance(motion, dict) and motion_path.exists():
        with parsing(), np.load(motion_path) as data:
            motion = {**motion, **{key: data[key] for key in data.files}}
    fem_file = None
    fem_path = scratch / f"fem-{token}.npz"
    if limits.save_fem_to and fem_path.exists():
        Path(limits.save_fem_to).parent.mkdir(parents=True, exist_ok=True)
        shutil.move(fem_path, limits.save_fem_to)
        fem_file = limits.save_fem_to
    error = result.get("error")
    return Execution(
        part=part,
        surface=surface,
        fine_surface=fine_surface,
        part_times=result.get("part_times") or {},
        fem_file=fem_file,
        stage=str(result.get("stage", last_stage)),
        error=error,
        error_kind="exception" if error else None,
        error_line=result.get("error_line") if error else None,
        items=result.get("items"),
        system=result.get("system") or {},
        times=times,
        trajectory=trajectory,
        warnings=tuple(result.get("warnings", ())),
        solve_time=result.get("solve_time"),
        inspection=result.get("inspection"),
        sensors=result.get("sensors"),
        motion=motion if isinstance(motion, dict) and "states" in motion else None,
        **common,
    )
