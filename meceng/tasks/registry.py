"""Finds the task models: every module of ``meceng.tasks`` (rigid, levels 1-2) and of its
``parts`` (3a), ``assemblies`` (3b) and ``design`` (4) subpackages that defines ``TASK``."""

from __future__ import annotations

import difflib
import importlib
import pkgutil
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from meceng.tasks.assembly_base import AssemblyModel
from meceng.tasks.base import TEXTS, TaskInstance, TaskModel
from meceng.tasks.design_base import DesignModel
from meceng.tasks.part_base import PartModel

_NOT_TASKS = {"base", "registry", "part_base", "assembly_base", "design_base", "design_sim", "design_measures",
              "design_check"}
_PACKAGES = ("meceng.tasks", "meceng.tasks.parts", "meceng.tasks.assemblies", "meceng.tasks.design")

#: The levels whose task models have an open text (issue 36): the rigid ones, and the design tasks,
#: whose one text is an engineer's.
OPEN_TEXT_LEVELS = ("1", "2", "4")

#: Any kind of task model: they share id, name, level, slug and ``instance(seed)``.
AnyModel = TaskModel | PartModel | AssemblyModel | DesignModel


class UnknownTaskError(KeyError, ValueError):
    """Task keys (slugs or paper ids) that name no task model; the message names each one with the
    slugs it is closest to. A ``KeyError`` for lookups, a ``ValueError`` for the settings that carry
    the keys (``--only``, a sweep spec's ``only``), so both kinds of caller refuse it."""

    def __init__(self, unknown: list[str], suggestions: dict[str, list[str]]) -> None:
        super().__init__(unknown)
        self.unknown = unknown
        self.suggestions = suggestions

    def __str__(self) -> str:
        parts = []
        for key in self.unknown:
            close = self.suggestions.get(key) or []
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            parts.append(f"{key!r}{hint}")
        noun = "task model" if len(parts) == 1 else "task models"
        return (f"unknown {noun} {'; '.join(parts)}; `meceng tasks list` shows every slug and id")


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
        raise self._unknown([str(key)])

    def check(self, keys: Iterable[str | int]) -> None:
        """Refuse keys that name no task model (one typo in ``--only`` must not shrink a run without a
        word): raises ``UnknownTaskError`` naming every unknown key with its close matches."""
        known = {m.slug for m in self.models} | {str(m.id) for m in self.models}
        unknown = [str(k) for k in keys if str(k) not in known]
        if unknown:
            raise self._unknown(unknown)

    def _unknown(self, keys: list[str]) -> UnknownTaskError:
        slugs = [m.slug for m in self.models]
        return UnknownTaskError(keys, {k: difflib.get_close_matches(k.lower(), slugs, n=3, cutoff=0.6) for k in keys})

    def select(self, levels: Iterable[str] | None = None, only: Iterable[str] | None = None) -> list[AnyModel]:
        """The models of ``levels`` (all when None) among ``only`` (all when None); an unknown key in
        ``only`` is an error, not an empty selection."""
        if only:
            self.check(only)
        wanted_levels = {str(lv) for lv in levels} if levels else None
        wanted = {str(x) for x in only} if only else None
        return [
            m
            for m in self.models
            if (wanted_levels is None or m.level in wanted_levels)
            and (wanted is None or m.slug in wanted or str(m.id) in wanted)
        ]

    def instances(self, models: Iterable[AnyModel], seed: int, variations: int,
                  texts: str = "paper") -> list[TaskInstance]:
        """Variation k of every model uses seed ``seed + k``; order is model-major. ``texts``: the
        task text every instance gets (``"open"``: only level-1/2 models have one, see ``with_texts``)."""
        models = [m for m in models if texts == "paper" or isinstance(m, TaskModel | DesignModel)]
        return [self.instance_of(m, seed + k, texts) for m in models for k in range(variations)]

    @staticmethod
    def instance_of(model: AnyModel, seed: int, texts: str = "paper") -> TaskInstance:
        """One instance with the ``texts`` task text; parts and assemblies have the paper's alone, a
        design task its engineer's text alone (whatever ``texts`` asks)."""
        if texts == "paper" or isinstance(model, DesignModel):
            return model.instance(seed)
        if not isinstance(model, TaskModel):
            raise ValueError(f"task model {model.slug!r} (level {model.level}) has no {texts} text")
        return model.instance(seed, texts=texts)

    def with_texts(self, models: list[AnyModel], texts: str, levels: Iterable[str],
                   only: Iterable[str] = ()) -> tuple[list[AnyModel], list[str]]:
        """The models that have a ``texts`` text, and the slugs of those left out (none for the
        paper's texts). Refused with a ``ValueError`` saying why: an unknown kind of text, levels
        that have no open text (parts and assemblies: 3a, 3b), a model named in ``only`` that has
        none, or nothing left to run."""
        if texts not in TEXTS:
            raise ValueError(f"unknown texts {texts!r}: choose one of {', '.join(TEXTS)}")
        if texts == "paper":
            return list(models), []
        without_levels = sorted({str(lv) for lv in levels} - set(OPEN_TEXT_LEVELS))
        if without_levels:
            which = (f"level {without_levels[0]} has" if len(without_levels) == 1
                     else f"levels {', '.join(without_levels)} have")
            raise ValueError(f"{which} no open texts (parts and assemblies; only levels "
                             f"{', '.join(OPEN_TEXT_LEVELS)} do): run {'it' if len(without_levels) == 1 else 'them'} "
                             "with --texts paper")
        kept = [m for m in models if isinstance(m, TaskModel | DesignModel) and m.open_description.strip()]
        missing = [m.slug for m in models if m not in kept]
        wanted = {str(k) for k in only}
        named = [m.slug for m in models if m.slug in missing and (m.slug in wanted or str(m.id) in wanted)]
        if named:
            raise ValueError(f"no open text yet for {', '.join(named)}: run {'it' if len(named) == 1 else 'them'} "
                             "with --texts paper")
        if not kept:
            raise ValueError("none of the selected task models has an open text yet")
        return kept, missing


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
            if isinstance(task, TaskModel | PartModel | AssemblyModel | DesignModel):
                models.append(task)
    return TaskRegistry(tuple(sorted(models, key=lambda m: m.id)))


def default_registry() -> TaskRegistry:
    return discover()
