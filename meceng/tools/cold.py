"""A cold child: a fresh interpreter per program, reaped here with its resource usage.

``asyncio``'s own subprocesses are reaped by its child watcher, which keeps the exit status and
throws the child's rusage away; the CPU time a program is graded by (issue 45) needs it. So the
child is started with ``subprocess.Popen`` (the same fork, limits and new session as before), its
exit is awaited on a pidfd (or, without one, by polling ``waitid`` with ``WNOWAIT``), and it is
reaped with ``os.wait4``, which returns the CPU time of all its threads and of the children it
waited for. Its output is read through the event loop, bounded.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import signal
import subprocess
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class ColdRun:
    """How a cold child ended: exit code (negative: the signal that killed it), whether the wall
    clock stopped it, its bounded output, and its wall and CPU seconds."""

    returncode: int
    wall_killed: bool
    stdout: bytes
    stderr: bytes
    wall_s: float
    cpu_s: float


async def read_bounded(stream: asyncio.StreamReader | None, limit: int) -> bytes:
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


def kill_group(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pid, signal.SIGKILL)


async def _pipe_reader(pipe: object) -> tuple[asyncio.StreamReader, asyncio.BaseTransport]:
    loop = asyncio.get_running_loop()
    reader = asyncio.StreamReader()
    transport, _ = await loop.connect_read_pipe(lambda: asyncio.StreamReaderProtocol(reader), pipe)
    return reader, transport


async def until_exit(pid: int) -> None:
    """Return once child ``pid`` has ended, without reaping it (its rusage is read by ``wait4``)."""
    loop = asyncio.get_running_loop()
    try:
        fd = os.pidfd_open(pid)
    except (AttributeError, OSError):  # no pidfd (kernel < 5.3): poll, leaving the zombie in place
        while os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is None:
            await asyncio.sleep(0.02)
        return
    ended = loop.create_future()
    loop.add_reader(fd, lambda: ended.done() or ended.set_result(None))
    try:
        await ended
    finally:
        loop.remove_reader(fd)
        os.close(fd)


def reap(pid: int) -> tuple[int, float]:
    """Kill what is left of the child's process group, reap the child: (exit code, CPU seconds)."""
    kill_group(pid)  # the program's children die with it, whether it ended or not
    _, status, usage = os.wait4(pid, 0)
    return os.waitstatus_to_exitcode(status), usage.ru_utime + usage.ru_stime


async def run_cold(argv: Sequence[str], cwd: Path, env: Mapping[str, str], preexec: Callable[[], None],
                   wall_s: float, output_bytes: int) -> ColdRun:
    """Run ``argv`` in its own session under ``preexec``'s limits; stop its group after ``wall_s``."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(list(argv), cwd=cwd, env=dict(env), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True, preexec_fn=preexec)
    transports: list[asyncio.BaseTransport] = []
    wall_killed = False
    try:
        (out, out_t), (err, err_t) = await _pipe_reader(proc.stdout), await _pipe_reader(proc.stderr)
        transports = [out_t, err_t]
        readers = asyncio.gather(read_bounded(out, output_bytes), read_bounded(err, output_bytes))
        try:
            await asyncio.wait_for(until_exit(proc.pid), timeout=wall_s)
        except TimeoutError:
            wall_killed = True
    finally:
        # also when cancelled: after SIGKILL the child is gone within milliseconds
        returncode, cpu = reap(proc.pid)
        proc.returncode = returncode  # reaped here: Popen must not wait for it again
        wall = time.perf_counter() - t0
    try:
        stdout, stderr = await asyncio.wait_for(readers, timeout=5.0)
    except TimeoutError:
        stdout, stderr = b"", b"[output not collected: a child kept the pipes open]"
        for transport in transports:
            transport.close()
    return ColdRun(returncode, wall_killed, stdout, stderr, wall, cpu)
