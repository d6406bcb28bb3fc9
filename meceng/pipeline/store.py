"""The reference store: ground-truth executions made once and reused by every run that needs them.

A ground truth depends only on its program (the task's parameters and seed are written into it),
the solver block, the limits that shape what the harness captures (rigid or part, the number of
modes) and the simulation stack (Exudyn, NGSolve/Netgen, NumPy, SciPy, PyMeshLab, and MecEng's
own capture code). The store keys an execution by a digest of all of those, so the 34 runs of the
main study execute the 1,000 rigid references once, and the level-3 study meshes and reduces its
440 reference parts once, not in each of its runs; a new Exudyn makes new entries by itself.

Concurrent writers (the runs of one sweep, the shard jobs of an array on shared storage) are
safe: an entry is written to a file of its own and renamed into place (atomic on one file
system); two writers of one key write the same execution and the last rename wins. Inside one
process, runs asking for the same key at the same time wait for one execution. Only successful
executions are stored: a ground truth that failed (a timeout on a loaded machine) is done again.
"""

from __future__ import annotations

import asyncio
import contextlib
import hashlib
import json
import os
import pickle
import secrets
from collections.abc import Awaitable, Callable
from dataclasses import asdict, dataclass
from functools import cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from meceng.logs import get_logger
from meceng.tasks.drafts import without_header
from meceng.tools.execution import Execution, ExecutionLimits

log = get_logger(__name__)

STACK = ("exudyn", "ngsolve", "netgen-mesher", "numpy", "scipy", "pymeshlab", "meceng")
#: the harness code that decides what an execution captures
CAPTURE_MODULES = ("runner.py", "harness.py", "part_runner.py", "guard.py", "executor.py", "execution.py",
                   "inspection.py", "motion.py", "pinning.py")  # pinning: the numbers a solve gives
#: 2: the program's leading comment block is left out of the key (issue 36: it holds the task's text,
#: and the paper's and the open text's ground truths are the same program)
FORMAT = 2


@cache
def stack_fingerprint() -> str:
    """The versions of the simulation stack and a digest of MecEng's capture code."""
    parts = []
    for package in STACK:
        try:
            parts.append(f"{package}={version(package)}")
        except PackageNotFoundError:
            parts.append(f"{package}=none")
    tools = Path(__file__).resolve().parents[1] / "tools"
    digest = hashlib.sha256()
    for name in CAPTURE_MODULES:
        digest.update((tools / name).read_bytes())
    parts.append(f"capture={digest.hexdigest()[:16]}")
    return ";".join(parts)


def reference_key(program: str, sim_block: str, limits: ExecutionLimits, variant: str = "") -> str:
    """The digest a ground-truth execution is stored under. The program's leading comment block (its
    title and task text) does not run: a ground truth stored for the paper's text serves the open
    one's too. ``variant``: what else is stored for the same run (behaviour's slim converged runs,
    the step count it compares at: ``pipeline/converged.py``); empty for the execution itself, whose
    keys stay as they were."""
    program = without_header(program)[0]
    shape = {k: v for k, v in asdict(limits).items()
             if k in ("mode", "n_modes", "guard", "inspect_times", "inspect_loads", "motion_grid")}
    text = json.dumps({"format": FORMAT, "program": program, "sim": sim_block, "limits": shape,
                       "stack": stack_fingerprint(), **({"variant": variant} if variant else {})}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


class ReferenceStore:
    """Ground-truth executions as files under ``root`` (``<digest[:2]>/<digest>.pkl``)."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.hits = 0
        self.made = 0
        self._pending: dict[str, asyncio.Future[Execution]] = {}

    def path(self, key: str) -> Path:
        return self.root / key[:2] / f"{key}.pkl"

    def get(self, key: str) -> Execution | None:
        """The stored execution, or None (missing, or unreadable: then it is made again)."""
        try:
            with self.path(key).open("rb") as handle:
                execution = pickle.load(handle)
        except FileNotFoundError:
            return None
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, TypeError) as exc:
            log.warning("unreadable reference entry, made again", key=key, error=str(exc))
            return None
        return execution if isinstance(execution, Execution) else None

    def put(self, key: str, execution: Execution) -> None:
        """Write the entry under a name of its own, then rename it into place."""
        target = self.path(key)
        target.parent.mkdir(parents=True, exist_ok=True)
        tmp = target.with_name(f".{target.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
        try:
            with tmp.open("wb") as handle:
                pickle.dump(execution, handle, protocol=pickle.HIGHEST_PROTOCOL)
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(tmp, target)
        finally:
            with contextlib.suppress(FileNotFoundError):
                tmp.unlink()

    def fact(self, key: str) -> dict[str, Any] | None:
        """A small finding stored beside the executions (``<digest>.json``), or None."""
        try:
            found = json.loads(self.path(key).with_suffix(".json").read_text())
        except FileNotFoundError:
            return None
        except (OSError, ValueError) as exc:
            log.warning("unreadable reference fact, found again", key=key, error=str(exc))
            return None
        return found if isinstance(found, dict) else None

    def put_fact(self, key: str, fact: dict[str, Any]) -> None:
        """Store a finding as JSON, written under a name of its own and renamed into place."""
        target = self.path(key).with_suffix(".json")
        target.parent.mkdir(parents=True, exist_ok=True)
        tmp = target.with_name(f".{target.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
        try:
            tmp.write_text(json.dumps(fact, sort_keys=True))
            os.replace(tmp, target)
        finally:
            with contextlib.suppress(FileNotFoundError):
                tmp.unlink()

    async def fetch(self, key: str, make: Callable[[], Awaitable[Execution]]) -> Execution:
        """The stored execution of ``key``; made (once in this process) and stored when missing.
        A making nobody waits for any more (every run that asked lost its task) is cancelled."""
        making = self._pending.get(key)
        if making is None:
            found = await asyncio.to_thread(self.get, key)
            if found is not None:
                self.hits += 1
                return found
            making = self._pending.get(key)  # another run started it while we read the disk
            if making is None:
                making = _Making(asyncio.ensure_future(self._make(key, make)))
                self._pending[key] = making
        making.waiters += 1
        try:
            return await asyncio.shield(making.task)
        finally:
            making.waiters -= 1
            if making.waiters == 0 and not making.task.done():
                making.task.cancel()
                if self._pending.get(key) is making:
                    del self._pending[key]

    async def _make(self, key: str, make: Callable[[], Awaitable[Execution]]) -> Execution:
        try:
            execution = await make()
            if execution.error is None:
                await asyncio.to_thread(self.put, key, execution)
                self.made += 1
            return execution
        finally:
            making = self._pending.get(key)
            if making is not None and making.task is asyncio.current_task():
                del self._pending[key]


@dataclass
class _Making:
    task: asyncio.Task[Execution]
    waiters: int = 0
