"""A progress bar for long runs (rich), silent when disabled or not on a terminal."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn


@contextmanager
def progress_bar(total: int, title: str, enabled: bool = True) -> Iterator[Callable[[bool], None]]:
    """Yields ``advance(success)``; the bar shows done/total and the success count so far."""
    if not enabled or not sys.stderr.isatty():
        yield lambda success: None
        return
    passed = 0
    with Progress(
        TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(),
        TextColumn("ok {task.fields[passed]}"), TimeElapsedColumn(), transient=False,
    ) as progress:
        task = progress.add_task(title, total=total, passed=0)

        def advance(success: bool) -> None:
            nonlocal passed
            passed += int(bool(success))
            progress.update(task, advance=1, passed=passed)

        yield advance
