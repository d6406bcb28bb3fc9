"""Runs one program in its own child process and reads back what the harness recorded.

Every program gets a fresh scratch directory (its cwd), its own session / process group (so a
timeout kills the program and every process it started), resource limits, a stripped
environment and bounded capture of stdout/stderr. A segfault or a kill is a verdict, not a crash
of the run: the stage the program had reached is read from the harness's ``stage.log``.
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

from meceng.syntax import parsing
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.warm import WarmPool

#: Environment variables passed to the child; everything else (API keys, tokens) is dropped.
ENV_KEEP = ("PATH", "HOME", "LANG", "LC_ALL", "PYTHONPATH", "VIRTUAL_ENV", "TMPDIR", "SYSTEMROOT")


def child_env() -> dict[str, str]:
    env = {k: os.environ[k] for k in ENV_KEEP if k in os.environ}
    env.update(
        MPLBACKEND="Agg",
        OMP_NUM_THREADS="1",
        OPENBLAS_NUM_THREADS="1",
        MKL_NUM_THREADS="1",
        PYTHONDONTWRITEBYTECODE="1",
        PYTHONUNBUFFERED="1",
    )
    return env


def _limit_child(limits: ExecutionLimits) -> None:
    """Runs in the child between fork and exec: resource limits only (no library calls here)."""
    resource.setrlimit(resource.RLIMIT_AS, (limits.memory_bytes, limits.memory_bytes))
    cpu = int(limits.timeout_s) + 5
    resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 5))
    resource.setrlimit(resource.RLIMIT_FSIZE, (limits.file_bytes, limits.file_bytes))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


async def _read_bounded(stream: asyncio.StreamReader | None, limit: int) -> bytes:
    """Read everything, keep the first and last ``limit // 2`` bytes."""
    if stream is None:
        return b""
    head = bytearray()
    tail = bytearray()
    half = max(limit // 2, 1)
    dropped = 0
    while chunk := await stream.read(65536):
        if len(head) < half:
            take = half - len(head)
            head += chunk[:take]
            chunk = chunk[take:]
        tail += chunk
        if len(tail) > half:
            dropped += len(tail) - half
            del tail[: len(tail) - half]
    if dropped:
        return bytes(head) + f"\n[... {dropped} bytes dropped ...]\n".encode() + bytes(tail)
    return bytes(head + tail)


def _kill_group(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pid, signal.SIGKILL)


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
        returncode, timed_out, stdout, stderr, wall = await _run_cold(scratch, job, limits)
    return _collect(scratch, returncode, timed_out, stdout, stderr, wall, limits, token)


async def _run_cold(scratch: Path, job: Path, limits: ExecutionLimits,
                    ) -> tuple[int | None, bool, bytes, bytes, float]:
    t0 = time.perf_counter()
    proc = await asyncio.create_subprocess_exec(
        sys.executable,
        "-m",
        "meceng.tools.runner",
        str(job),
        cwd=scratch,
        env=child_env(),
        stdin=asyncio.subprocess.DEVNULL,
        stdout=asyncio.subprocess.PIPE,
        stderr=asyncio.subprocess.PIPE,
        start_new_session=True,
        preexec_fn=lambda: _limit_child(limits),
    )
    readers = asyncio.gather(
        _read_bounded(proc.stdout, limits.output_bytes), _read_bounded(proc.stderr, limits.output_bytes)
    )
    timed_out = False
    try:
        await asyncio.wait_for(proc.wait(), timeout=limits.timeout_s)
    except TimeoutError:
        timed_out = True
    finally:
        # the program's children die with it, whether it ended or not
        _kill_group(proc.pid)
        if proc.returncode is None:
            await proc.wait()
    try:
        stdout, stderr = await asyncio.wait_for(readers, timeout=5.0)
    except TimeoutError:
        stdout, stderr = b"", b"[output not collected: a child kept the pipes open]"
    return proc.returncode, timed_out, stdout, stderr, time.perf_counter() - t0


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
    rlimits = {"memory": limits.memory_bytes, "cpu": int(limits.timeout_s) + 5, "file": limits.file_bytes}
    async with slots or contextlib.nullcontext():
        t0 = time.perf_counter()
        returncode, timed_out = await pool.run(job, child_env(), rlimits, limits.timeout_s)
        wall = time.perf_counter() - t0
    stdout = _read_bounded_file(scratch / "stdout.txt", limits.output_bytes)
    stderr = _read_bounded_file(scratch / "stderr.txt", limits.output_bytes)
    # reading the result, trajectory and part files: off the event loop
    return await asyncio.to_thread(_collect, scratch, returncode, timed_out, stdout, stderr, wall, limits, token)


def _collect(
    scratch: Path,
    returncode: int | None,
    timed_out: bool,
    stdout: bytes,
    stderr: bytes,
    wall: float,
    limits: ExecutionLimits,
    token: str,
) -> Execution:
    out = stdout.decode(errors="replace")
    err = stderr.decode(errors="replace")
    stage_log = scratch / "stage.log"
    stages = stage_log.read_text().split() if stage_log.exists() else []
    last_stage = stages[-1] if stages else "started"
    common = {"stdout_tail": out[-4000:], "stderr_tail": err[-4000:], "returncode": returncode,
              "wall_time": wall}
    if timed_out:
        return Execution(stage=last_stage, error=f"timeout after {limits.timeout_s:g} s (process group killed)",
                         error_kind="timeout", **common)
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
        return Execution(stage="refused", error=result.get("error"), error_kind="safety")
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
