"""What the concurrent runs of one sweep share: the worker slots, the fork server, the grading
pool and the reference store.

A run alone makes its own (``run_benchmark`` without ``shared``). Runs of a sweep that make their
own would each size their workers to the machine and together oversubscribe it N times, boot N
fork servers, and fight over the terminal with N progress bars.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from contextlib import AbstractContextManager
from dataclasses import dataclass

from meceng.progress import Advance
from meceng.tools.warm import WarmPool

from .grading import GradingPool
from .store import ReferenceStore

#: (tasks to do, title) -> a context yielding ``advance(success, tokens)`` per finished task
ProgressFactory = Callable[[int, str], AbstractContextManager[Advance]]


@dataclass(frozen=True)
class SharedServices:
    """The services every run of a sweep uses instead of its own. The owner (the sweep) starts
    and closes the pool; a run only uses it."""

    workers: asyncio.Semaphore
    pool: WarmPool | None = None
    store: ReferenceStore | None = None
    grading: GradingPool | None = None
