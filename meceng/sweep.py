"""Sweeps: a grid of runs from a TOML spec, flags overriding it.

The grid is models x temperatures x thinking x selection prompt x code prompt; each point is one
run folder named from its settings. A point whose run.json exists is skipped, a point whose
folder holds an unfinished journal is resumed, so rerunning a sweep only does missing work.

Token limits follow the paper (section 2.3): context 4096 and answer 2048 tokens, times 1.5 for
models that reason even with thinking off, times 3.75 with thinking on; level 3 (parts and
assemblies, longer descriptions) starts from a 6144-token context (section 4.2).
"""

from __future__ import annotations

import asyncio
import itertools
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import httpx

from meceng.agents.llm import LLMSettings
from meceng.agents.prompts import DEFAULT_CODE, DEFAULT_SELECT

BASE_CTX = 4096
BASE_PREDICT = 2048
FLEXIBLE_CTX = 6144
REASONING_FACTOR = 1.5
THINKING_FACTOR = 3.75


@dataclass(frozen=True)
class ModelSpec:
    name: str
    backend: str = "ollama"
    hosts: tuple[str, ...] = ("http://127.0.0.1:11434",)
    batch_size: int = 4
    reasons_anyway: bool = False
    release: str | None = None
    size_b: float | None = None


@dataclass(frozen=True)
class SweepSpec:
    models: tuple[ModelSpec, ...]
    temperatures: tuple[float, ...] = (0.0,)
    thinks: tuple[bool | str, ...] = (False,)
    select_templates: tuple[str, ...] = (DEFAULT_SELECT,)
    code_templates: tuple[str, ...] = (DEFAULT_CODE,)
    levels: tuple[str, ...] = ("1", "2")
    only: tuple[str, ...] = ()
    variations: int = 20
    seed: int = 0
    out: Path = Path("runs")
    workers: int | None = None
    exec_timeout_s: float = 60.0
    extra: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class GridPoint:
    model: ModelSpec
    temperature: float
    think: bool | str
    select_template: str
    code_template: str

    def token_limits(self, levels: tuple[str, ...] = ("1", "2")) -> tuple[int, int]:
        factor = THINKING_FACTOR if self.think not in (False, None) else (
            REASONING_FACTOR if self.model.reasons_anyway else 1.0)
        base = FLEXIBLE_CTX if any(level in ("3a", "3b") for level in levels) else BASE_CTX
        return int(base * factor), int(BASE_PREDICT * factor)

    def llm(self, llm_timeout_s: float = 600.0, levels: tuple[str, ...] = ("1", "2")) -> LLMSettings:
        num_ctx, num_predict = self.token_limits(levels)
        backend = "gold" if self.model.name == "gold" else self.model.backend
        return LLMSettings(model=self.model.name, backend=backend, hosts=self.model.hosts,
                           temperature=self.temperature, think=self.think, num_ctx=num_ctx,
                           num_predict=num_predict, batch_size=self.model.batch_size, timeout_s=llm_timeout_s)

    def name(self, spec: SweepSpec) -> str:
        levels = "-".join(spec.levels)
        text = (f"{self.model.name}_T{self.temperature:g}_think-{self.think}_{self.select_template}_"
                f"{self.code_template}_L{levels}_v{spec.variations}_s{spec.seed}")
        return re.sub(r"[^A-Za-z0-9_.-]+", "-", text)


def _tuple(value: Any) -> tuple[Any, ...]:
    if value is None:
        return ()
    return tuple(value) if isinstance(value, list | tuple) else (value,)


def load_spec(path: Path) -> SweepSpec:
    """Read a sweep spec; unknown keys are an error (a typo must not silently change a study)."""
    data = tomllib.loads(path.read_text())
    known = {"models", "grid", "levels", "only", "variations", "seed", "out", "workers", "exec_timeout_s",
             "description"}
    unknown = set(data) - known
    if unknown:
        raise ValueError(f"{path}: unknown keys {sorted(unknown)}")
    models = []
    for entry in data.get("models", []):
        entry = dict(entry)
        entry["hosts"] = tuple(entry.get("hosts", ("http://127.0.0.1:11434",)))
        models.append(ModelSpec(**entry))
    grid = data.get("grid", {})
    return SweepSpec(
        models=tuple(models),
        temperatures=tuple(float(t) for t in _tuple(grid.get("temperature", [0.0]))),
        thinks=_tuple(grid.get("think", [False])),
        select_templates=_tuple(grid.get("select_template", [DEFAULT_SELECT])),
        code_templates=_tuple(grid.get("code_template", [DEFAULT_CODE])),
        levels=tuple(str(x) for x in _tuple(data.get("levels", ["1", "2"]))),
        only=tuple(str(x) for x in _tuple(data.get("only", []))),
        variations=int(data.get("variations", 20)),
        seed=int(data.get("seed", 0)),
        out=Path(data.get("out", "runs")),
        workers=data.get("workers"),
        exec_timeout_s=float(data.get("exec_timeout_s", 60.0)),
    )


def grid_points(spec: SweepSpec) -> list[GridPoint]:
    return [GridPoint(*p) for p in itertools.product(spec.models, spec.temperatures, spec.thinks,
                                                          spec.select_templates, spec.code_templates)]


async def _answers(host: str, path: str, timeout_s: float = 3.0) -> bool:
    try:
        async with httpx.AsyncClient(timeout=timeout_s) as client:
            response = await client.get(host.rstrip("/") + path)
            return response.status_code == 200
    except httpx.HTTPError:
        return False


def unreachable_hosts(points: list[GridPoint]) -> list[str]:
    """Hosts of Ollama grid points that do not answer ``/api/version``."""
    hosts = sorted({h for p in points if p.llm().backend == "ollama" for h in p.model.hosts})
    openai_hosts = sorted({h for p in points if p.llm().backend == "openai" for h in p.model.hosts})

    async def probe() -> list[str]:
        results = await asyncio.gather(*(_answers(h, "/api/version") for h in hosts),
                                       *(_answers(h, "/models") for h in openai_hosts))
        return [h for h, ok in zip(hosts + openai_hosts, results, strict=True) if not ok]

    return asyncio.run(probe()) if hosts or openai_hosts else []


def with_overrides(spec: SweepSpec, **changes: Any) -> SweepSpec:
    return replace(spec, **{k: v for k, v in changes.items() if v is not None})
