"""One process per run folder: ``<run>/.lock`` says who works on it.

Two shard jobs of an array, a sweep started twice, or a ``--resume`` beside a running sweep would
otherwise append to one journal together. The lock file is made with ``O_EXCL`` and names its
holder: host, boot, process id and the process's start time (a reused pid is not the same
process), the Slurm job if any. A holder on this host that no longer exists left a stale lock; a
holder on another host (shared storage) is stale when its heartbeat, the file's mtime touched
every ``HEARTBEAT_S``, is older than ``STALE_AFTER_S``. A stale lock is renamed aside (one taker
wins the rename), checked to be the one judged stale, and replaced.
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import socket
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from meceng.logs import get_logger

log = get_logger(__name__)

HEARTBEAT_S = 30.0
STALE_AFTER_S = 300.0
LOCK_NAME = ".lock"


class RunBusy(ValueError):
    """Another live process works on this run folder."""


def _boot_id() -> str:
    try:
        return Path("/proc/sys/kernel/random/boot_id").read_text().strip()
    except OSError:
        return ""


def _start_time(pid: int) -> str:
    """The process's start time in clock ticks since boot (field 22 of /proc/PID/stat)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return ""
    return stat.rsplit(")", 1)[1].split()[19]


@dataclass(frozen=True)
class Holder:
    host: str
    boot: str
    pid: int
    start: str
    job: str
    token: str

    @classmethod
    def me(cls) -> Holder:
        job = os.environ.get("SLURM_JOB_ID", "")
        if os.environ.get("SLURM_ARRAY_JOB_ID"):
            job = f"{os.environ['SLURM_ARRAY_JOB_ID']}_{os.environ.get('SLURM_ARRAY_TASK_ID', '')}"
        return cls(socket.gethostname(), _boot_id(), os.getpid(), _start_time(os.getpid()), job,
                   secrets.token_hex(8))

    def alive(self) -> bool | None:
        """Whether the holder still runs; None when that cannot be told from here (another host)."""
        if self.host != socket.gethostname() or self.boot != _boot_id():
            return None if self.host != socket.gethostname() else False
        return _start_time(self.pid) == self.start and self.start != ""

    def describe(self) -> str:
        return f"process {self.pid} on {self.host}" + (f" (Slurm job {self.job})" if self.job else "")


class RunLock:
    """``acquire()`` before touching the folder, ``heartbeat()`` now and then, ``release()`` at the end."""

    def __init__(self, run_dir: Path, stale_after_s: float = STALE_AFTER_S) -> None:
        self.path = run_dir / LOCK_NAME
        self.stale_after_s = stale_after_s
        self.holder = Holder.me()

    def acquire(self) -> None:
        for _ in range(5):
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                self._take_over_if_stale()
                continue
            with os.fdopen(fd, "w") as handle:
                handle.write(json.dumps(asdict(self.holder)))
            return
        raise RunBusy(f"{self.path.parent}: could not take its lock")

    def _read(self) -> tuple[Holder | None, float]:
        try:
            mtime = self.path.stat().st_mtime
            return Holder(**json.loads(self.path.read_text())), mtime
        except FileNotFoundError:
            return None, time.time()
        except (OSError, ValueError, TypeError):
            return None, mtime  # half-written by a taker right now, or garbage: judged by its age

    def _take_over_if_stale(self) -> None:
        holder, mtime = self._read()
        alive = holder.alive() if holder is not None else None
        old = time.time() - mtime > self.stale_after_s
        if alive or (alive is None and not old):
            who = holder.describe() if holder is not None else "another process"
            raise RunBusy(f"{self.path.parent} is being run by {who}")
        aside = self.path.with_name(f"{LOCK_NAME}.stale.{os.getpid()}.{secrets.token_hex(4)}")
        try:
            os.rename(self.path, aside)
        except FileNotFoundError:
            return  # another taker was faster; try to create it again
        try:
            taken = Holder(**json.loads(aside.read_text()))
        except (OSError, ValueError, TypeError):
            taken = None
        if holder is not None and taken is not None and taken.token != holder.token:
            # between our look and our rename another taker made a fresh lock: give it back
            with contextlib.suppress(FileExistsError):
                os.link(aside, self.path)
            aside.unlink()
            raise RunBusy(f"{self.path.parent} was just taken by {taken.describe()}")
        aside.unlink()
        log.warning("stale run lock taken over", run_dir=str(self.path.parent),
                    previous=holder.describe() if holder else "unreadable lock")

    def heartbeat(self) -> None:
        with contextlib.suppress(OSError):
            os.utime(self.path)

    def release(self) -> None:
        holder, _ = self._read()
        if holder is not None and holder.token == self.holder.token:
            with contextlib.suppress(FileNotFoundError):
                self.path.unlink()
