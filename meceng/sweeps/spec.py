"""Sweeps: the paper's studies as run folders, from a TOML spec, flags overriding it.

A spec names its models once (``[[models]]``) and its studies (``[[studies]]``), each a grid of
its own: models x temperatures x thinking x selection prompt x code prompt, on its own levels,
variations and seed. The paper varies one factor at a time (section 4: the main table at
temperature 0 without thinking, then temperature, thinking, prompt variants CI1-CI6 and
MBS1-MBS4, level 3), so studies share grid points; each point is one run folder named from
everything that defines it, and a point two studies share runs once. A point whose run.json
exists is skipped, one whose folder holds an unfinished journal is resumed, so rerunning a sweep
only does missing work. A spec without ``[[studies]]`` is one study of its ``[grid]``. A study's
``texts = ["paper", "open"]`` (or ``grid.texts``) runs its points on both task texts (issue 36).

Token limits follow the paper (section 2.3): context 4096 and answer 2048 tokens, times 1.5 for
models that reason even with thinking off, times 3.75 with thinking on; level 3 (parts and
assemblies, longer descriptions) starts from a 6144-token context (section 4.2).
"""

from __future__ import annotations

import itertools
import re
import tomllib
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path
from typing import Any

from meceng.agents.prompts import DEFAULT_CODE, DEFAULT_SELECT
from meceng.llm.types import LLMSettings, backend_for
from meceng.pipeline.settings import RunSettings
from meceng.sweeps.hosts import unreachable_hosts  # noqa: F401 (scripts/sweep.py takes it from here)
from meceng.sweeps.keys import (
    GRID_KEYS,
    SCOPE_KEYS,
    agent_of,
    as_tuple,
    check_keys,
    consensus_mode,
    only_of,
    temperature_of,
    texts_of,
    tools_of,
)
from meceng.tasks import default_registry

BASE_CTX = 4096
BASE_PREDICT = 2048
FLEXIBLE_CTX = 6144
REASONING_FACTOR = 1.5
THINKING_FACTOR = 3.75
DEFAULT_HOST = "http://127.0.0.1:11434"
REQUESTS_PER_TASK = 2  # the paper's pipeline: select components, then write the program


@dataclass(frozen=True)
class ModelSpec:
    """A model as a sweep runs it. ``think_off``/``think_on`` are what the grid's thinking axis
    means for this model (gpt-oss: reasoning "low" and "medium", paper Table 3);
    ``api_defaults`` sends neither temperature nor seed (the hosted models "with default API
    settings"); ``vision``: the model takes images (the agent loop's pictures); prices are USD per
    million tokens, for the report's cost column."""

    name: str
    backend: str = "ollama"
    hosts: tuple[str, ...] = (DEFAULT_HOST,)
    batch_size: int = 4
    reasons_anyway: bool = False
    release: str | None = None
    size_b: float | None = None
    think_off: bool | str = False
    think_on: bool | str = True
    api_defaults: bool = False
    api_key_env: str | None = None
    vision: bool = False
    price_prompt: float | None = None
    price_completion: float | None = None


@dataclass(frozen=True)
class Study:
    """One factor of the paper's design: its models and grid, levels, variations and seed."""

    name: str
    models: tuple[ModelSpec, ...]
    temperatures: tuple[float | None, ...] = (0.0,)  # None: the model's default temperature
    thinks: tuple[bool | str, ...] = (False,)
    select_templates: tuple[str, ...] = (DEFAULT_SELECT,)
    code_templates: tuple[str, ...] = (DEFAULT_CODE,)
    levels: tuple[str, ...] = ("1", "2")
    only: tuple[str, ...] = ()
    variations: int = 20
    seed: int = 0
    description: str = ""
    agent: str = "pipeline"  # "loop": the tool-calling agent; "repair": the repair benchmark; "consensus"
    repair_tools: bool = True
    drafts_per_task: int = 1
    texts: tuple[str, ...] = ("paper",)  # an axis: the paper's task texts and/or the open ones (issue 36)
    samples: int = 5  # agent = "consensus": independent programs per task
    consensus: str = "each"  # "across": one consensus run over all the study's models (k mod M)


@dataclass(frozen=True)
class SweepSpec:
    studies: tuple[Study, ...]
    out: Path = Path("runs")
    workers: int | None = None
    exec_timeout_s: float = 60.0  # CPU seconds per program (RunSettings.exec_timeout_s)
    description: str = ""
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def models(self) -> tuple[ModelSpec, ...]:
        seen: dict[str, ModelSpec] = {}
        for study in self.studies:
            for model in study.models:
                seen.setdefault(model.name, model)
        return tuple(seen.values())


@dataclass(frozen=True)
class GridPoint:
    """One run: everything that defines it, so that its folder name says it all."""

    model: ModelSpec
    temperature: float | None
    think: bool | str
    select_template: str
    code_template: str
    levels: tuple[str, ...] = ("1", "2")
    only: tuple[str, ...] = ()
    variations: int = 20
    seed: int = 0
    agent: str = "pipeline"
    repair_tools: bool = True
    drafts_per_task: int = 1
    texts: str = "paper"
    samples: int = 5
    # a consensus run across models: the point of each model (``model`` is the first's); sample k is
    # written by members[k mod M]
    members: tuple[GridPoint, ...] = ()

    def llms(self, llm_timeout_s: float = 600.0) -> tuple[LLMSettings, ...]:
        """The settings of every model of a consensus run across models (``RunSettings.consensus_models``)."""
        return tuple(member.llm(llm_timeout_s) for member in self.members)

    @property
    def model_points(self) -> tuple[GridPoint, ...]:
        """The point of each model this run asks: its members, or itself."""
        return self.members or (self,)

    @property
    def model_names(self) -> tuple[str, ...]:
        return tuple(p.model.name for p in self.model_points)

    @property
    def default_sampling(self) -> bool:
        return self.model.api_defaults or self.temperature is None

    def token_limits(self) -> tuple[int, int]:
        factor = THINKING_FACTOR if self.think not in (False, None) else (
            REASONING_FACTOR if self.model.reasons_anyway else 1.0)
        base = FLEXIBLE_CTX if any(level in ("3a", "3b") for level in self.levels) else BASE_CTX
        return int(base * factor), int(BASE_PREDICT * factor)

    def llm(self, llm_timeout_s: float = 600.0) -> LLMSettings:
        num_ctx, num_predict = self.token_limits()
        backend = backend_for(self.model.name, self.model.backend)
        return LLMSettings(model=self.model.name, backend=backend, hosts=self.model.hosts,
                           temperature=0.0 if self.temperature is None else self.temperature,
                           think=self.think, num_ctx=num_ctx, num_predict=num_predict,
                           batch_size=self.model.batch_size, timeout_s=llm_timeout_s,
                           api_defaults=self.default_sampling, api_key_env=self.model.api_key_env,
                           vision=self.model.vision)

    @property
    def name(self) -> str:
        temperature = "default" if self.default_sampling else f"{self.temperature:g}"
        models = "-and-".join(m.model.name for m in self.members) or self.model.name
        text = (f"{models}_T{temperature}_think-{self.think}_{self.select_template}_"
                f"{self.code_template}_L{'-'.join(self.levels)}_v{self.variations}_s{self.seed}")
        if self.only:
            text += "_only-" + "-".join(self.only)
        if self.model.vision:  # only then: the folders of earlier sweeps keep their names
            text += "_vision"
        if self.texts != "paper":  # likewise: a paper-text run's folder keeps its name
            text += f"_texts-{self.texts}"
        if self.agent == "repair":
            text += f"_repair-tools-{'on' if self.repair_tools else 'off'}-d{self.drafts_per_task}"
        elif self.agent == "consensus":
            text += f"_consensus-{'across-' if self.members else ''}k{self.samples}"
        elif self.agent != "pipeline":
            text += f"_agent-{self.agent}"
        return re.sub(r"[^A-Za-z0-9_.-]+", "-", text)


def _study(name: str, data: dict[str, Any], defaults: dict[str, Any], models: tuple[ModelSpec, ...]) -> Study:
    grid = {**defaults.get("grid", {}), **data.get("grid", {})}
    check_keys(f"study {name} grid", grid, GRID_KEYS)
    merged = {**defaults, **data}
    levels = tuple(str(x) for x in as_tuple(merged.get("levels", ["1", "2"])))
    only = only_of(merged.get("only", []))
    # consensus needs samples that differ: sampled at 0.7 unless the grid says otherwise
    default_t = 0.7 if merged.get("agent") == "consensus" else 0.0
    return Study(
        name=name, models=models,
        temperatures=tuple(temperature_of(t) for t in as_tuple(grid.get("temperature", [default_t]))),
        thinks=as_tuple(grid.get("think", [False])),
        select_templates=tuple(str(x) for x in as_tuple(grid.get("select_template", [DEFAULT_SELECT]))),
        code_templates=tuple(str(x) for x in as_tuple(grid.get("code_template", [DEFAULT_CODE]))),
        levels=levels, only=only,
        variations=int(merged.get("variations", 20)), seed=int(merged.get("seed", 0)),
        description=str(data.get("description", "")), agent=agent_of(name, merged.get("agent", "pipeline")),
        repair_tools=tools_of(name, merged.get("tools", "on")), drafts_per_task=int(merged.get("drafts_per_task", 1)),
        samples=int(merged.get("samples", 5)),
        consensus=consensus_mode(name, merged.get("consensus", "each"), merged.get("agent", "pipeline"), len(models)),
        texts=texts_of(name, grid.get("texts", merged.get("texts", ["paper"])), levels, only),
    )


MODEL_KEYS = set(ModelSpec.__dataclass_fields__)


def load_spec(path: Path) -> SweepSpec:
    """Read a sweep spec; unknown keys are an error (a typo must not silently change a study)."""
    data = tomllib.loads(path.read_text())
    check_keys(str(path), data, SCOPE_KEYS | {"models", "studies", "out", "workers", "exec_timeout_s"})
    catalogue: dict[str, ModelSpec] = {}
    for entry in data.get("models", []):
        check_keys(f"{path}: model {entry.get('name')}", entry, MODEL_KEYS)
        entry = dict(entry)
        entry["hosts"] = tuple(entry.get("hosts", (DEFAULT_HOST,)))
        catalogue[entry["name"]] = ModelSpec(**entry)
    defaults = {k: v for k, v in data.items() if k in SCOPE_KEYS - {"description"}}
    studies = []
    for entry in data.get("studies", []):
        name = str(entry.get("name", ""))
        if not name:
            raise ValueError(f"{path}: a study without a name")
        check_keys(f"{path}: study {name}", entry, SCOPE_KEYS | {"name", "models"})
        missing = [m for m in as_tuple(entry.get("models")) if m not in catalogue]
        if missing:
            raise ValueError(f"{path}: study {name} names models not in [[models]]: {missing}")
        chosen = tuple(catalogue[m] for m in as_tuple(entry.get("models"))) or tuple(catalogue.values())
        studies.append(_study(name, entry, defaults, chosen))
    if not studies:
        studies.append(_study("sweep", {}, defaults, tuple(catalogue.values())))
    if len({s.name for s in studies}) != len(studies):
        raise ValueError(f"{path}: two studies share a name")
    return SweepSpec(studies=tuple(studies), out=Path(data.get("out", "runs")), workers=data.get("workers"),
                     exec_timeout_s=float(data.get("exec_timeout_s", 60.0)),
                     description=str(data.get("description", "")))


def _think(model: ModelSpec, think: bool | str) -> bool | str:
    if think is True:
        return model.think_on
    if think is False:
        return model.think_off
    return think  # an explicit level ("low", "high") is taken as given


def _point(study: Study, model: ModelSpec, temperature: float | None, think: bool | str, select: str, code: str,
           texts: str) -> GridPoint:
    return GridPoint(model, temperature, _think(model, think), select, code, study.levels, study.only,
                     study.variations, study.seed, study.agent, study.repair_tools, study.drafts_per_task,
                     texts, study.samples)


def study_points(study: Study) -> list[GridPoint]:
    """The study's runs; points that coincide (a hosted model at several temperatures it never
    receives) are one."""
    points = {}
    across = study.consensus == "across"  # one run over all the models instead of one per model
    for model, temperature, think, select, code, texts in itertools.product(
            study.models[:1] if across else study.models, study.temperatures, study.thinks, study.select_templates,
            study.code_templates, study.texts):
        axes = (temperature, think, select, code, texts)
        point = _point(study, model, *axes)
        if across:
            point = replace(point, members=tuple(_point(study, m, *axes) for m in study.models))
        points.setdefault(point.name, point)
    return list(points.values())


@dataclass(frozen=True)
class PlannedRun:
    study: str
    point: GridPoint
    shared_with: str | None  # the earlier study that already runs this point


def plan(spec: SweepSpec) -> list[PlannedRun]:
    """Every study's runs in spec order; a point an earlier study holds is marked shared."""
    owner: dict[str, str] = {}
    planned = []
    for study in spec.studies:
        for point in study_points(study):
            planned.append(PlannedRun(study.name, point, owner.get(point.name)))
            owner.setdefault(point.name, study.name)
    return planned


def unique_points(planned: list[PlannedRun]) -> list[GridPoint]:
    return [run.point for run in planned if run.shared_with is None]


@cache
def workload(levels: tuple[str, ...], only: tuple[str, ...], variations: int, seed: int,
             texts: str = "paper", agent: str = "pipeline", samples: int = 5, drafts_per_task: int = 1,
             repair_tools: bool = True) -> tuple[int, int]:
    """(task records, LLM requests at most) of one pipeline run: an assembly counts its distinct
    parts too, and its own requests are made only when every part passed; open texts count the
    models that have one. Requests per task by the run's agent (``requests_per_task``); a repair run
    has up to ``drafts_per_task`` tasks per instance (only the drafts that fail are tasks)."""
    registry = default_registry()
    models, _ = registry.with_texts(registry.select(levels, only or None), texts, levels, only)
    records = 0
    for instance in registry.instances(models, seed, variations, texts):
        records += 1 + len({part.key for _, part in instance.parts}) if instance.kind == "assembly" else 1
    if agent == "repair":
        records *= drafts_per_task
    return records, records * requests_per_task(agent, samples, repair_tools)


def requests_per_task(agent: str, samples: int = 5, repair_tools: bool = True) -> int:
    """LLM requests one task makes at most: the pipeline selects and writes (2); a consensus of K
    samples does so K times; the tool-calling loop selects and then asks up to its rounds; a repair
    draft has its components chosen and asks once, or up to the rounds with tools."""
    rounds = RunSettings.max_rounds  # the runs a sweep starts keep the default
    if agent == "consensus":
        return REQUESTS_PER_TASK * samples
    if agent == "loop":
        return 1 + rounds
    if agent == "repair":
        return rounds if repair_tools else 1
    return REQUESTS_PER_TASK


def point_workload(point: GridPoint) -> tuple[int, int]:
    return workload(point.levels, point.only, point.variations, point.seed, point.texts, point.agent,
                    point.samples, point.drafts_per_task, point.repair_tools)


def with_overrides(study: Study, **changes: Any) -> Study:
    return replace(study, **{k: v for k, v in changes.items() if v is not None})
