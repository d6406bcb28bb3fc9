"""Level 3a part models (ids 51-72), one module each, plus the master parameters of each family.

Each part's module is named by its slug, so an assembly finds the parts it names without the
registry (``part_model``), and the registry, which knows assemblies, stays the only one that
looks at every task module.
"""

from __future__ import annotations

import importlib

from meceng.tasks.part_base import PartModel


def part_model(slug: str) -> PartModel:
    """The part model of this slug (its module's ``TASK``)."""
    try:
        model = importlib.import_module(f"{__name__}.{slug}").TASK
    except (ModuleNotFoundError, AttributeError) as exc:
        raise KeyError(f"no part model {slug!r}") from exc
    if not isinstance(model, PartModel):
        raise KeyError(f"{slug!r} is not a part model")
    return model
