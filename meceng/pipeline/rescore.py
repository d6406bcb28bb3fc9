"""Grading outside a run: one program (``meceng evaluate``) or a run's saved programs again
(``meceng rescore``), through the same task kinds as the flow, with no LLM call."""

from __future__ import annotations

import asyncio
import datetime as dt
import json
import os
import tempfile
from pathlib import Path
from typing import Any

from meceng.eval import EVALUATOR_VERSION
from meceng.eval.aggregate import summarize
from meceng.eval.chain import StageResult, Tolerances, Verdict
from meceng.progress import progress_bar
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import TaskRegistry, default_registry
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

from .evaluation import Evaluator
from .graded import Graded
from .grading import grading_pool as make_grading_pool
from .grading import offload
from .kinds import AssemblyKind, TaskKind, single_kind
from .preflight import ensure_stack
from .rundir import record_key, write_atomic
from .store import ReferenceStore
from .traces import save_traces


async def evaluate_program(
    instance: TaskInstance,
    code: str,
    selected: tuple[str, ...] | None = None,
    limits: ExecutionLimits | None = None,
) -> tuple[Verdict, Execution, Execution]:
    """Grade one program against the task instance, as if an LLM had written it. An assembly's
    parts are made from their ground truths first (outside a run no LLM made them)."""
    graded = await evaluate_graded(instance, code, selected, limits)
    return graded.verdict, graded.candidate, graded.reference


async def evaluate_graded(instance: TaskInstance, code: str, selected: tuple[str, ...] | None = None,
                          limits: ExecutionLimits | None = None) -> Graded:
    """``evaluate_program`` with what the task kind keeps beside the verdict (a design's outcome)."""
    evaluator = Evaluator(2, limits or ExecutionLimits(), Tolerances())
    if instance.kind == "assembly":
        with tempfile.TemporaryDirectory(prefix="meceng-parts-") as folder:
            files = await evaluator.ground_truth_parts(instance, Path(folder))
            return Graded(*await evaluator.evaluate(instance, code, selected, None, files=files))
    # no components given: not applicable
    return await single_kind(instance, evaluator).grade(instance, code, selected, None, keep=False)


async def rescore(run_dir: Path, registry: TaskRegistry | None = None,
                  workers: int = max(1, os.cpu_count() or 1), grading_pool: bool = True,
                  executor: str = "fork", store: Path | None = None, progress: bool = False) -> Path:
    """Grade the saved programs of a run again with the current evaluator; no LLM is called.

    The LLM answers (selection, generation) stay as they were; stages, verdict, categories and
    the summary are recomputed and the record says which evaluator graded it. run.json is
    replaced atomically; the previous one is kept as run.previous.json.

    Programs run in children of the warm fork server (``executor="subprocess"``: a cold
    interpreter each, ~0.1 s more a program), ground truths come from the reference ``store`` when
    one is given (a sweep's), and grading runs in a pool of ``workers`` processes
    (``grading_pool=False``: on threads of this process).
    """
    registry = registry or default_registry()
    run_path = run_dir / "run.json"
    run = json.loads(run_path.read_text())
    pipeline = run["settings"]["pipeline"]
    grading = make_grading_pool(workers) if grading_pool else None  # grading on every core, not on the parent's one
    pool = WarmPool(child_env()) if executor == "fork" else None
    evaluator = Evaluator(workers, ExecutionLimits(timeout_s=pipeline["exec_timeout_s"]),
                          Tolerances(solution=pipeline["solution_tolerance"]), pool=pool,
                          part_timeout_s=pipeline.get("part_timeout_s", 300.0), grading=grading,
                          store=ReferenceStore(store) if store is not None else None)
    saved_parts = {record_key(r): r for r in run["tasks"] if r.get("origin")}

    def instance_of(record: dict[str, Any]) -> TaskInstance:
        if record.get("origin"):  # a part drawn for an assembly: with the assembly's master values
            slug, seed = record["origin"].rsplit("@", 1)
            assembly = registry.get(slug).instance(int(seed))
            return next(part for _, part in assembly.parts if part.key == record_key(record))
        # the text the task had (records before issue 36 say none: the paper's)
        return registry.instance_of(registry.get(record["slug"]), record["seed"], record.get("texts", "paper"))

    def kind_of(instance: TaskInstance, record: dict[str, Any]) -> TaskKind:
        if instance.kind == "assembly":
            files = {f"{slot}.npz": run_dir / saved_parts[part.key]["files"]["part"] for slot, part in instance.parts}
            before = tuple(StageResult(**s) for s in record["stages"][:2])  # parts overall, MBS started
            return AssemblyKind(evaluator, files, before, record.get("parts", {}), {})
        return single_kind(instance, evaluator)

    async def one(record: dict[str, Any]) -> dict[str, Any]:
        if record.get("first_failure") == "infrastructure" or "generation" not in record:
            return record  # also an assembly that never started: nothing was generated
        instance = instance_of(record)
        generation = record["generation"]
        selected = tuple(record["selection"].get("names", ()))
        graded = await kind_of(instance, record).grade(instance, generation.get("code"), selected,
                                                       generation.get("error"), keep=False)
        files = dict(record.get("files") or {})
        files.pop("traces", None)
        traces = await offload(evaluator.grading, save_traces, run_dir, record_key(record), graded.candidate,
                               graded.reference)
        if traces is not None:  # the plots follow the new grading
            files["traces"] = traces
        regraded = {**record, **graded.verdict.to_json(), "execution": graded.candidate.summary(),
                    "reference_execution": graded.reference.summary(), "evaluator": EVALUATOR_VERSION, "files": files}
        if record.get("repair"):  # a repair task: whether the draft was repaired follows the new grading
            regraded["repair"] = {**record["repair"], "repaired": graded.verdict.overall}
        return regraded

    async def counted(record: dict[str, Any], advance: Any) -> dict[str, Any]:
        regraded = await one(record)
        advance(bool(regraded.get("overall")), 0)
        return regraded

    try:
        graded = [instance_of(r) for r in run["tasks"]
                  if r.get("first_failure") != "infrastructure" and "generation" in r]
        await ensure_stack(graded, evaluator)  # a stack that cannot grade must not overwrite run.json
        with progress_bar(len(run["tasks"]), f"rescore {run_dir.name}", enabled=progress, tokens=False) as advance:
            run["tasks"] = list(await asyncio.gather(*(counted(r, advance) for r in run["tasks"])))
    finally:
        if pool is not None:
            await pool.close()
        if grading is not None:
            await asyncio.to_thread(grading.close)
    run["summary"] = summarize(run["tasks"])
    run["rescored"] = {"evaluator": EVALUATOR_VERSION, "at": dt.datetime.now(dt.UTC).isoformat()}
    os.replace(run_path, run_dir / "run.previous.json")
    write_atomic(run_path, json.dumps(run, indent=1, default=str))
    return run_path
