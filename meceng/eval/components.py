"""The 'choose simulation components' metric: missing fails, surplus is fine, and a chosen
component brings its dependencies along (a joint brings ground and rigid body)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass


@dataclass(frozen=True)
class ComponentCheck:
    passed: bool
    missing: tuple[str, ...]
    surplus: tuple[str, ...]
    detail: str


def expand(selected: Iterable[str], dependencies: Mapping[str, Iterable[str]]) -> set[str]:
    """The chosen components plus everything they depend on, transitively."""
    out: set[str] = set()
    stack = list(selected)
    while stack:
        name = stack.pop()
        if name in out:
            continue
        out.add(name)
        stack.extend(dependencies.get(name, ()))
    return out


def check_components(
    selected: Iterable[str],
    required: Iterable[str],
    dependencies: Mapping[str, Iterable[str]],
) -> ComponentCheck:
    chosen = expand(selected, dependencies)
    need = set(required)
    missing = tuple(sorted(need - chosen))
    surplus = tuple(sorted(set(selected) - need))
    if missing:
        return ComponentCheck(False, missing, surplus, "missing: " + ", ".join(missing))
    detail = "all required components chosen"
    if surplus:
        detail += " (surplus: " + ", ".join(surplus) + ")"
    return ComponentCheck(True, missing, surplus, detail)
