#!/usr/bin/env python
"""Run the benchmark's studies: one run folder per grid point of each study in a TOML spec.

    python scripts/sweep.py                                   # runs sweeps/default.toml
    python scripts/sweep.py --model gold                      # harness self-check, offline
    python scripts/sweep.py --spec sweeps/paper.toml --dry-run             # the paper's design, counted
    python scripts/sweep.py --spec sweeps/paper.toml --study temperature   # one study of it
    python scripts/sweep.py --model gemma4:31b --temperature 0 --temperature 0.7

Flags override every chosen study; --model, --temperature, --think, --select-template and
--code-template may be repeated and replace that axis of the grid. A grid point two studies
share runs once. Run folders under --out are named from their settings: a finished point is
skipped, an interrupted one resumed. Runs whose servers are free go at the same time (see
meceng.sweeps.farm), their programs on one worker pool; ground truths are executed once into the
reference store (OUT/references) and reused by every run and later sweep.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from meceng.cli import exit_now, parse_levels, parse_think, positive_int, print_summary
from meceng.cli.arguments import parse_only
from meceng.llm.types import DEFAULT_HOSTS
from meceng.logs import configure_logging
from meceng.pipeline import RunSettings
from meceng.pipeline.preflight import StackUnusable
from meceng.sweeps.farm import SweepJob, run_sweep
from meceng.sweeps.shard import Shard, pick
from meceng.sweeps.spec import (
    GridPoint,
    ModelSpec,
    PlannedRun,
    SweepSpec,
    load_spec,
    plan,
    point_workload,
    unique_points,
    unreachable_hosts,
    with_overrides,
)
from meceng.tasks.base import TEXTS

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_SPEC = ROOT / "sweeps" / "default.toml"


def parse_temperature(text: str) -> float | None:
    if text == "default":
        return None
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("temperature must be a number or 'default'") from None


def parse_shard(text: str) -> Shard:
    try:
        return Shard.parse(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def state_of(spec: SweepSpec, name: str) -> str:
    if (spec.out / name / "run.json").exists():
        return "finished"
    return "resume" if (spec.out / name / "journal.jsonl").exists() else "planned"


def plan_json(spec: SweepSpec, planned: list[PlannedRun], jobs: list[SweepJob], shard: Shard | None) -> str:
    """The plan of this shard (or the whole sweep) for scripts: each run's folder, studies, model,
    settings, tasks, LLM requests and state."""
    studies: dict[str, list[str]] = {}
    for item in planned:
        studies.setdefault(item.point.name, []).append(item.study)
    runs = []
    for job in jobs:
        assert job.point is not None
        tasks, requests = point_workload(job.point)
        runs.append({"folder": str(spec.out / job.name), "study": studies[job.point.name][0],
                     "studies": studies[job.point.name], "model": job.model, "backend": job.settings.llm.backend,
                     "hosts": list(job.hosts), "settings": job.settings.to_json(), "tasks": tasks,
                     "requests": requests, "state": state_of(spec, job.name)})
    return json.dumps({"shard": str(shard) if shard else None, "runs": runs,
                       "tasks": sum(r["tasks"] for r in runs), "requests": sum(r["requests"] for r in runs)},
                      indent=1)


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--spec", type=Path, default=None, help=f"TOML sweep spec (default {DEFAULT_SPEC.name})")
    p.add_argument("--study", action="append", help="run only this study of the spec; repeatable")
    p.add_argument("--dry-run", action="store_true",
                   help="print the planned runs, tasks and LLM requests per study; start nothing")
    p.add_argument("--json", action="store_true", help="with --dry-run: the plan as JSON, one object per run")
    p.add_argument("--shard", type=parse_shard, default=None,
                   help="K/N: only the K-th (from 0) of N parts of the runs, balanced by LLM requests; "
                        "inside a Slurm array SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT say it")
    p.add_argument("--model", action="append", help="model name; repeat for several (gold = ground truth)")
    p.add_argument("--backend", choices=tuple(DEFAULT_HOSTS), default=None)
    p.add_argument("--host", "--base-url", action="append", dest="host",
                   help="server URL (Ollama, or an OpenAI-compatible .../v1); repeat for several")
    p.add_argument("--api-defaults", action="store_true", help="send neither temperature nor seed (with --model)")
    p.add_argument("--vision", action="store_true",
                   help="the models take images: pictures for the agent loop (with --model; see meceng run --help)")
    p.add_argument("--temperature", action="append", type=parse_temperature,
                   help="a number, or 'default' for the model's own; repeatable")
    p.add_argument("--think", action="append", type=parse_think)
    p.add_argument("--select-template", action="append")
    p.add_argument("--code-template", action="append")
    p.add_argument("--levels", type=parse_levels)
    p.add_argument("--texts", action="append", choices=TEXTS,
                   help="task texts: paper and/or open (levels 1-2, graded by behaviour); repeat for both")
    p.add_argument("--only", action="append", default=None, help="task slugs or ids, comma-separated; repeatable")
    p.add_argument("--variations", type=positive_int)
    p.add_argument("--seed", type=int)
    p.add_argument("--batch-size", type=positive_int)
    p.add_argument("--workers", type=positive_int)
    p.add_argument("--timeout", type=float, help="seconds per program execution")
    p.add_argument("--executor", choices=("fork", "subprocess"), default="fork")
    p.add_argument("--out", type=Path)
    p.add_argument("--name", default=None, help="run folder name (single grid point only)")
    p.add_argument("--no-progress", action="store_true")
    p.add_argument("--reference-store", type=Path, default=None,
                   help="where ground-truth executions are kept for every run and later sweeps "
                        "(default OUT/references)")
    p.add_argument("--no-reference-store", action="store_true", help="execute every ground truth in every run")
    return p


def apply_flags(spec: SweepSpec, args: argparse.Namespace) -> SweepSpec:
    studies = spec.studies
    if args.study:
        unknown = sorted(set(args.study) - {s.name for s in studies})
        if unknown:
            raise ValueError(f"no study {', '.join(unknown)} in the spec (it has {', '.join(s.name for s in studies)})")
        studies = tuple(s for s in studies if s.name in args.study)
    models: tuple[ModelSpec, ...] | None = None
    if args.model:
        backend = args.backend or "ollama"
        hosts = tuple(args.host) if args.host else (DEFAULT_HOSTS[backend],)
        # gold and scripted models find their own backend where a point becomes settings (GridPoint.llm)
        models = tuple(ModelSpec(name=m, backend=backend, hosts=hosts,
                                 batch_size=args.batch_size or 4, vision=args.vision,
                                 api_defaults=args.api_defaults or backend == "anthropic") for m in args.model)
    only = parse_only(args.only) if args.only else None
    changed = []
    for study in studies:
        study_models = models
        if study_models is None and (args.host or args.batch_size):
            study_models = tuple(replace(m, hosts=tuple(args.host) if args.host else m.hosts,
                                         batch_size=args.batch_size or m.batch_size) for m in study.models)
        changed.append(with_overrides(
            study, models=study_models, temperatures=tuple(args.temperature) if args.temperature else None,
            thinks=tuple(args.think) if args.think else None,
            select_templates=tuple(args.select_template) if args.select_template else None,
            code_templates=tuple(args.code_template) if args.code_template else None,
            levels=args.levels, variations=args.variations, seed=args.seed, only=only,
            texts=tuple(dict.fromkeys(args.texts)) if args.texts else None))
    return replace(spec, studies=tuple(changed), out=args.out or spec.out, workers=args.workers or spec.workers,
                   exec_timeout_s=args.timeout or spec.exec_timeout_s)


def print_plan(spec: SweepSpec, planned: list[PlannedRun], console: Console) -> None:
    runs = Table(title=f"Planned runs under {spec.out}", title_justify="left")
    for column in ("study", "run folder", "tasks", "LLM requests", "state"):
        runs.add_column(column, justify="right" if column in ("tasks", "LLM requests") else "left",
                        overflow="fold")  # a folder name is folded onto a second line, never cut
    for item in planned:
        tasks, requests = point_workload(item.point)
        state = f"shared with {item.shared_with}" if item.shared_with else state_of(spec, item.point.name)
        runs.add_row(item.study, item.point.name, f"{tasks:,}", f"{requests:,}", state)
    console.print(runs)
    summary = Table(title=spec.description or "Studies", title_justify="left")
    for column in ("study", "models", "runs", "of them new", "tasks (new runs)", "LLM requests (new runs)"):
        summary.add_column(column, justify="left" if column == "study" else "right")
    for study in dict.fromkeys(item.study for item in planned):
        items = [i for i in planned if i.study == study]
        new = [i for i in items if i.shared_with is None]
        summary.add_row(study, str(len({m for i in items for m in i.point.model_names})), str(len(items)),
                        str(len(new)),
                        f"{sum(point_workload(i.point)[0] for i in new):,}",
                        f"{sum(point_workload(i.point)[1] for i in new):,}")
    points = unique_points(planned)
    summary.add_section()
    summary.add_row("total (each run once)", str(len({m for p in points for m in p.model_names})), str(len(planned)),
                    str(len(points)), f"{sum(point_workload(p)[0] for p in points):,}",
                    f"{sum(point_workload(p)[1] for p in points):,}")
    console.print(summary)
    console.print("LLM requests are an upper bound: two per task (selection, program), 2K for a consensus of K "
                  "samples, a selection and up to the agent's rounds for the tool-calling loop, one per repair "
                  "draft (up to the rounds with tools); an assembly's own only when all its parts pass.")


def sweep_jobs(points: list[GridPoint], spec: SweepSpec, args: argparse.Namespace, workers: int) -> list[SweepJob]:
    """The runs of the sweep with the settings each is started (or resumed) with."""
    jobs = []
    for point in points:
        name = args.name or point.name
        run_dir = spec.out / name
        settings = RunSettings(
            llm=point.llm(), levels=point.levels, only=point.only, variations=point.variations, seed=point.seed,
            out=spec.out, run_name=name, workers=workers, exec_timeout_s=spec.exec_timeout_s,
            select_template=point.select_template, code_template=point.code_template,
            progress=not args.no_progress, resume=(run_dir / "journal.jsonl").exists(), executor=args.executor,
            agent=point.agent, repair_tools=point.repair_tools, drafts_per_task=point.drafts_per_task,
            texts=point.texts, samples=point.samples, consensus_models=point.llms())
        jobs.append(SweepJob(name, point.model.name, settings, point_workload(point)[0], point))
    return jobs


def report_results(results: list[dict[str, Any]]) -> None:
    """After the live display: each run's summary, or why it did not run."""
    for result in results:
        name = Path(result["run"]).parent.name if result["run"].endswith("run.json") else Path(result["run"]).name
        if result.get("skipped"):
            print(f"{name}: finished earlier, skipped")
        elif "busy" in result:
            print(f"{name}: skipped, {result['busy']}")
        elif "error" in result:
            print(f"{name}: failed: {result['error']}", file=sys.stderr)
        else:
            print_summary(Path(result["run"]))
            result["overall"] = json.loads(Path(result["run"]).read_text())["summary"]["rates"]["overall"]


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    spec_path = args.spec or DEFAULT_SPEC
    try:
        spec = apply_flags(load_spec(spec_path), args)
    except (OSError, ValueError) as exc:
        print(f"error: sweep spec {spec_path}: {exc}", file=sys.stderr)
        return 2
    planned = plan(spec)
    points = unique_points(planned)
    if not points:
        print("error: the sweep has no grid point (no models?)", file=sys.stderr)
        return 2
    try:
        shard = args.shard or Shard.from_env()
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    points = pick(points, shard, weight=lambda p: point_workload(p)[1], name=lambda p: p.name)
    mine = {p.name for p in points}
    planned = [item for item in planned if item.point.name in mine]
    workers = spec.workers or max(1, os.cpu_count() or 1)  # one pool for all runs, sized to the machine
    if args.dry_run and args.json:
        print(plan_json(spec, planned, sweep_jobs(points, spec, args, workers), shard))
        return 0
    if args.dry_run:
        if shard is not None:
            print(f"shard {shard}: {len(points)} runs")
        if points:
            print_plan(spec, planned, Console())
        return 0
    if not points:
        print(f"shard {shard}: no runs (more shards than runs)")
        return 0
    if args.name and len(points) > 1:
        print("error: --name needs a single grid point", file=sys.stderr)
        return 2
    down = unreachable_hosts([m for p in points for m in p.model_points])  # every model of a run
    if down:
        print(f"no LLM server answers at {', '.join(down)}: start `ollama serve` there, or check the harness "
              "offline with: python scripts/sweep.py --model gold", file=sys.stderr)
        return 3
    configure_logging(None)
    store = None if args.no_reference_store else (args.reference_store or spec.out / "references")
    try:
        results = asyncio.run(run_sweep(sweep_jobs(points, spec, args, workers), workers, args.executor, store,
                                        display=not args.no_progress))
    except StackUnusable as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 3
    report_results(results)
    print(json.dumps(results, indent=1))
    return 1 if any("error" in r for r in results) else 0


if __name__ == "__main__":
    exit_now(main())  # without the interpreter's teardown: see meceng.cli.exit_now
