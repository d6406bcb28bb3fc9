"""Finds the task models: every module of ``meceng.tasks`` (rigid, levels 1-2) and of its
``parts`` (3a) and ``assemblies`` (3b) subpackages that defines ``TASK``."""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from meceng.tasks.assembly_base import AssemblyModel
from meceng.tasks.base import TaskInstance, TaskModel
from meceng.tasks.part_base import PartModel

_NOT_TASKS = {"base", "registry", "part_base", "assembly_base"}
_PACKAGES = ("meceng.tasks", "meceng.tasks.parts", "meceng.tasks.assemblies")

#: Any kind of task model: they share id, name, level, slug and ``instance(seed)``.
AnyModel = TaskModel | PartModel | AssemblyModel


@dataclass(frozen=True)
class TaskRegistry:
    """An ordered, immutable set of task models, looked up by slug or paper id."""

    models: tuple[AnyModel, ...]

    def __post_init__(self) -> None:
        slugs = [m.slug for m in self.models]
        ids = [m.id for m in self.models]
        if len(set(slugs)) != len(slugs) or len(set(ids)) != len(ids):
            raise ValueError("task models must have unique ids and slugs")

    def __iter__(self) -> Iterator[TaskModel]:
        return iter(self.models)

    def __len__(self) -> int:
        return len(self.models)

    def get(self, key: str | int) -> AnyModel:
        """Look up by slug, by paper id, or by the id given as text ("43")."""
        for model in self.models:
            if model.slug == key or model.id == key or str(model.id) == str(key):
                return model
        known = ", ".join(m.slug for m in self.models)
        raise KeyError(f"unknown task model {key!r}; known: {known}")

    def select(self, levels: Iterable[str] | None = None, only: Iterable[str] | None = None) -> list[AnyModel]:
        wanted_levels = {str(lv) for lv in levels} if levels else None
        wanted = {str(x) for x in only} if only else None
        return [
            m
            for m in self.models
            if (wanted_levels is None or m.level in wanted_levels)
            and (wanted is None or m.slug in wanted or str(m.id) in wanted)
        ]

    def instances(self, models: Iterable[AnyModel], seed: int, variations: int) -> list[TaskInstance]:
        """Variation k of every model uses seed ``seed + k``; order is model-major."""
        return [m.instance(seed + k) for m in models for k in range(variations)]


def discover() -> TaskRegistry:
    models = []
    for package_name in _PACKAGES:
        try:
            package = importlib.import_module(package_name)
        except ModuleNotFoundError:
            continue
        for info in pkgutil.iter_modules(package.__path__):
            if info.ispkg or info.name in _NOT_TASKS or info.name.startswith("_"):
                continue
            module = importlib.import_module(f"{package_name}.{info.name}")
            task = getattr(module, "TASK", None)
            if isinstance(task, TaskModel | PartModel | AssemblyModel):
                models.append(task)
    return TaskRegistry(tuple(sorted(models, key=lambda m: m.id)))


def default_registry() -> TaskRegistry:
    return discover()
