"""A process pool beside the workers for the CPU work a task needs after its programs ran:
grading (the level 1-2 chain, the part metrics) and the viewer's traces.

In threads of the parent this work held the GIL: the parent spent ~40-70 ms of its own CPU per
task serially, so two workers gave 1.54x the tasks per second of one where the machine gives
2.11x, and a 16-core server would grade on one core. In a pool of processes it runs where the
cores are; the parent keeps only what must be in one place (scheduling, the journal). Started
with the ``forkserver`` method: the parent has threads and imported Exudyn, a plain fork of it is
not safe. The executions go to the pool pickled (arrays are copied, a few hundred KB a task). Like
every non-fork start method, the pool's processes import a script that started the parent
(``python some_script.py``) as ``__mp_main__``: a script that grades must keep its work under
``if __name__ == "__main__"`` (``python -m meceng.cli`` is not imported again).
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import select
import threading
import time
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from typing import Any, TypeVar

from meceng.logs import get_logger
from meceng.syntax import parse

T = TypeVar("T")
log = get_logger(__name__)


PRELOAD = ("meceng.eval.chain", "meceng.pipeline.traces", "meceng.pipeline.rundir")


def _warm(parent: int) -> None:
    """Import what grading needs once per pool process, and leave when ``parent`` (the process
    that made the pool) is gone. PyMeshLab is imported by the first part graded, on the pool
    process's main thread as it must be (``meceng.eval.parts.load_mesh_library``)."""
    import meceng.eval.chain
    import meceng.pipeline.traces  # noqa: F401

    threading.Thread(target=_leave_with, args=(parent,), daemon=True, name="leave-with-parent").start()


def _leave_with(parent: int) -> None:
    """A pool process is a child of the pool's fork server, not of the process that uses the pool,
    and it waits for work on a pipe that a killed parent (SIGKILL, an out-of-memory kill) never
    closes; it also keeps the fork server alive. So it watches the parent itself: a pidfd becomes
    readable when that process ends (no race with a reused pid, unlike polling the number)."""
    try:
        handle = os.pidfd_open(parent)
    except (OSError, AttributeError):  # no pidfd (an old kernel): poll the pid instead
        while _alive(parent):
            time.sleep(2.0)
    else:
        select.select([handle], [], [])
    os._exit(0)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True  # also on PermissionError: the process exists


class GradingPool:
    """``await pool.run(fn, *args)`` runs a picklable pure function in one of ``processes``."""

    def __init__(self, processes: int) -> None:
        self.processes = processes
        context = multiprocessing.get_context("forkserver")
        # the server imports these once and the pool's processes fork from it warm ("__main__": a
        # script that started us is imported there, not again in every pool process)
        context.set_forkserver_preload(["__main__", *PRELOAD])
        self._executor = ProcessPoolExecutor(processes, mp_context=context, initializer=_warm,
                                             initargs=(os.getpid(),))

    async def warm(self) -> None:
        """Start every process now (the first start boots the fork server: ~1 s of imports), so
        that a run's first grading does not wait for it; a run calls this while the LLM answers."""
        await asyncio.gather(*(self.run(len, ()) for _ in range(self.processes)))

    async def run(self, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
        return await asyncio.get_running_loop().run_in_executor(self._executor, partial(fn, *args, **kwargs))

    def close(self) -> None:
        self._executor.shutdown(wait=True, cancel_futures=True)


def main_script_is_guarded() -> bool:
    """Whether the pool's processes may import the script that started us: true when there is no
    script (``python -m``, a console entry point, an interactive session) or when its top level
    only defines things and keeps its work under ``if __name__ == "__main__"``. A script that runs
    a benchmark at its top level would run it again in the pool's fork server."""
    import ast
    import sys

    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if main is None or getattr(main, "__spec__", None) is not None or not path:
        return True
    try:
        with open(path, encoding="utf-8") as handle:
            tree = parse(handle.read())
    except (OSError, SyntaxError, UnicodeDecodeError):
        return False
    # definitions and constants (ROOT = Path(__file__).parent) are quiet; a statement that is a
    # call, a loop or a with block at the top level does the work
    quiet = (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Assign,
             ast.AnnAssign, ast.If, ast.Expr, ast.Try)
    for node in tree.body:
        if not isinstance(node, quiet):
            return False
        if isinstance(node, ast.Expr) and not isinstance(node.value, ast.Constant) and not ast.unparse(
                node.value).startswith("sys.path."):  # a call at the top level (sys.path.insert is set-up)
            return False
        if isinstance(node, ast.If) and "__main__" not in ast.dump(node.test):
            return False
        if isinstance(node, ast.Assign | ast.AnnAssign) and "run" in ast.dump(node.value).lower():
            return False  # run = asyncio.run(main()), run_benchmark(...)
    return True


def grading_pool(processes: int) -> GradingPool | None:
    """The pool, or None (grading on threads of this process) when the script that started us
    does its work at its top level: the pool's fork server would import it and run it again."""
    if main_script_is_guarded():
        return GradingPool(processes)
    log.warning("grading on threads: the script that started MecEng runs at its top level, and the grading "
                "pool's processes would run it again; keep a script's work under "
                "if __name__ == '__main__': to grade on every core")
    return None


async def offload(pool: GradingPool | None, fn: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """``fn`` in the grading pool when there is one, else on a thread of this process."""
    if pool is not None:
        return await pool.run(fn, *args, **kwargs)
    return await asyncio.to_thread(fn, *args, **kwargs)
