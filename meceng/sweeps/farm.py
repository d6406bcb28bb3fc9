"""A sweep's runs at the same time, each as soon as its servers are free.

Grid points one after another leave every server but one waiting (two models on two servers took
1.97x one model's time). Here every run goes as soon as its servers can take it:

- runs are grouped by the servers they use (two runs sharing any host are in one group); groups
  run side by side, one group's runs share each server's slots (never more requests in flight
  than its slots) and are served in sweep order, so a later run only fills the slots an earlier
  one leaves free;
- inside a group the runs of one model go together: the next run of the same model starts once
  the group's servers have had free slots nobody waited for (the earlier run is in its tail); a
  run of another model waits until the group's runs are done (no model swaps on Ollama);
- the program executions of all runs share one worker pool sized to the machine, one fork server
  and the reference store;
- one live display: a row per run (progress, what it waits on) and the sweep's done/ETA.

Every run writes its own folder exactly as alone (journal fsynced per task, lock, run.json), so
Ctrl-C or a kill leaves each one resumable and a rerun of the sweep does only what is missing.
"""

from __future__ import annotations

import asyncio
import contextlib
import functools
import time
from collections.abc import Iterator
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

from meceng.llm.ensemble import EnsembleBackend
from meceng.llm.factory import make_backend
from meceng.llm.scheduler import EndpointBackend, PrioritySlots
from meceng.llm.types import LOCAL_BACKENDS, Backend, LLMSettings
from meceng.logs import get_logger
from meceng.pipeline import RunSettings, run_benchmark
from meceng.pipeline.grading import grading_pool
from meceng.pipeline.lock import RunBusy
from meceng.pipeline.preflight import ensure_sweep_stack
from meceng.pipeline.services import SharedServices
from meceng.pipeline.store import ReferenceStore
from meceng.progress import Advance, live_display_enabled
from meceng.sweeps.spec import GridPoint
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

log = get_logger(__name__)

POLL_S = 0.25
IDLE_POLLS = 4  # a server seen with free, unclaimed slots this many polls in a row is in a tail
SERVERLESS_RUNS = 2  # gold runs (no server) at the same time: they only compete for workers


@dataclass(frozen=True)
class SweepJob:
    """One run of the sweep: its settings and where it sits in the sweep's order."""

    name: str
    model: str
    settings: RunSettings
    planned_tasks: int
    point: GridPoint | None = None  # the sweep's grid point it runs, when it came from a spec

    @property
    def models(self) -> tuple[str, ...]:
        """The models this run asks: a consensus run across models asks each of its members."""
        return tuple(dict.fromkeys(llm.model for llm in self.settings.sample_models))

    @property
    def hosts(self) -> tuple[str, ...]:
        """The servers this run uses, every model's (a consensus run across models uses each member's
        servers). A hosted API is a server per model (its limits are per model and it swaps nothing):
        two models on api.openai.com go side by side, not one after another."""
        return tuple(dict.fromkeys(key for llm in self.settings.sample_models for key in _servers(llm)))

    def slots(self, servers: dict[str, PrioritySlots], llm: LLMSettings | None = None) -> dict[str, PrioritySlots]:
        """One model's endpoints (by host; the run's model unless ``llm``) to the sweep's slots of each server."""
        llm = llm or self.settings.llm
        return {h.rstrip("/"): servers.setdefault(key, PrioritySlots(llm.batch_size))
                for h, key in zip(llm.hosts, _servers(llm), strict=True)}


def _servers(llm: LLMSettings) -> tuple[str, ...]:
    """The sweep's name of each server a model is asked on (a hosted API: one per model)."""
    if llm.backend in LOCAL_BACKENDS:
        return ()
    hosted = llm.backend == "anthropic" or any("api.openai.com" in h for h in llm.hosts)
    return tuple(h.rstrip("/") + (f"#{llm.model}" if hosted else "") for h in llm.hosts)


def server_groups(jobs: list[SweepJob]) -> list[list[SweepJob]]:
    """Runs that share any server, transitively, in one group; gold runs (no server) in one group
    of their own. Inside a group: sweep order, with each model's runs moved together."""
    parent: dict[str, str] = {}

    def find(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    for job in jobs:
        roots = [find(h) for h in job.hosts]
        for other in roots[1:]:
            parent[other] = roots[0]
    groups: dict[str, list[SweepJob]] = {}
    for job in jobs:
        groups.setdefault(find(job.hosts[0]) if job.hosts else "", []).append(job)
    ordered = []
    for members in groups.values():
        first = {m.models: k for k, m in reversed(list(enumerate(members)))}
        ordered.append(sorted(members, key=lambda m: first[m.models]))  # stable: sweep order per model
    return ordered


@dataclass
class SweepDisplay:
    """The sweep's one live display: an overall row and one row per run."""

    jobs: list[SweepJob]
    enabled: bool = True
    _progress: Progress | None = None
    _rows: dict[str, Any] = field(default_factory=dict)
    _overall: Any = None
    _passed: dict[str, int] = field(default_factory=dict)

    @contextlib.contextmanager
    def live(self) -> Iterator[SweepDisplay]:
        if not self.enabled or not live_display_enabled():
            yield self
            return
        with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                      TextColumn("{task.fields[status]}"), TimeElapsedColumn(), TextColumn("eta"),
                      TimeRemainingColumn()) as progress:
            self._progress = progress
            total = sum(job.planned_tasks for job in self.jobs)
            self._overall = progress.add_task("[bold]sweep", total=total, status=f"{len(self.jobs)} runs")
            for job in self.jobs:
                self._rows[job.name] = progress.add_task(job.name, total=job.planned_tasks, status="planned",
                                                         start=False)
            try:
                yield self
            finally:
                self._progress = None

    def status(self, job: SweepJob, text: str) -> None:
        log.info("sweep run", run=job.name, status=text)
        if self._progress is not None:
            self._progress.update(self._rows[job.name], status=text)

    def finished(self, job: SweepJob, text: str, remaining: int) -> None:
        """A run is over (done, skipped, failed): the overall total loses what it will not do."""
        self.status(job, text)
        if self._progress is not None and remaining:
            row = self._progress.tasks[self._overall]
            self._progress.update(self._overall, total=(row.total or 0) - remaining)

    @contextlib.contextmanager
    def run_rows(self, job: SweepJob, total: int, title: str) -> Iterator[Advance]:
        """The ``progress`` a run gets instead of its own bar (see ``ProgressFactory``)."""
        progress = self._progress
        if progress is not None:
            row = self._rows[job.name]
            progress.start_task(row)
            overall = progress.tasks[self._overall]
            progress.update(self._overall, total=(overall.total or 0) - job.planned_tasks + total)
            progress.update(row, total=total, completed=0, status="running")
        self._passed[job.name] = 0

        def advance(success: bool, tokens: int = 0) -> None:
            self._passed[job.name] += int(bool(success))
            if progress is not None:
                progress.update(row, advance=1, status=f"ok {self._passed[job.name]}")
                progress.update(self._overall, advance=1)

        yield advance


@dataclass
class _Group:
    """One group's servers, as the sweep watches them to decide when the next run may start."""

    slots: dict[str, PrioritySlots]
    hosts: tuple[str, ...]
    idle_polls: int = 0

    def idle(self) -> bool:
        """Every server of the group has a free slot nobody waits for."""
        slots = [self.slots[h] for h in self.hosts if h in self.slots]
        return bool(slots) and all(s.free > 0 and s.waiting == 0 for s in slots)


async def run_sweep(jobs: list[SweepJob], workers: int, executor: str = "fork", store: Path | None = None,
                    display: bool = True) -> list[dict[str, Any]]:
    """Run the sweep's jobs concurrently; one result per job, in the jobs' order."""
    pool = WarmPool(child_env()) if executor == "fork" else None
    grading = grading_pool(workers)
    shared = SharedServices(asyncio.Semaphore(workers), pool, ReferenceStore(store) if store else None, grading)
    servers: dict[str, PrioritySlots] = {}
    results: dict[str, dict[str, Any]] = {}
    rank = {job.name: k for k, job in enumerate(jobs)}
    screen = SweepDisplay(jobs, display)
    t0 = time.perf_counter()
    warming: asyncio.Future[None] | None = None
    with screen.live():
        try:
            if grading is not None:
                warming = asyncio.ensure_future(grading.warm())  # boots while the first runs start
            # once for the sweep, before any run asks a server: a stack that cannot grade stops it here
            await ensure_sweep_stack([job.settings for job in jobs], pool, shared.workers)
            groups = server_groups(jobs)
            await asyncio.gather(*(_drive(group, shared, servers, rank, screen, results) for group in groups))
        finally:
            if pool is not None:
                await pool.close()
            if warming is not None:
                await asyncio.gather(warming, return_exceptions=True)
            if grading is not None:
                await asyncio.to_thread(grading.close)
    log.info("sweep finished", runs=len(jobs), wall_s=time.perf_counter() - t0,
             references_made=shared.store.made if shared.store else None,
             references_reused=shared.store.hits if shared.store else None)
    return [results[job.name] for job in jobs]


async def _drive(group: list[SweepJob], shared: SharedServices, servers: dict[str, PrioritySlots],
                 rank: dict[str, int], screen: SweepDisplay, results: dict[str, dict[str, Any]]) -> None:
    """Start the group's runs one after another as the servers allow; wait for all of them."""
    watch = _Group(servers, tuple(dict.fromkeys(h for job in group for h in job.hosts)))
    running: dict[asyncio.Task[None], SweepJob] = {}
    try:
        for job in group:
            reason = _blocked(job, running, watch)
            while reason is not None:
                screen.status(job, reason)
                done, _ = await asyncio.wait(running, timeout=POLL_S)
                for task in done:
                    running.pop(task)
                watch.idle_polls = watch.idle_polls + 1 if watch.idle() else 0
                reason = _blocked(job, running, watch)
            watch.idle_polls = 0
            running[asyncio.ensure_future(_one(job, shared, servers, rank[job.name], screen, results))] = job
        await asyncio.gather(*running)
    finally:
        for task in running:
            task.cancel()
        await asyncio.gather(*running, return_exceptions=True)


def _backend(job: SweepJob, settings: RunSettings, servers: dict[str, PrioritySlots], rank: int
             ) -> Backend | None:
    """The run's backend with the sweep's slots of every server it asks: a consensus run across
    models gets one backend per model, each on its servers' shared slots. None where the run makes
    its own (a scripted model needs the run's task instances: pipeline/run.py)."""
    models = settings.sample_models
    if any(llm.backend == "scripted" for llm in models):
        return None
    members = []
    for llm in models:
        backend = make_backend(llm)
        if isinstance(backend, EndpointBackend):
            backend.share_slots(job.slots(servers, llm), rank)
        members.append((llm, backend))
    return EnsembleBackend(members) if len(members) > 1 else members[0][1]


def _blocked(job: SweepJob, running: dict[asyncio.Task[None], SweepJob], watch: _Group) -> str | None:
    """Why ``job`` may not start yet (None: it may)."""
    if not running:
        return None
    others = list(running.values())
    if not job.hosts:
        return None if len(others) < SERVERLESS_RUNS else f"waits for {others[0].name} (workers)"
    other_model = next((o for o in others if o.models != job.models), None)
    if other_model is not None:
        return f"waits for {other_model.name} (another model on {', '.join(job.hosts)})"
    if watch.idle_polls < IDLE_POLLS:
        return f"waits for {others[-1].name} (server {', '.join(job.hosts)} busy)"
    return None


async def _one(job: SweepJob, shared: SharedServices, servers: dict[str, PrioritySlots], rank: int,
               screen: SweepDisplay, results: dict[str, dict[str, Any]]) -> None:
    """One run with the sweep's services; its failure is its result, never the sweep's end."""
    run_dir = job.settings.out / job.name
    if (run_dir / "run.json").exists():
        results[job.name] = {"run": str(run_dir / "run.json"), "skipped": True}
        screen.finished(job, "finished earlier", job.planned_tasks)
        return
    settings = job.settings
    if (run_dir / "journal.jsonl").exists() and not settings.resume:
        settings = replace(settings, resume=True)
    screen.status(job, "starting")
    backend = None
    try:
        backend = _backend(job, settings, servers, rank)
        path = await run_benchmark(settings, backend=backend, shared=shared,
                                   progress=functools.partial(screen.run_rows, job))
    except RunBusy as exc:
        results[job.name] = {"run": str(run_dir), "busy": str(exc)}
        screen.finished(job, "busy in another process", job.planned_tasks)
    except Exception as exc:  # one grid point never ends the sweep
        log.error("run failed", run=job.name, error=str(exc))
        results[job.name] = {"run": str(run_dir), "error": str(exc)}
        screen.finished(job, f"failed: {exc}", 0)
    else:
        results[job.name] = {"run": str(path)}
        screen.finished(job, "done", 0)
    finally:
        if backend is not None:
            await backend.aclose()
