"""Splitting a sweep's runs over the jobs of a cluster array.

``--shard K/N`` (K from 0) or, inside a Slurm array job, ``SLURM_ARRAY_TASK_ID`` and
``SLURM_ARRAY_TASK_COUNT`` choose one of N disjoint parts of the sweep's runs. The split depends
only on the spec (never on which runs are finished), so every job of the array computes the same
one; it balances the expected LLM requests, not the count of runs: one level-3 run is 680 records
and a level 1-2 run 1,000, and a shard of the paper's 171 runs by count alone would differ by
whole studies. Longest run first, each onto the shard with the least so far (ties: the lowest
shard), which keeps every shard within one run of the mean.
"""

from __future__ import annotations

import heapq
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TypeVar

T = TypeVar("T")


@dataclass(frozen=True)
class Shard:
    index: int  # 0 .. count-1
    count: int

    def __post_init__(self) -> None:
        if self.count < 1 or not 0 <= self.index < self.count:
            raise ValueError(f"shard {self.index}/{self.count}: K/N needs 0 <= K < N")

    @classmethod
    def parse(cls, text: str) -> Shard:
        try:
            index, count = (int(x) for x in text.split("/"))
        except ValueError:
            raise ValueError(f"shard {text!r}: write K/N, e.g. 0/4") from None
        return cls(index, count)

    @classmethod
    def from_env(cls, env: Mapping[str, str] = os.environ) -> Shard | None:
        """The Slurm array task this process is (an array numbered from SLURM_ARRAY_TASK_MIN)."""
        if "SLURM_ARRAY_TASK_ID" not in env or "SLURM_ARRAY_TASK_COUNT" not in env:
            return None
        first = int(env.get("SLURM_ARRAY_TASK_MIN", "0"))
        return cls(int(env["SLURM_ARRAY_TASK_ID"]) - first, int(env["SLURM_ARRAY_TASK_COUNT"]))

    def __str__(self) -> str:
        return f"{self.index}/{self.count}"


def split(items: Sequence[T], count: int, weight: Callable[[T], float], name: Callable[[T], str]) -> list[list[T]]:
    """``items`` in ``count`` parts of near-equal total weight, each part in the items' order."""
    order = sorted(range(len(items)), key=lambda k: (-weight(items[k]), name(items[k])))
    loads = [(0.0, shard) for shard in range(count)]
    owner: dict[int, int] = {}
    for k in order:
        load, shard = heapq.heappop(loads)
        owner[k] = shard
        heapq.heappush(loads, (load + weight(items[k]), shard))
    return [[items[k] for k in range(len(items)) if owner[k] == shard] for shard in range(count)]


def pick(items: Sequence[T], shard: Shard | None, weight: Callable[[T], float], name: Callable[[T], str]) -> list[T]:
    """The shard's items (all of them without a shard)."""
    if shard is None:
        return list(items)
    return split(items, shard.count, weight, name)[shard.index]
