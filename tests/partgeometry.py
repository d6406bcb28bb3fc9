"""Helper for level 3a tests: a part's ground-truth solid, built in the test process."""

from __future__ import annotations

from typing import Any

from meceng.tasks.registry import default_registry


def build(pid: int, values: dict[str, Any]) -> Any:
    """The GT solid, built in this process without meshing, as the program text builds it."""
    namespace: dict[str, Any] = {}
    exec("from netgen.occ import *", namespace)
    namespace.update(values)
    exec(default_registry().get(pid).geometry_code, namespace)
    return namespace["shape"]
