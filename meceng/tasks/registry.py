"""Finds the task models: every module in this package that defines ``TASK``."""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from meceng.tasks.base import TaskInstance, TaskModel

_NOT_TASKS = {"base", "registry"}


@dataclass(frozen=True)
class TaskRegistry:
    """An ordered, immutable set of task models, looked up by slug or paper id."""

    models: tuple[TaskModel, ...]

    def __post_init__(self) -> None:
        slugs = [m.slug for m in self.models]
        ids = [m.id for m in self.models]
        if len(set(slugs)) != len(slugs) or len(set(ids)) != len(ids):
            raise ValueError("task models must have unique ids and slugs")

    def __iter__(self) -> Iterator[TaskModel]:
        return iter(self.models)

    def __len__(self) -> int:
        return len(self.models)

    def get(self, key: str | int) -> TaskModel:
        """Look up by slug, by paper id, or by the id given as text ("43")."""
        for model in self.models:
            if model.slug == key or model.id == key or str(model.id) == str(key):
                return model
        known = ", ".join(m.slug for m in self.models)
        raise KeyError(f"unknown task model {key!r}; known: {known}")

    def select(self, levels: Iterable[str] | None = None, only: Iterable[str] | None = None) -> list[TaskModel]:
        wanted_levels = {str(lv) for lv in levels} if levels else None
        wanted = {str(x) for x in only} if only else None
        return [
            m
            for m in self.models
            if (wanted_levels is None or m.level in wanted_levels)
            and (wanted is None or m.slug in wanted or str(m.id) in wanted)
        ]

    def instances(self, models: Iterable[TaskModel], seed: int, variations: int) -> list[TaskInstance]:
        """Variation k of every model uses seed ``seed + k``; order is model-major."""
        return [m.instance(seed + k) for m in models for k in range(variations)]


def discover() -> TaskRegistry:
    import meceng.tasks as package

    models = []
    for info in pkgutil.iter_modules(package.__path__):
        if info.name in _NOT_TASKS or info.name.startswith("_"):
            continue
        module = importlib.import_module(f"meceng.tasks.{info.name}")
        task = getattr(module, "TASK", None)
        if isinstance(task, TaskModel):
            models.append(task)
    return TaskRegistry(tuple(sorted(models, key=lambda m: m.id)))


def default_registry() -> TaskRegistry:
    return discover()
