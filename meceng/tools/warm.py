"""Warm workers: a fork server that imports Exudyn, NumPy and NGSolve once and forks a fresh
child per program (see :mod:`meceng.tools.forkserver`).

A cold child pays the imports (~0.1-0.5 s) before it does anything; a forked one starts in a few
milliseconds. The fork server only imports: it never meshes or solves, because Netgen leaves a
worker thread behind after meshing and children forked from such a process deadlock when they
mesh. Each child is still its own session and process group, with the same limits, stripped
environment, empty network namespace, audit hook and result token as a cold child, and it leaves
with ``os._exit``. The server reaps each child with ``wait4`` and reports its CPU time, which the
program is graded by (issue 45). The server itself runs under the pinned environment
(``pinning.PINNED_ENV``): the numerical libraries read their thread counts when the server imports
them, and the hash seed when it starts, and every child inherits both.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import resource
import signal
import sys
import tempfile
from pathlib import Path

from meceng.tools.pinning import PINNED_ENV


def child_main(job_path: str, env: dict[str, str], limits: dict[str, int]) -> None:
    """Runs in the forked child: become a session leader, limit, isolate, run, leave."""
    code = 1
    try:
        os.setsid()
        resource.setrlimit(resource.RLIMIT_AS, (limits["memory"], limits["memory"]))
        resource.setrlimit(resource.RLIMIT_CPU, (limits["cpu"], limits.get("cpu_hard", limits["cpu"] + 2)))
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits["file"], limits["file"]))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        os.environ.clear()
        os.environ.update(env)
        scratch = Path(job_path).parent
        os.chdir(scratch)
        for fd, name in ((1, "stdout.txt"), (2, "stderr.txt")):
            target = os.open(scratch / name, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
            os.dup2(target, fd)
            os.close(target)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        from meceng.tools.runner import enter

        code = enter(Path(job_path))
    finally:
        os._exit(code)


class WarmPool:
    """A running fork server. ``await start()`` once, ``await run(...)`` per program, ``close()``."""

    def __init__(self, env: dict[str, str] | None = None) -> None:
        # whatever the caller passes, the server's libraries load pinned (see the module's note)
        self.env = {**(env if env is not None else os.environ), **PINNED_ENV}
        self._dir = tempfile.mkdtemp(prefix="meceng-forkserver-")
        self.socket_path = os.path.join(self._dir, "server.sock")
        self._process: asyncio.subprocess.Process | None = None
        self._lock = asyncio.Lock()
        self._closed = False

    async def start(self) -> None:
        async with self._lock:
            if self._closed:  # a late caller must not start a server nobody will stop
                raise RuntimeError("the fork server is closed")
            if self._process is not None and self._process.returncode is None:
                return
            self._process = await asyncio.create_subprocess_exec(
                sys.executable, "-m", "meceng.tools.forkserver", self.socket_path,
                stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE, env=self.env,
                start_new_session=True,
            )
            assert self._process.stdout is not None
            line = await asyncio.wait_for(self._process.stdout.readline(), timeout=120)
            if line.strip() != b"ready":
                raise RuntimeError("the fork server did not start")

    async def run(self, job_path: Path, env: dict[str, str], limits: dict[str, int], wall_s: float,
                  ) -> tuple[int | None, bool, float | None]:
        """Run one job in a forked child, stopped after ``wall_s`` seconds on the wall clock; returns
        (exit code, negative for a signal; stopped by the wall clock?; its CPU seconds, None if unknown)."""
        await self.start()
        reader, writer = await asyncio.open_unix_connection(self.socket_path)
        pid: int | None = None
        try:
            writer.write(json.dumps({"job": str(job_path), "env": env, "limits": limits}).encode() + b"\n")
            await writer.drain()
            pid = json.loads(await asyncio.wait_for(reader.readline(), timeout=30))["pid"]
            wall_killed = False
            try:
                line = await asyncio.wait_for(reader.readline(), timeout=wall_s)
            except TimeoutError:
                wall_killed = True
                _kill_group(pid)
                line = await asyncio.wait_for(reader.readline(), timeout=30)
            ended = json.loads(line) if line else {}
            return ended.get("exit"), wall_killed, ended.get("cpu_s")
        finally:
            if pid is not None:  # ended, timed out or cancelled: its group dies with it
                _kill_group(pid)
            writer.close()
            with contextlib.suppress(Exception):
                await writer.wait_closed()

    async def close(self) -> None:
        self._closed = True
        process = self._process
        self._process = None
        if process is not None and process.returncode is None:
            assert process.stdin is not None
            process.stdin.close()
            try:
                await asyncio.wait_for(process.wait(), timeout=5)
            except TimeoutError:
                process.kill()
                await process.wait()
        with contextlib.suppress(OSError):
            os.unlink(self.socket_path)
        with contextlib.suppress(OSError):
            os.rmdir(self._dir)


def _kill_group(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pid, signal.SIGKILL)
