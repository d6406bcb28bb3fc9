"""The evaluation service: runs candidate and reference programs in isolation and grades them.

Executions are bounded by ``workers`` slots (the fork server's children or cold interpreters).
A ground truth runs once per task instance and is shared by everyone who asks for it, started
as early as possible so it runs while the model is still answering.
"""

from __future__ import annotations

import asyncio
import os
import re
import time
from collections.abc import Awaitable, Callable
from dataclasses import replace
from pathlib import Path
from typing import Any, Generic, TypeVar

import numpy as np

from meceng.catalog.catalogs import assembly_catalog, part_catalog, rigid_catalog
from meceng.catalog.component import Catalog
from meceng.eval.behaviour import BehaviourTolerance, tolerance_for
from meceng.eval.chain import Tolerances, Verdict, by_behaviour, evaluate_rigid
from meceng.eval.convergence import ASSEMBLY_CAP, ConvergedRuns
from meceng.eval.parts import evaluate_part, load_mesh_library, minimum_maxh, part_data
from meceng.tasks.base import TaskInstance
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import execute
from meceng.tools.meshcheck import check_mesh_size
from meceng.tools.recording import MOTION_SAMPLES, REFINE, recording
from meceng.tools.warm import WarmPool

from .converged import SLIM, ConvergedTruth, at_steps, candidate_runs, fact_variant, find_convergence, from_fact, slim
from .grading import GradingPool, offload
from .store import ReferenceStore, reference_key

T = TypeVar("T")


class ReferenceCache(Generic[T]):
    """Ground-truth executions (or what is found from them), run once per task instance and shared
    by everyone who asks."""

    def __init__(self, run: Callable[[TaskInstance], Awaitable[T]]) -> None:
        self._run = run
        self._tasks: dict[str, asyncio.Task[T]] = {}

    def start(self, instance: TaskInstance) -> asyncio.Task[T]:
        task = self._tasks.get(instance.key)
        if task is None:
            task = asyncio.ensure_future(self._run(instance))
            self._tasks[instance.key] = task
        return task

    async def get(self, instance: TaskInstance) -> T:
        return await asyncio.shield(self.start(instance))

    def discard(self, key: str) -> None:
        """Forget an instance's execution once its task is done: a reference holds the whole
        system and trajectory (a 1000-task run kept ~300 MB of them to the end). One still running
        is cancelled (its task was lost to the server before grading): nobody will read it, and
        left alone it would outlive the run and its fork server."""
        _cancel(self._tasks.pop(key, None))


def _cancel(task: asyncio.Task[Any] | None) -> None:
    if task is not None and not task.done():
        task.cancel()


def refined(instance: TaskInstance) -> TaskInstance:
    """The instance simulated with twice the steps (the behaviour verdict's step-error run)."""
    return at_steps(instance, REFINE)


def not_run(code_error: str | None) -> Execution:
    """The candidate 'execution' of an answer that had no program to run."""
    return Execution(stage="no_code", error=code_error or "no program", error_kind="no_code")


class Evaluator:
    """Runs candidate and reference programs in isolation (bounded by ``workers``) and grades."""

    def __init__(self, workers: int, limits: ExecutionLimits, tolerances: Tolerances, catalog: Catalog | None = None,
                 pool: WarmPool | None = None, parts: Catalog | None = None,
                 part_timeout_s: float = 300.0, slots: asyncio.Semaphore | None = None,
                 store: ReferenceStore | None = None, grading: GradingPool | None = None) -> None:
        self.slots = slots or asyncio.Semaphore(workers)  # a sweep's runs share one set of slots
        self.pool = pool
        self.store = store
        self.grading = grading  # where grading and traces run (None: a thread of this process)
        self.limits = limits
        self.tolerances = tolerances
        self.catalog = catalog or rigid_catalog()
        self.part_catalog = parts or part_catalog()
        self.assembly_catalog = assembly_catalog()
        self.part_limits = replace(limits, mode="part", timeout_s=max(limits.timeout_s, part_timeout_s))
        self.references: ReferenceCache[Execution] = ReferenceCache(self._run_reference)
        # the ground truth again with twice the steps (its own time-stepping error, which the behaviour
        # verdict allows a program built another way), and where that binds with 4, 8, ... x the steps
        # until it does not: the step count behaviour compares at (levels 1-2 and 3b; pipeline/converged.py)
        self.converged: ReferenceCache[ConvergedTruth] = ReferenceCache(self._run_converged)
        self._remeshed: dict[tuple[str, float], asyncio.Task[Execution]] = {}

    def catalog_for(self, instance: TaskInstance) -> Catalog:
        return {"part": self.part_catalog, "assembly": self.assembly_catalog}.get(instance.kind, self.catalog)

    def limits_for(self, instance: TaskInstance) -> ExecutionLimits:
        return self.part_limits if instance.kind == "part" else self.limits

    def release(self, instance: TaskInstance) -> None:
        """The task is graded: its ground-truth executions are not needed again in this run."""
        self.references.discard(instance.key)
        self.converged.discard(instance.key)
        for key in [k for k in self._remeshed if k[0] == instance.key]:
            _cancel(self._remeshed.pop(key))

    def prefetch(self, instance: TaskInstance) -> None:
        """Start the reference execution now, while the LLM is still busy with this task (a design
        task's reference is built with the answer's values: nothing to start before it)."""
        # an assembly's reference needs the parts the LLM makes first
        if instance.kind != "assembly" and instance.design is None:
            self.references.start(instance)
            if instance.kind == "rigid":
                self.converged.start(instance)

    def graded_limits(self, instance: TaskInstance) -> ExecutionLimits:
        """The limits a graded level 1-2/3b program runs under: the states at t = 0 and at the end
        (the viewer's pictures of the system) and every body's motion on a grid (the behaviour
        verdict); reading them does not touch the solution."""
        return recording(replace(self.limits, inspect_times=(instance.sim.end_time,)), instance.sim.end_time,
                         MOTION_SAMPLES)

    async def execute(self, program: str, instance: TaskInstance, check: bool,
                      files: dict[str, Path] | None = None) -> Execution:
        limits = self.graded_limits(instance)
        return await execute(program, instance.sim.block(), limits, check=check, pool=self.pool, files=files,
                             slots=self.slots)

    async def execute_part(self, program: str, instance: TaskInstance, check: bool,
                           save_to: Path | None = None) -> Execution:
        limits = replace(self.part_limits, n_modes=instance.part.n_modes,
                         save_fem_to=str(save_to) if save_to is not None else None)
        return await execute(program, "", limits, check=check, pool=self.pool, slots=self.slots)

    async def run_motion(self, program: str, instance: TaskInstance, check: bool,
                         files: dict[str, Path] | None = None) -> Execution:
        """A run for behaviour only (a converged run): its motion and outcome (``converged.slim``)."""
        limits = recording(self.limits, instance.sim.end_time, MOTION_SAMPLES)
        return slim(await execute(program, instance.sim.block(), limits, check=check, pool=self.pool, files=files,
                                  slots=self.slots))

    async def _run_converged(self, instance: TaskInstance) -> ConvergedTruth:
        return await self.convergence(instance, instance.reference_program, lambda: self.references.get(instance))

    async def convergence(self, instance: TaskInstance, program: str, nominal: Callable[[], Awaitable[Execution]],
                          tolerance: BehaviourTolerance | None = None, files: dict[str, Path] | None = None
                          ) -> ConvergedTruth:
        """The step count behaviour compares ``program`` (a ground truth) at, and its runs there
        (``pipeline/converged.py``); ``nominal``: its graded run, shared with the caller. With a
        store (and no parts to load) every run and R itself are kept there."""
        tol = tolerance or tolerance_for(instance.slug)
        limits = recording(self.limits, instance.sim.end_time, MOTION_SAMPLES)

        async def run_at(factor: int) -> Execution:
            if factor == 1:
                return await nominal()
            scaled = at_steps(instance, factor)
            if self.store is None or files:
                return await self.run_motion(program, scaled, check=False, files=files)
            key = reference_key(program, scaled.sim.block(), limits, variant=SLIM)
            return await self.store.fetch(key, lambda: self.run_motion(program, scaled, check=False))

        if files:  # the model's parts: run for this task alone, so a lower bound (ASSEMBLY_CAP)
            return await find_convergence(run_at, instance.sim.steps, tol, ASSEMBLY_CAP)
        if self.store is None:
            return await find_convergence(run_at, instance.sim.steps, tol)
        key = reference_key(program, instance.sim.block(), limits, variant=fact_variant(tol))
        fact = await asyncio.to_thread(self.store.fact, key)
        if fact is not None:
            return await from_fact(run_at, fact, instance.sim.steps)
        found = await find_convergence(run_at, instance.sim.steps, tol)
        if found.complete:
            await asyncio.to_thread(self.store.put_fact, key, found.convergence.to_json())
        return found

    async def converged_runs(self, code: str | None, instance: TaskInstance, candidate: Execution,
                             truth: ConvergedTruth, files: dict[str, Path] | None = None) -> ConvergedRuns:
        """The motions behaviour compares (the candidate again at R x the steps when R > 1)."""

        async def again(factor: int) -> Execution:
            assert code is not None  # a candidate without a program never solved: not run again
            return await self.run_motion(code, at_steps(instance, factor), check=True, files=files)

        return await candidate_runs(again, candidate, truth)

    async def _run_reference(self, instance: TaskInstance) -> Execution:
        return await self.ground_truth(instance, instance.reference_program)

    async def ground_truth(self, instance: TaskInstance, program: str) -> Execution:
        """A ground-truth execution: from the reference store when there is one, else run here."""

        async def run() -> Execution:
            if instance.kind == "part":
                return await self.execute_part(program, instance, check=False)
            return await self.execute(program, instance, check=False)

        if self.store is None:
            return await run()
        if instance.kind == "part":
            limits = replace(self.part_limits, n_modes=instance.part.n_modes)
        else:
            limits = self.graded_limits(instance)
        sim = "" if instance.kind == "part" else instance.sim.block()
        return await self.store.fetch(reference_key(program, sim, limits), run)

    async def _reference_at(self, instance: TaskInstance, maxh: float) -> Execution:
        """The ground-truth part meshed with another maxh (run once per instance and size)."""
        key = (instance.key, maxh)
        if key not in self._remeshed:
            program = re.sub(r"GenerateMesh\(maxh=[^)]*\)", f"GenerateMesh(maxh={maxh!r})", instance.reference_program)
            self._remeshed[key] = asyncio.ensure_future(self.ground_truth(instance, program))
        return await asyncio.shield(self._remeshed[key])

    async def evaluate(
        self, instance: TaskInstance, code: str | None, selected: tuple[str, ...] | None, code_error: str | None,
        files: dict[str, Path] | None = None,
    ) -> tuple[Verdict, Execution, Execution]:
        """Run candidate and reference, grade with the level 1-2 chain (an open-text task: by
        behaviour, ``eval.chain.by_behaviour``). ``files``: the parts an assembly loads; both
        programs get the same ones (the reference is then run uncached)."""
        if files:
            reference_task = asyncio.ensure_future(
                self.execute(instance.reference_program, instance, check=False, files=files))
            truth_task = asyncio.ensure_future(self.convergence(
                instance, instance.reference_program, lambda: asyncio.shield(reference_task), files=files))
        else:
            reference_task = asyncio.ensure_future(self.references.get(instance))
            truth_task = asyncio.ensure_future(self.converged.get(instance))
        candidate = not_run(code_error) if code is None else await self.execute(code, instance, check=True, files=files)
        reference = await reference_task
        converged = await self.converged_runs(code, instance, candidate, await truth_task, files)
        # off the event loop and off this process: graph isomorphism and trajectory resampling take
        # ~10 ms a task, during which no LLM answer would be read, and they scale with the cores
        verdict = await offload(
            self.grading, evaluate_rigid, candidate, reference, end_time=instance.sim.end_time,
            steps=instance.sim.steps, selected=selected, required=instance.required_components,
            dependencies=self.catalog_for(instance).dependency_map(), tolerances=self.tolerances,
            behaviour=tolerance_for(instance.slug), converged=converged,
        )
        if instance.texts == "open":  # an engineer's words leave the writing free: graded by behaviour
            verdict = by_behaviour(verdict)
        return verdict, candidate, reference

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
            candidate = not_run(code_error)
        else:
            mesh_check = check_mesh_size(code, minimum)
            facts.update(maxh=list(mesh_check.maxh), maxh_raised=mesh_check.raised)
            if mesh_check.code is None:
                candidate = Execution(stage="flagged", error=mesh_check.error, error_kind="mesh_size")
            else:
                candidate = await self.execute_part(mesh_check.code, instance, check=True, save_to=pending)
        if candidate.lost_to_machine:  # stopped by the wall clock, under the CPU limit: not graded
            if pending is not None:
                pending.unlink(missing_ok=True)
            return Verdict((), infrastructure_error=f"part not graded: {candidate.error}"), candidate, reference, facts
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
        if self.grading is None:
            load_mesh_library()  # on the loop's thread, before the metrics' worker thread uses it
        t0 = time.perf_counter()
        stages = await offload(
            self.grading, evaluate_part, produced, truth, selected=selected, required=instance.required_components,
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

    async def ground_truth_parts(self, instance: TaskInstance, folder: Path) -> dict[str, Path]:
        """The assembly's parts made from their ground truths and saved as '<slot>.npz' in ``folder``
        (for grading an assembly program outside a run, where no LLM made the parts)."""

        async def one(slot: str, part: TaskInstance) -> tuple[str, Path]:
            path = folder / f"{slot}.npz"
            run = await self.execute_part(part.reference_program, part, check=False, save_to=path)
            if run.fem_file is None:
                raise RuntimeError(f"ground-truth part {part.key} failed: {run.error}")
            return f"{slot}.npz", path

        return dict(await asyncio.gather(*(one(slot, part) for slot, part in instance.parts)))
