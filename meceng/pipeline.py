"""The asyncio pipeline: task instances -> LLM steps -> isolated execution -> verdicts -> records.

Per task instance (paper Fig. 2): choose components, build the context, generate the program,
run it in isolation, run the ground truth the same way (once per instance, cached), grade. The
instances run as concurrent coroutines: LLM calls are bounded per endpoint by the backend's
scheduler and executions by a worker semaphore, so inference of one task overlaps the evaluation
of another and a run costs about max(LLM time, evaluation time). Every finished task is appended
to the JSONL journal at once; one task's failure is recorded and never stops the run.
"""

from __future__ import annotations

import asyncio
import datetime as dt
import json
import logging
import os
import platform
import re
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import structlog

from meceng.agents.cache import CachedBackend, ResponseCache, read_jsonl
from meceng.agents.catalog import Catalog, assembly_catalog, part_catalog, rigid_catalog
from meceng.agents.llm import Backend, LLMSettings, make_backend
from meceng.agents.loop import AgentResult, run_agent
from meceng.agents.prompts import DEFAULT_CODE, DEFAULT_PART_CODE, DEFAULT_PART_SELECT, DEFAULT_SELECT
from meceng.agents.steps import Generation, Selection, choose_components, generate_code
from meceng.agents.toolbox import Toolbox
from meceng.eval import EVALUATOR_VERSION
from meceng.eval.aggregate import summarize
from meceng.eval.chain import RIGID_STAGES, StageResult, Tolerances, Verdict, evaluate_rigid
from meceng.eval.parts import evaluate_part, minimum_maxh, part_data
from meceng.logs import get_logger
from meceng.tasks.base import TaskInstance, program_header
from meceng.tasks.registry import TaskRegistry, default_registry
from meceng.tools.executor import Execution, ExecutionLimits, child_env, execute
from meceng.tools.meshcheck import check_mesh_size
from meceng.tools.warm import WarmPool

log = get_logger("meceng.pipeline")


@dataclass(frozen=True)
class RunSettings:
    """Everything that defines a run; written to run.json as given."""

    llm: LLMSettings = field(default_factory=LLMSettings)
    levels: tuple[str, ...] = ("1", "2")
    only: tuple[str, ...] = ()
    variations: int = 3
    seed: int = 0
    out: Path = Path("runs")
    run_name: str | None = None
    workers: int = max(1, os.cpu_count() or 1)
    exec_timeout_s: float = 60.0
    select_template: str = DEFAULT_SELECT
    code_template: str = DEFAULT_CODE
    solution_tolerance: float = 1e-5
    progress: bool = True
    resume: bool = False
    executor: str = "fork"
    agent: str = "pipeline"  # "pipeline": the paper's two steps; "loop": tool-calling agent that tests its code
    max_rounds: int = 6
    token_budget: int = 30000
    part_select_template: str = DEFAULT_PART_SELECT
    part_code_template: str = DEFAULT_PART_CODE
    part_timeout_s: float = 300.0  # meshing + HCB of a part; the paper's parts take seconds

    @classmethod
    def from_json(cls, data: dict[str, Any], out: Path, run_name: str) -> RunSettings:
        """Rebuild the settings a run was started with (for ``--resume``)."""
        llm = dict(data["llm"])
        llm["hosts"] = tuple(llm["hosts"])
        pipeline = data["pipeline"]
        return cls(
            llm=LLMSettings(**llm), levels=tuple(pipeline["levels"]), only=tuple(pipeline["only"]),
            variations=pipeline["variations"], seed=pipeline["seed"], out=out, run_name=run_name,
            workers=pipeline["workers"], exec_timeout_s=pipeline["exec_timeout_s"],
            solution_tolerance=pipeline["solution_tolerance"], select_template=data["prompt"]["select_template"],
            code_template=data["prompt"]["code_template"], resume=True,
            executor=pipeline.get("executor", "fork"), agent=pipeline.get("agent", "pipeline"),
            max_rounds=pipeline.get("max_rounds", 6), token_budget=pipeline.get("token_budget", 30000),
            part_timeout_s=pipeline.get("part_timeout_s", 300.0),
            part_select_template=data["prompt"].get("part_select_template", DEFAULT_PART_SELECT),
            part_code_template=data["prompt"].get("part_code_template", DEFAULT_PART_CODE),
        )

    def to_json(self) -> dict[str, Any]:
        return {
            "llm": self.llm.to_json(),
            "pipeline": {
                "executor": self.executor, "agent": self.agent, "max_rounds": self.max_rounds,
                "token_budget": self.token_budget,
                "levels": list(self.levels), "only": list(self.only), "variations": self.variations,
                "seed": self.seed, "workers": self.workers, "exec_timeout_s": self.exec_timeout_s,
                "solution_tolerance": self.solution_tolerance, "part_timeout_s": self.part_timeout_s,
            },
            "prompt": {"select_template": self.select_template, "code_template": self.code_template,
                       "part_select_template": self.part_select_template,
                       "part_code_template": self.part_code_template},
        }


class ReferenceCache:
    """Ground-truth executions, run once per task instance and shared by everyone who asks."""

    def __init__(self, run: Callable[[TaskInstance], Any]) -> None:
        self._run = run
        self._tasks: dict[str, asyncio.Task[Execution]] = {}

    def start(self, instance: TaskInstance) -> asyncio.Task[Execution]:
        task = self._tasks.get(instance.key)
        if task is None:
            task = asyncio.ensure_future(self._run(instance))
            self._tasks[instance.key] = task
        return task

    async def get(self, instance: TaskInstance) -> Execution:
        return await asyncio.shield(self.start(instance))


class Evaluator:
    """Runs candidate and reference programs in isolation (bounded by ``workers``) and grades."""

    def __init__(self, workers: int, limits: ExecutionLimits, tolerances: Tolerances, catalog: Catalog,
                 pool: WarmPool | None = None, parts: Catalog | None = None,
                 part_timeout_s: float = 300.0) -> None:
        self.slots = asyncio.Semaphore(workers)
        self.pool = pool
        self.limits = limits
        self.tolerances = tolerances
        self.catalog = catalog
        self.part_catalog = parts or part_catalog()
        self.assembly_catalog = assembly_catalog()
        self.part_limits = replace(limits, mode="part", timeout_s=max(limits.timeout_s, part_timeout_s))
        self.references = ReferenceCache(self._run_reference)
        self._remeshed: dict[tuple[str, float], asyncio.Task[Execution]] = {}

    def catalog_for(self, instance: TaskInstance) -> Catalog:
        return {"part": self.part_catalog, "assembly": self.assembly_catalog}.get(instance.kind, self.catalog)

    async def _execute(self, program: str, instance: TaskInstance, check: bool,
                       files: dict[str, Path] | None = None) -> Execution:
        async with self.slots:
            return await execute(program, instance.sim.block(), self.limits, check=check, pool=self.pool, files=files)

    async def _run_reference(self, instance: TaskInstance) -> Execution:
        if instance.kind == "part":
            return await self._execute_part(instance.reference_program, instance, check=False)
        return await self._execute(instance.reference_program, instance, check=False)

    async def _execute_part(self, program: str, instance: TaskInstance, check: bool,
                            save_to: Path | None = None) -> Execution:
        limits = replace(self.part_limits, n_modes=instance.part.n_modes,
                         save_fem_to=str(save_to) if save_to is not None else None)
        async with self.slots:
            return await execute(program, "", limits, check=check, pool=self.pool)

    async def _reference_at(self, instance: TaskInstance, maxh: float) -> Execution:
        """The ground-truth part meshed with another maxh (run once per instance and size)."""
        key = (instance.key, maxh)
        if key not in self._remeshed:
            program = re.sub(r"GenerateMesh\(maxh=[^)]*\)", f"GenerateMesh(maxh={maxh!r})", instance.reference_program)
            self._remeshed[key] = asyncio.ensure_future(self._execute_part(program, instance, check=False))
        return await asyncio.shield(self._remeshed[key])

    async def evaluate_part(
        self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None, code_error: str | None,
        save_to: Path | None = None,
    ) -> tuple[Verdict, Execution, Execution, dict[str, Any]]:
        """Level 3a: ground truth first (its bounding box sets the finest allowed maxh), then the
        mesh-size pre-check, the candidate part, the part metrics. ``save_to`` keeps a passing part.

        Returns the verdict, both executions and facts about the pre-check and the metrics' time.
        """
        reference = await self.references.get(instance)
        facts: dict[str, Any] = {}
        if reference.error is not None or reference.part is None or reference.surface is None:
            failure = f"ground-truth part failed: {reference.error or 'no part captured'}"
            return Verdict((), infrastructure_error=failure), Execution(stage="not_run"), reference, facts
        truth = part_data(reference.part, reference.surface, reference.fine_surface)
        minimum = minimum_maxh(truth, instance.part.maxh)
        facts["minimum_maxh"] = minimum
        pending = save_to.with_name(save_to.name + ".pending.npz") if save_to is not None else None
        if code is None:
            candidate = Execution(stage="no_code", error=code_error or "no program", error_kind="no_code")
        else:
            mesh_check = check_mesh_size(code, minimum)
            facts.update(maxh=list(mesh_check.maxh), maxh_raised=mesh_check.raised)
            if mesh_check.code is None:
                candidate = Execution(stage="flagged", error=mesh_check.error, error_kind="mesh_size")
            else:
                candidate = await self._execute_part(mesh_check.code, instance, check=True, save_to=pending)
        produced = None
        frequencies = None
        if candidate.error is None and candidate.part is not None and candidate.surface is not None:
            produced = part_data(candidate.part, candidate.surface, candidate.fine_surface)
            sizes = {max(v, minimum) for v in facts.get("maxh", [])}
            if len(sizes) == 1 and (size := sizes.pop()) != instance.part.maxh:
                remeshed = await self._reference_at(instance, size)
                if remeshed.part is not None:
                    frequencies = np.asarray(remeshed.part["eigenfrequencies"], dtype=float)
                    facts["reference_frequencies_at_maxh"] = size
        t0 = time.perf_counter()
        stages = await asyncio.to_thread(
            evaluate_part, produced, truth, selected=selected, required=instance.required_components,
            dependencies=self.part_catalog.dependency_map(), failure=candidate.error,
            reference_frequencies=frequencies)
        facts["metrics_s"] = time.perf_counter() - t0
        verdict = Verdict(tuple(stages))
        if pending is not None and save_to is not None and pending.exists():
            if verdict.overall:
                os.replace(pending, save_to)
                facts["saved_part"] = str(save_to)
            else:
                pending.unlink()
        return verdict, candidate, reference, facts

    def prefetch(self, instance: TaskInstance) -> None:
        """Start the reference execution now, while the LLM is still busy with this task."""
        self.references.start(instance)

    async def evaluate(
        self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None, code_error: str | None,
        files: dict[str, Path] | None = None,
    ) -> tuple[Verdict, Execution, Execution]:
        """Run candidate and reference, grade with the level 1-2 chain. ``files``: the parts an
        assembly loads; both programs get the same ones (the reference is then run uncached)."""
        if files:
            reference_task = asyncio.ensure_future(
                self._execute(instance.reference_program, instance, check=False, files=files))
        else:
            reference_task = asyncio.ensure_future(self.references.get(instance))
        if code is None:
            candidate = Execution(stage="no_code", error=code_error or "no program", error_kind="no_code")
        else:
            candidate = await self._execute(code, instance, check=True, files=files)
        reference = await reference_task
        verdict = evaluate_rigid(
            candidate, reference, end_time=instance.sim.end_time, steps=instance.sim.steps,
            selected=selected, required=instance.required_components,
            dependencies=self.catalog_for(instance).dependency_map(), tolerances=self.tolerances,
        )
        return verdict, candidate, reference


def record_key(record: dict[str, Any]) -> str:
    """The key of the instance a record belongs to (a part drawn for an assembly names it)."""
    own = f"{record['slug']}@{record['seed']}"
    return f"{record['origin']}/{own}" if record.get("origin") else own


def _safe_name(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", text).strip("-") or "run"


def versions() -> dict[str, str]:
    """Package versions from their metadata (importing NGSolve here would cost a third of a second)."""
    from importlib.metadata import PackageNotFoundError, version

    out = {"python": platform.python_version(), "platform": platform.platform()}
    for package in ("meceng", "exudyn", "ngsolve", "netgen-mesher", "numpy", "scipy", "networkx", "ollama",
                    "pymeshlab"):
        try:
            out[package] = version(package)
        except PackageNotFoundError:
            out[package] = "not installed"
    return out


def gpu_telemetry() -> list[dict[str, str]]:
    """nvidia-smi readings where a GPU exists; empty elsewhere."""
    import shutil
    import subprocess

    if shutil.which("nvidia-smi") is None:
        return []
    try:
        out = subprocess.run(
            ["nvidia-smi", "--query-gpu=name,memory.total,memory.used,utilization.gpu,driver_version",
             "--format=csv,noheader"], capture_output=True, text=True, timeout=10, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return []
    keys = ("name", "memory_total", "memory_used", "utilization", "driver")
    return [dict(zip(keys, (p.strip() for p in line.split(",")), strict=False)) for line in out.splitlines()]


class RunWriter:
    """The run directory: journal.jsonl as tasks finish, programs/, and run.json at the end."""

    def __init__(self, run_dir: Path) -> None:
        self.run_dir = run_dir
        (run_dir / "programs").mkdir(parents=True, exist_ok=True)
        self.journal_path = run_dir / "journal.jsonl"
        self.finished = read_jsonl(self.journal_path)  # also cuts a line half-written by a kill
        self._journal = open(self.journal_path, "a", encoding="utf-8")  # noqa: SIM115 - kept open for the run

    def part_path(self, instance: TaskInstance) -> Path:
        """Where a passing part's reduced FEM model is kept (for its assembly)."""
        folder = self.run_dir / "parts"
        folder.mkdir(parents=True, exist_ok=True)
        return folder / f"{_safe_name(instance.key.replace('/', '--'))}.npz"

    def save_programs(self, instance: TaskInstance, code: str | None) -> dict[str, str]:
        folder = self.run_dir / "programs" / instance.slug
        folder.mkdir(parents=True, exist_ok=True)
        stem = f"seed{instance.seed}" + (f"_for_{_safe_name(instance.origin)}" if instance.origin else "")
        reference = folder / f"{stem}_reference.py"
        _write_atomic(reference, instance.reference_program)
        files = {"reference": str(reference.relative_to(self.run_dir))}
        if code is not None:
            generated = folder / f"{stem}_generated.py"
            header = program_header(f"generated program: {instance.task_id} {instance.name}, seed {instance.seed}",
                                    instance.description)
            _write_atomic(generated, f"{header}\n{code}")
            files["generated"] = str(generated.relative_to(self.run_dir))
        return files

    def append(self, record: dict[str, Any]) -> None:
        self._journal.write(json.dumps(record, default=str) + "\n")
        self._journal.flush()
        os.fsync(self._journal.fileno())

    def finish(self, settings: RunSettings, records: list[dict[str, Any]], started: float, wall: float,
               extra: dict[str, Any] | None = None) -> Path:
        self._journal.close()
        run = {
            **(extra or {}),
            "settings": settings.to_json(),
            "versions": versions(),
            "gpu": gpu_telemetry(),
            "started": dt.datetime.fromtimestamp(started, dt.UTC).isoformat(),
            "wall_time_s": wall,
            "summary": summarize(records),
            "tasks": records,
        }
        path = self.run_dir / "run.json"
        tmp = path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(run, indent=1, default=str))
        os.replace(tmp, path)
        return path


def _write_atomic(path: Path, text: str) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def task_record(
    instance: TaskInstance,
    selection: Selection,
    generation: Generation,
    verdict: Verdict,
    candidate: Execution,
    reference: Execution,
    timing: dict[str, float],
    files: dict[str, str],
) -> dict[str, Any]:
    infra = selection.infrastructure_error or generation.infrastructure_error or verdict.infrastructure_error
    verdict_json = verdict.to_json()
    if infra and not verdict.infrastructure_error:
        verdict_json.update(overall=False, first_failure="infrastructure")
    return {
        "id": instance.task_id,
        "slug": instance.slug,
        "name": instance.name,
        "level": instance.level,
        "seed": instance.seed,
        "params": instance.params,
        "description": instance.description,
        "required_components": list(instance.required_components),
        **verdict_json,
        "infrastructure_error": infra,
        "selection": selection.to_json(),
        "generation": generation.to_json(),
        "execution": candidate.summary(),
        "reference_execution": reference.summary(),
        "timing": {k: round(v, 4) for k, v in timing.items()},
        "tokens": {
            "prompt": sum(m.get("prompt_tokens", 0) for m in (selection.meta, generation.meta)),
            "completion": sum(m.get("completion_tokens", 0) for m in (selection.meta, generation.meta)),
        },
        "files": files,
        "evaluator": EVALUATOR_VERSION,
    }


async def run_task(
    instance: TaskInstance, backend: Backend, catalog: Catalog, evaluator: Evaluator, settings: RunSettings,
    writer: RunWriter,
) -> dict[str, Any]:
    if instance.kind == "part":
        return await run_part_task(instance, backend, evaluator, settings, writer)
    if instance.kind == "assembly":
        raise ValueError("assemblies are run by run_assembly_task")
    t0 = time.perf_counter()
    evaluator.prefetch(instance)
    selection = await choose_components(backend, instance, catalog, settings.select_template)
    if settings.agent == "loop":
        return await _run_agent_task(instance, backend, catalog, evaluator, settings, writer, selection, t0)
    generation = await generate_code(backend, instance, catalog, selection, settings.code_template)
    t_llm = time.perf_counter() - t0
    selected = selection.names if selection.infrastructure_error is None else ()
    verdict, candidate, reference = await evaluator.evaluate(instance, generation.code, selected, generation.error)
    t_total = time.perf_counter() - t0
    files = writer.save_programs(instance, generation.code)
    return task_record(instance, selection, generation, verdict, candidate, reference,
                       {"llm_s": t_llm, "evaluation_s": t_total - t_llm, "total_s": t_total}, files)


async def run_part_task(
    instance: TaskInstance, backend: Backend, evaluator: Evaluator, settings: RunSettings, writer: RunWriter,
) -> dict[str, Any]:
    """Level 3a (paper Fig. 5): choose part components, write the part program, pre-check its mesh
    size, mesh and reduce it in isolation, grade it with the part metrics, keep it if it passes."""
    t0 = time.perf_counter()
    evaluator.prefetch(instance)
    catalog = evaluator.part_catalog
    selection = await choose_components(backend, instance, catalog, settings.part_select_template)
    selected = selection.names if selection.infrastructure_error is None else ()
    agent = None
    if settings.agent == "loop":
        toolbox = Toolbox(instance, catalog, evaluator.part_limits, evaluator.pool)
        agent = await run_agent(backend, instance, catalog, selection, toolbox, template=settings.part_code_template,
                                max_rounds=settings.max_rounds, token_budget=settings.token_budget)
        generation = _agent_generation(agent)
    else:
        generation = await generate_code(backend, instance, catalog, selection, settings.part_code_template)
    t_llm = time.perf_counter() - t0
    verdict, candidate, reference, facts = await evaluator.evaluate_part(
        instance, generation.code, selected, generation.error, save_to=writer.part_path(instance))
    first = verdict
    if agent is not None and agent.first_code != agent.final_code:
        first, _, _, _ = await evaluator.evaluate_part(instance, agent.first_code, selected, agent.error)
    t_total = time.perf_counter() - t0
    files = writer.save_programs(instance, generation.code)
    if "saved_part" in facts:
        files["part"] = str(Path(facts.pop("saved_part")).relative_to(writer.run_dir))
    timing = {"llm_s": t_llm, "evaluation_s": t_total - t_llm, "total_s": t_total,
              "part_run_s": candidate.wall_time, "reference_run_s": reference.wall_time,
              **{k: v for k, v in candidate.part_times.items()}, "metrics_s": facts.pop("metrics_s", 0.0)}
    record = task_record(instance, selection, generation, verdict, candidate, reference, timing, files)
    record["part"] = {**facts, "spec": instance.part.to_json(), "reference_times": reference.part_times,
                      "reference_nodes": (reference.part or {}).get("nodes")}
    if agent is not None:
        record["agent"] = _agent_block(agent, first)
    if instance.origin:
        record["origin"] = instance.origin
    return record


async def run_assembly_task(
    instance: TaskInstance, backend: Backend, evaluator: Evaluator, settings: RunSettings, writer: RunWriter,
) -> list[dict[str, Any]]:
    """Level 3b (paper Fig. 4-5): every part first; the assembly starts only when all passed,
    and then both its program and the ground truth load the LLM-made parts.

    Returns the part records followed by the assembly's record.
    """
    t0 = time.perf_counter()
    # a part the assembly uses twice (two identical bearing blocks) is generated once and loaded twice
    unique = {part.key: part for _, part in instance.parts}
    part_records = list(await asyncio.gather(
        *(run_part_task(part, backend, evaluator, settings, writer) for part in unique.values())))
    by_key = dict(zip(unique, part_records, strict=True))
    t_parts = time.perf_counter() - t0
    started = all(r["overall"] for r in part_records)
    passed = sum(1 for r in part_records if r["overall"])
    parts_stage = StageResult("parts_overall", started, f"{passed} of {len(part_records)} parts passed")
    part_keys = {slot: part.key for slot, part in instance.parts}
    part_timing = {"parts_llm_s": sum(r["timing"]["llm_s"] for r in part_records),
                   "parts_evaluation_s": sum(r["timing"]["evaluation_s"] for r in part_records),
                   "parts_wall_s": t_parts}
    if not started:
        stages = (parts_stage, StageResult("mbs_started", False, "not started: a part failed"),
                  *(StageResult(name, None, "not started") for name in RIGID_STAGES))
        record = _assembly_record(instance, Verdict(stages), part_keys, part_timing)
        return [*part_records, record]
    files = {f"{slot}.npz": writer.run_dir / by_key[part.key]["files"]["part"] for slot, part in instance.parts}
    catalog = evaluator.assembly_catalog
    t1 = time.perf_counter()
    selection = await choose_components(backend, instance, catalog, settings.select_template)
    agent = None
    if settings.agent == "loop":
        toolbox = Toolbox(instance, catalog, evaluator.limits, evaluator.pool, files=files)
        agent = await run_agent(backend, instance, catalog, selection, toolbox, template=settings.code_template,
                                max_rounds=settings.max_rounds, token_budget=settings.token_budget)
        generation = _agent_generation(agent)
    else:
        generation = await generate_code(backend, instance, catalog, selection, settings.code_template)
    t_llm = time.perf_counter() - t1
    selected = selection.names if selection.infrastructure_error is None else ()
    chain, candidate, reference = await evaluator.evaluate(instance, generation.code, selected, generation.error,
                                                           files=files)
    first = chain
    if agent is not None and agent.first_code != agent.final_code:
        first, _, _ = await evaluator.evaluate(instance, agent.first_code, selected, agent.error, files=files)
    t_total = time.perf_counter() - t0
    verdict = Verdict((parts_stage, StageResult("mbs_started", True, "all parts passed"), *chain.stages),
                      chain.error_categories, chain.differences, chain.solution_norm, chain.infrastructure_error)
    program_files = writer.save_programs(instance, generation.code)
    timing = {"llm_s": t_llm, "evaluation_s": t_total - t_parts - t_llm, "total_s": t_total,
              "mbs_evaluation_s": t_total - t_parts - t_llm, **part_timing}
    record = task_record(instance, selection, generation, verdict, candidate, reference, timing, program_files)
    record["parts"] = part_keys
    if agent is not None:
        record["agent"] = _agent_block(agent, first)
    return [*part_records, record]


def _assembly_record(instance: TaskInstance, verdict: Verdict, part_keys: dict[str, str],
                     timing: dict[str, float]) -> dict[str, Any]:
    """The record of an assembly that was not started (a part failed): no LLM call, no run."""
    return {
        "id": instance.task_id, "slug": instance.slug, "name": instance.name, "level": instance.level,
        "seed": instance.seed, "params": instance.params, "description": instance.description,
        "required_components": list(instance.required_components), **verdict.to_json(),
        "parts": part_keys, "timing": {"llm_s": 0.0, "evaluation_s": 0.0, "total_s": timing["parts_wall_s"],
                                       **timing},
        "tokens": {"prompt": 0, "completion": 0}, "evaluator": EVALUATOR_VERSION,
    }


async def _run_agent_task(
    instance: TaskInstance, backend: Backend, catalog: Catalog, evaluator: Evaluator, settings: RunSettings,
    writer: RunWriter, selection: Selection, t0: float,
) -> dict[str, Any]:
    """The tool-calling agent: grade its first and its final program with the standard chain."""
    toolbox = Toolbox(instance, catalog, evaluator.limits, evaluator.pool)
    agent = await run_agent(backend, instance, catalog, selection, toolbox, template=settings.code_template,
                            max_rounds=settings.max_rounds, token_budget=settings.token_budget)
    t_llm = time.perf_counter() - t0
    selected = selection.names if selection.infrastructure_error is None else ()
    verdict, candidate, reference = await evaluator.evaluate(instance, agent.final_code, selected, agent.error)
    if agent.first_code == agent.final_code:  # answered at once, or never changed: same verdict
        first = verdict
    else:
        first, _, _ = await evaluator.evaluate(instance, agent.first_code, selected, agent.error)
    generation = _agent_generation(agent)
    t_total = time.perf_counter() - t0
    files = writer.save_programs(instance, agent.final_code)
    record = task_record(instance, selection, generation, verdict, candidate, reference,
                         {"llm_s": t_llm, "evaluation_s": t_total - t_llm, "total_s": t_total}, files)
    record["agent"] = _agent_block(agent, first)
    return record


def _agent_block(agent: AgentResult, first: Verdict) -> dict[str, Any]:
    """The agent's record: transcript, rounds, tools, and the verdict of its first program."""
    return {**agent.to_json(), "first_overall": first.overall, "first_failure": first.first_failure,
            "first_stages": [s.to_json() for s in first.stages]}


def _agent_generation(agent: AgentResult) -> Generation:
    """The agent's final answer in the shape of the two-step pipeline's generation record."""
    return Generation(prompt=agent.transcript[0]["content"], answer=agent.transcript[-1].get("content", ""),
                      code=agent.final_code, error=agent.error, infrastructure_error=agent.infrastructure_error,
                      meta={"completion_tokens": agent.completion_tokens, "prompt_tokens": agent.prompt_tokens,
                            "context_used": agent.prompt_tokens + agent.completion_tokens})


def _failed_record(instance: TaskInstance, exc: BaseException) -> dict[str, Any]:
    """A record for a task whose processing raised: recorded, never fatal to the run."""
    text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))[-3000:]
    return {
        "id": instance.task_id, "slug": instance.slug, "name": instance.name, "level": instance.level,
        "seed": instance.seed, "params": instance.params, "description": instance.description,
        "required_components": list(instance.required_components), "stages": [], "overall": False,
        "first_failure": "infrastructure", "error_categories": [],
        "infrastructure_error": f"pipeline error: {type(exc).__name__}: {exc}", "traceback": text,
        "timing": {"llm_s": 0.0, "evaluation_s": 0.0, "total_s": 0.0},
    }


async def run_benchmark(
    settings: RunSettings,
    registry: TaskRegistry | None = None,
    catalog: Catalog | None = None,
    backend: Backend | None = None,
) -> Path:
    """Run every selected task instance and write the run directory; returns run.json's path."""
    registry = registry or default_registry()
    catalog = catalog or rigid_catalog()
    models = registry.select(settings.levels, settings.only or None)
    if not models:
        raise ValueError(f"no task models for levels {settings.levels} / only {settings.only}")
    instances = registry.instances(models, settings.seed, settings.variations)
    started = time.time()
    stamp = dt.datetime.now().strftime("%Y%m%d-%H%M%S")
    run_dir = settings.out / (settings.run_name or f"{stamp}_{_safe_name(settings.llm.model)}")
    run_dir.mkdir(parents=True, exist_ok=True)
    writer = RunWriter(run_dir)
    if writer.finished and not settings.resume:
        raise ValueError(f"{run_dir} already holds a run; resume it with --resume {run_dir}")
    if not (run_dir / "settings.json").exists():
        _write_atomic(run_dir / "settings.json", json.dumps(settings.to_json(), indent=1))
    # the last record of a task wins; tasks that failed for infrastructure reasons are tried again
    latest = {record_key(r): r for r in writer.finished}
    done = {k: r for k, r in latest.items() if r.get("first_failure") != "infrastructure"}
    # parts of an unfinished assembly are made again with it
    records: list[dict[str, Any]] = [r for r in done.values() if not r.get("origin") or r["origin"] in done]
    todo = [i for i in instances if i.key not in done]
    own_backend = backend is None
    cache = ResponseCache(run_dir / "responses.jsonl")
    backend = CachedBackend(backend or make_backend(settings.llm), cache, settings.llm)
    if settings.executor not in ("fork", "subprocess"):
        raise ValueError(f"unknown executor {settings.executor!r} (fork or subprocess)")
    pool = WarmPool(child_env()) if settings.executor == "fork" else None
    evaluator = Evaluator(settings.workers, ExecutionLimits(timeout_s=settings.exec_timeout_s),
                          Tolerances(solution=settings.solution_tolerance), catalog, pool)
    # enough tasks in flight to fill every LLM slot and every worker, not the whole sweep at once
    window = asyncio.Semaphore(settings.llm.batch_size * max(1, len(settings.llm.hosts)) * 2 + settings.workers + 2)
    log_handler = _attach_run_log(run_dir / "log.jsonl")
    if pool is not None:
        pool_start = asyncio.ensure_future(pool.start())  # the fork server boots while the LLM works
    log.info("run started", run_dir=str(run_dir), tasks=len(instances), resumed=len(done), model=settings.llm.model)

    from meceng.progress import progress_bar

    t0 = time.perf_counter()
    with progress_bar(len(todo), f"{settings.llm.model}", enabled=settings.progress) as advance:

        async def one(instance: TaskInstance) -> None:
            async with window:
                try:
                    if instance.kind == "assembly":
                        produced = await run_assembly_task(instance, backend, evaluator, settings, writer)
                    else:
                        produced = [await run_task(instance, backend, catalog, evaluator, settings, writer)]
                except Exception as exc:
                    log.error("task failed", task=instance.key, error=str(exc))
                    produced = [_failed_record(instance, exc)]
            for record in produced:
                writer.append(record)
                records.append(record)
            record = produced[-1]
            log.info("task done", task=instance.key, overall=record["overall"],
                     first_failure=record["first_failure"])
            advance(record["overall"], sum(int(r.get("tokens", {}).get("completion", 0)) for r in produced))

        try:
            await asyncio.gather(*(one(i) for i in todo))
        finally:
            if pool is not None:
                await asyncio.gather(pool_start, return_exceptions=True)
                await pool.close()
            if own_backend:
                await backend.aclose()
            else:
                cache.close()
    order = {inst.key: k for k, inst in enumerate(instances)}
    # a part drawn for an assembly sits just before its assembly
    records.sort(key=lambda r: (order.get(r.get("origin") or record_key(r), 0), 0 if r.get("origin") else 1))
    extra = {"llm_calls": {"answered_from_cache": cache.hits, "requested": cache.misses},
             "resumed_tasks": len(done)}
    path = writer.finish(settings, records, started, time.perf_counter() - t0, extra)
    log.info("run finished", run_json=str(path))
    logging.getLogger("meceng").removeHandler(log_handler)
    log_handler.close()
    return path


def _attach_run_log(path: Path) -> logging.Handler:
    """JSON lines of this run's log events into the run folder, for as long as the run lasts."""
    handler = logging.FileHandler(path)
    handler.setFormatter(structlog.stdlib.ProcessorFormatter(
        processor=structlog.processors.JSONRenderer(),
        foreign_pre_chain=[structlog.processors.add_log_level, structlog.processors.TimeStamper(fmt="iso")]))
    logger = logging.getLogger("meceng")
    logger.addHandler(handler)
    if logger.level == logging.NOTSET or logger.level > logging.INFO:
        logger.setLevel(logging.INFO)
    return handler


async def evaluate_program(
    instance: TaskInstance,
    code: str,
    selected: tuple[str, ...] | None = None,
    catalog: Catalog | None = None,
    limits: ExecutionLimits | None = None,
) -> tuple[Verdict, Execution, Execution]:
    """Grade one program against the task instance, as if an LLM had written it."""
    catalog = catalog or rigid_catalog()
    evaluator = Evaluator(2, limits or ExecutionLimits(), Tolerances(), catalog)
    if instance.kind == "part":
        verdict, candidate, reference, _ = await evaluator.evaluate_part(instance, code, selected, None)
        return verdict, candidate, reference
    if instance.kind == "assembly":
        import tempfile

        with tempfile.TemporaryDirectory(prefix="meceng-parts-") as folder:
            files = await ground_truth_parts(instance, Path(folder), evaluator)
            return await evaluator.evaluate(instance, code, selected, None, files=files)
    return await evaluator.evaluate(instance, code, selected, None)


async def ground_truth_parts(instance: TaskInstance, folder: Path, evaluator: Evaluator) -> dict[str, Path]:
    """The assembly's parts made from their ground truths and saved as '<slot>.npz' in ``folder``
    (for grading an assembly program outside a run, where no LLM made the parts)."""

    async def one(slot: str, part: TaskInstance) -> tuple[str, Path]:
        path = folder / f"{slot}.npz"
        run = await evaluator._execute_part(part.reference_program, part, check=False, save_to=path)
        if run.fem_file is None:
            raise RuntimeError(f"ground-truth part {part.key} failed: {run.error}")
        return f"{slot}.npz", path

    return dict(await asyncio.gather(*(one(slot, part) for slot, part in instance.parts)))


async def rescore(run_dir: Path, registry: TaskRegistry | None = None, catalog: Catalog | None = None,
                  workers: int = max(1, os.cpu_count() or 1)) -> Path:
    """Grade the saved programs of a run again with the current evaluator; no LLM is called.

    The LLM answers (selection, generation) stay as they were; stages, verdict, categories and
    the summary are recomputed and the record says which evaluator graded it. run.json is
    replaced atomically; the previous one is kept as run.previous.json.
    """
    registry = registry or default_registry()
    catalog = catalog or rigid_catalog()
    run_path = run_dir / "run.json"
    run = json.loads(run_path.read_text())
    evaluator = Evaluator(workers, ExecutionLimits(timeout_s=run["settings"]["pipeline"]["exec_timeout_s"]),
                          Tolerances(solution=run["settings"]["pipeline"]["solution_tolerance"]), catalog)

    def instance_of(record: dict[str, Any]) -> TaskInstance:
        if record.get("origin"):  # a part drawn for an assembly: with the assembly's master values
            slug, seed = record["origin"].rsplit("@", 1)
            assembly = registry.get(slug).instance(int(seed))
            return next(part for _, part in assembly.parts if part.key == record_key(record))
        return registry.get(record["slug"]).instance(record["seed"])

    async def one(record: dict[str, Any]) -> dict[str, Any]:
        if record.get("first_failure") == "infrastructure" or "generation" not in record:
            return record  # also an assembly that never started: nothing was generated
        instance = instance_of(record)
        generation = record["generation"]
        selected = tuple(record["selection"].get("names", ()))
        if instance.kind == "part":
            verdict, candidate, reference, _ = await evaluator.evaluate_part(
                instance, generation.get("code"), selected, generation.get("error"))
        elif instance.kind == "assembly":
            parts = {r["origin"] + "/" + f"{r['slug']}@{r['seed']}": r for r in run["tasks"] if r.get("origin")}
            files = {f"{slot}.npz": run_dir / parts[part.key]["files"]["part"] for slot, part in instance.parts}
            chain, candidate, reference = await evaluator.evaluate(
                instance, generation.get("code"), selected, generation.get("error"), files=files)
            verdict = Verdict((*(StageResult(**s) for s in record["stages"][:2]), *chain.stages),
                              chain.error_categories, chain.differences, chain.solution_norm,
                              chain.infrastructure_error)
        else:
            verdict, candidate, reference = await evaluator.evaluate(
                instance, generation.get("code"), selected, generation.get("error"))
        updated = {**record, **verdict.to_json(), "execution": candidate.summary(),
                   "reference_execution": reference.summary(), "evaluator": EVALUATOR_VERSION}
        return updated

    records = await asyncio.gather(*(one(r) for r in run["tasks"]))
    run["tasks"] = list(records)
    run["summary"] = summarize(run["tasks"])
    run["rescored"] = {"evaluator": EVALUATOR_VERSION, "at": dt.datetime.now(dt.UTC).isoformat()}
    os.replace(run_path, run_dir / "run.previous.json")
    _write_atomic(run_path, json.dumps(run, indent=1, default=str))
    return run_path
