"""Comparing run records apart from what differs between two runs of the same thing (times, hosts)."""

from __future__ import annotations

from typing import Any

VOLATILE = ("time", "timing", "duration", "started", "stderr_tail", "endpoint", "cpu_s", "wall_s")


def normalized(value: Any, volatile: tuple[str, ...] = VOLATILE) -> Any:
    """``value`` without the keys that name a volatile quantity, at any depth."""
    if isinstance(value, dict):
        return {k: normalized(v, volatile) for k, v in value.items() if not any(w in k for w in volatile)}
    if isinstance(value, list):
        return [normalized(v, volatile) for v in value]
    return value
