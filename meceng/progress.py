"""A progress bar for long runs (rich): done/total, success so far, tokens/s, ETA.

Silent when disabled or when stderr is not a terminal (CI, pipes).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

Advance = Callable[[bool, int], None]


def live_display_enabled() -> bool:
    """A live display only on a terminal: in CI and pipes it would be lines of escape codes."""
    return sys.stderr.isatty()


@contextmanager
def progress_bar(total: int, title: str, enabled: bool = True, tokens: bool = True) -> Iterator[Advance]:
    """Yields ``advance(success, tokens)`` to call once per finished task (``tokens=False``: no
    tokens/s column, for work that calls no LLM such as a rescore)."""
    if not enabled or not live_display_enabled():
        yield lambda success, tokens=0: None
        return
    passed = 0
    tokens_total = 0
    t0 = time.perf_counter()
    with Progress(
        TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(),
        TextColumn("ok {task.fields[passed]}"), *([TextColumn("{task.fields[rate]} tok/s")] if tokens else []),
        TimeElapsedColumn(), TextColumn("eta"), TimeRemainingColumn(), transient=False,
    ) as progress:
        task = progress.add_task(title, total=total, passed=0, rate="0")

        def advance(success: bool, tokens: int = 0) -> None:
            nonlocal passed, tokens_total
            passed += int(bool(success))
            tokens_total += tokens
            rate = tokens_total / max(time.perf_counter() - t0, 1e-9)
            progress.update(task, advance=1, passed=passed, rate=f"{rate:.0f}")

        yield advance
