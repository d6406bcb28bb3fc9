"""The run loop: every selected task instance through its flow, concurrently, into the run folder.

The instances run as coroutines inside a window: LLM calls are bounded per endpoint by the
backend's scheduler and executions by the evaluator's worker slots, so inference of one task
overlaps the evaluation of another and a run costs about max(LLM time, evaluation time). Every
finished task is appended to the journal at once; one task's failure is recorded and never stops
the run; ``--resume`` keeps what finished and does the rest (and what the server lost) again.
"""

from __future__ import annotations

import asyncio
import datetime as dt
import json
import logging
import time
from contextlib import AbstractContextManager
from pathlib import Path
from typing import Any

from meceng.eval.chain import Tolerances
from meceng.llm.cache import CachedBackend, ResponseCache
from meceng.llm.ensemble import EnsembleBackend
from meceng.llm.factory import make_backend
from meceng.llm.types import LOCAL_BACKENDS, Backend, LLMSettings
from meceng.logs import get_logger
from meceng.progress import Advance
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import TaskRegistry, default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

from .drafts import repair_instances
from .evaluation import Evaluator
from .flow import FlowContext, run_instance
from .grading import grading_pool
from .lock import HEARTBEAT_S, RunLock
from .preflight import ensure_stack
from .records import failed_record
from .rundir import RunWriter, attach_run_log, record_key, safe_name, slim_record, write_atomic
from .scripted import scripted_backend
from .services import ProgressFactory, SharedServices
from .settings import RunSettings

log = get_logger("meceng.pipeline")


def resumable(finished: list[dict[str, Any]], retry_overflow: bool = False) -> dict[str, dict[str, Any]]:
    """The records a resumed run keeps, by instance key: the last record of a task wins; tasks
    lost to infrastructure are done again, and so are the parts of an assembly that is. A prompt
    that did not fit the server's context is kept (that server would refuse it again) unless
    ``retry_overflow``: the run resumes on a server the user named."""
    latest = {record_key(r): r for r in finished}
    done = {k: r for k, r in latest.items() if r.get("first_failure") != "infrastructure"
            or (r.get("context_exceeded") and not retry_overflow)}
    return {k: r for k, r in done.items() if not r.get("origin") or r["origin"] in done}


async def run_benchmark(
    settings: RunSettings,
    registry: TaskRegistry | None = None,
    backend: Backend | None = None,
    shared: SharedServices | None = None,
    progress: ProgressFactory | None = None,
) -> Path:
    """Run every selected task instance and write the run directory; returns run.json's path.

    ``shared``: the worker slots, fork server and reference store of a sweep whose runs go at the
    same time (the sweep owns them); ``progress``: the sweep's display instead of this run's bar.
    """
    registry = registry or default_registry()
    models = registry.select(settings.levels, settings.only or None)
    if not models:
        raise ValueError(f"no task models for levels {settings.levels} / only {settings.only}")
    if settings.executor not in ("fork", "subprocess"):
        raise ValueError(f"unknown executor {settings.executor!r} (fork or subprocess)")
    if settings.agent == "consensus" and not set(settings.levels) <= {"1", "2"}:
        raise ValueError("--agent consensus groups programs by their motion: levels 1 and 2 only")
    # open texts: only the models that have one; one named in --only that has none is refused
    models, without_text = registry.with_texts(models, settings.texts, settings.levels, settings.only)
    if without_text:
        log.warning("task models without an open text are left out of this run", texts=settings.texts,
                    left_out=without_text)
    instances = registry.instances(models, settings.seed, settings.variations, settings.texts)
    if settings.consensus_models and settings.agent != "consensus":
        raise ValueError("several models in one run (--consensus-models) are a consensus run: --agent consensus")
    own_backend = backend is None
    if backend is None and len(settings.consensus_models) > 1:  # sample k by model k mod M (llm/ensemble.py)
        backend = EnsembleBackend([(m, _backend(m, instances)) for m in settings.consensus_models])
    # a missing API key stops here, before any file is written
    backend = backend or _backend(settings.llm, instances)
    started = time.time()
    stamp = dt.datetime.now().strftime("%Y%m%d-%H%M%S")
    models = "+".join(m.model for m in settings.sample_models)  # a consensus run across models names them all
    run_dir = settings.out / (settings.run_name or f"{stamp}_{safe_name(models)}")
    run_dir.mkdir(parents=True, exist_ok=True)
    lock = RunLock(run_dir)
    lock.acquire()  # another process on this folder: RunBusy, nothing touched
    beat = asyncio.ensure_future(_heartbeat(lock))
    try:
        return await _run_in(run_dir, settings, instances, backend, own_backend, started, shared, progress,
                             without_text)
    finally:
        beat.cancel()
        lock.release()


def _backend(llm: LLMSettings, instances: list[TaskInstance]) -> Backend:
    """The backend of one model: the scripted one needs the run's instances (pipeline/scripted.py)."""
    return scripted_backend(llm, instances) if llm.backend == "scripted" else make_backend(llm)


async def _heartbeat(lock: RunLock) -> None:
    while True:
        await asyncio.sleep(HEARTBEAT_S)
        await asyncio.to_thread(lock.heartbeat)


async def _run_in(run_dir: Path, settings: RunSettings, instances: list[TaskInstance], backend: Backend,
                  own_backend: bool, started: float, shared: SharedServices | None,
                  progress: ProgressFactory | None, without_text: list[str] | None = None) -> Path:
    """The run itself, in a folder this process holds the lock of; ``without_text``: the selected
    models left out for want of the run's kind of text (said in run.json)."""
    writer = RunWriter(run_dir)
    if writer.finished and not settings.resume:
        raise ValueError(f"{run_dir} already holds a run; resume it with --resume {run_dir}")
    if not (run_dir / "settings.json").exists():
        write_atomic(run_dir / "settings.json", json.dumps(settings.to_json(), indent=1))
    kept = resumable(writer.finished, retry_overflow=settings.retry_overflow)
    records: list[dict[str, Any]] = [slim_record(r) for r in kept.values()]  # full records stay in the journal
    writer.finished = []
    done_keys = {k for k, r in kept.items() if not r.get("origin")}
    todo = [i for i in instances if i.key not in done_keys]
    cache = ResponseCache(run_dir / "responses.jsonl")
    if isinstance(backend, EnsembleBackend):  # each model's answers under its own keys
        backend = backend.wrapped(lambda inner, llm: CachedBackend(inner, cache, llm))
    else:
        backend = CachedBackend(backend, cache, settings.llm)
    own_pool = shared is None and settings.executor == "fork"
    pool = WarmPool(child_env()) if own_pool else (shared.pool if shared is not None else None)
    evaluator = Evaluator(settings.workers, ExecutionLimits(timeout_s=settings.exec_timeout_s),
                          Tolerances(solution=settings.solution_tolerance), pool=pool,
                          part_timeout_s=settings.part_timeout_s,
                          slots=shared.workers if shared is not None else None,
                          store=shared.store if shared is not None else None,
                          grading=shared.grading if shared is not None else grading_pool(settings.workers))
    # a stack that cannot grade stops here, before any LLM request (a gold run asks no server)
    if settings.preflight and todo and any(m.backend not in LOCAL_BACKENDS for m in settings.sample_models):
        try:
            await ensure_stack(todo, evaluator)
        except BaseException:
            if own_pool and pool is not None:
                await pool.close()
            if shared is None and evaluator.grading is not None:
                await asyncio.to_thread(evaluator.grading.close)
            if own_backend:
                await backend.aclose()
            raise
    if settings.agent == "repair":  # the tasks are the instances' failing drafts, graded before the first request
        instances = await repair_instances(instances, evaluator, settings.drafts_per_task)
        todo = [i for i in instances if i.key not in done_keys]
    ctx = FlowContext(backend, evaluator, settings, writer)
    # enough tasks in flight to fill every LLM slot and every worker, not the whole sweep at once
    window = asyncio.Semaphore(settings.llm.batch_size * max(1, len(settings.llm.hosts)) * 2 + settings.workers + 2)
    log_handler = attach_run_log(run_dir / "log.jsonl")
    if pool is not None:
        pool_start = asyncio.ensure_future(pool.start())  # the fork server boots while the LLM works
    if shared is None and evaluator.grading is not None:
        grading_start = asyncio.ensure_future(evaluator.grading.warm())  # so does the grading pool
    log.info("run started", run_dir=str(run_dir), tasks=len(instances), resumed=len(kept), model=settings.llm.model)

    if progress is None:
        from meceng.progress import progress_bar

        def progress(total: int, title: str) -> AbstractContextManager[Advance]:
            return progress_bar(total, title, enabled=settings.progress)

    t0 = time.perf_counter()
    with progress(len(todo), f"{settings.llm.model}") as advance:

        async def one(instance: TaskInstance) -> None:
            async with window:
                try:
                    produced = await run_instance(instance, ctx)
                except Exception as exc:
                    log.error("task failed", task=instance.key, error=str(exc))
                    produced = [failed_record(instance, exc)]
            for record in produced:
                await asyncio.to_thread(writer.append, record)  # JSON of a whole record and an fsync
                records.append(slim_record(record))
            record = produced[-1]
            log.info("task done", task=instance.key, overall=record["overall"],
                     first_failure=record["first_failure"])
            advance(record["overall"], sum(int(r.get("tokens", {}).get("completion", 0)) for r in produced))

        async def close_services() -> None:
            if pool is not None:
                await asyncio.gather(pool_start, return_exceptions=True)
            if own_pool and pool is not None:
                await pool.close()
            if shared is None and evaluator.grading is not None:
                await asyncio.gather(grading_start, return_exceptions=True)
                await asyncio.to_thread(evaluator.grading.close)
            if own_backend:
                await backend.aclose()
            else:
                cache.close()

        try:
            await asyncio.gather(*(one(i) for i in todo))
        except BaseException:
            await close_services()
            raise
    # the fork server and the HTTP sessions wind down while run.json is written
    closing = asyncio.ensure_future(close_services())
    order = {inst.key: k for k, inst in enumerate(instances)}
    # a part drawn for an assembly sits just before its assembly
    records.sort(key=lambda r: (order.get(r.get("origin") or record_key(r), 0), 0 if r.get("origin") else 1))
    extra = {"llm_calls": {"answered_from_cache": cache.hits, "requested": cache.misses},
             "resumed_tasks": len(kept), "texts": settings.texts,
             **({"without_text": without_text} if without_text else {})}
    try:
        path = await asyncio.to_thread(writer.finish, settings.to_json(), records, started,
                                       time.perf_counter() - t0, extra)
    finally:
        await closing
    log.info("run finished", run_json=str(path))
    logging.getLogger("meceng").removeHandler(log_handler)
    log_handler.close()
    return path
