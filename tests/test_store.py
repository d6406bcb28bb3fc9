"""The reference store: an entry per ground truth, shared safely, the same execution back."""

from __future__ import annotations

import asyncio
import pickle
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from meceng.pipeline.store import ReferenceStore, reference_key
from meceng.tools.execution import Execution, ExecutionLimits


def execution(value: float = 1.0, error: str | None = None) -> Execution:
    return Execution(stage="solved" if error is None else "started", error=error, times=np.linspace(0, 1, 5),
                     trajectory=np.full((5, 2), value), items={"objects": [{"objectType": "MassPoint"}]})


def write_many(root: str, value: float) -> None:
    store = ReferenceStore(Path(root))
    for _ in range(50):
        store.put("ab" + "0" * 62, execution(value))


def test_key_follows_program_solver_and_capture_mode() -> None:
    base = reference_key("p", "sim", ExecutionLimits())
    assert base == reference_key("p", "sim", ExecutionLimits(timeout_s=5))  # a limit that shapes nothing
    assert len({base, reference_key("q", "sim", ExecutionLimits()), reference_key("p", "sim2", ExecutionLimits()),
                reference_key("p", "sim", ExecutionLimits(mode="part"))}) == 4


def test_concurrent_writers_leave_one_whole_entry(tmp_path: Path) -> None:
    with ProcessPoolExecutor(4) as pool:
        list(pool.map(write_many, [str(tmp_path)] * 4, [1.0, 2.0, 3.0, 4.0]))
    (entry,) = [p for p in tmp_path.rglob("*") if p.is_file()]  # no temporary file left
    stored = ReferenceStore(tmp_path).get(entry.stem)
    assert stored is not None and stored.trajectory is not None and stored.trajectory[0, 0] in (1.0, 2.0, 3.0, 4.0)


async def test_made_once_reused_and_failures_not_kept(tmp_path: Path) -> None:
    store = ReferenceStore(tmp_path)
    made: list[str] = []

    async def make(key: str, error: str | None = None) -> Execution:
        made.append(key)
        await asyncio.sleep(0.01)
        return execution(error=error)

    first = await asyncio.gather(*(store.fetch("k" * 64, lambda: make("k")) for _ in range(5)))
    assert made == ["k"] and all(f is first[0] for f in first)  # five runs asking at once: one execution
    again = await ReferenceStore(tmp_path).fetch("k" * 64, lambda: make("k"))
    assert made == ["k"] and np.array_equal(again.trajectory, first[0].trajectory)
    await store.fetch("f" * 64, lambda: make("f", error="timeout"))
    await store.fetch("f" * 64, lambda: make("f", error="timeout"))
    assert made == ["k", "f", "f"]  # a failed ground truth is done again


def test_an_unreadable_entry_is_made_again(tmp_path: Path) -> None:
    store = ReferenceStore(tmp_path)
    store.put("cd" + "1" * 62, execution())
    store.path("cd" + "1" * 62).write_bytes(pickle.dumps(execution())[:20])
    assert store.get("cd" + "1" * 62) is None
