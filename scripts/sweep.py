#!/usr/bin/env python
"""Sweep the benchmark over a grid: models x temperatures x thinking x prompt templates.

    python scripts/sweep.py                                   # runs sweeps/default.toml
    python scripts/sweep.py --model gold                      # harness self-check, offline
    python scripts/sweep.py --spec sweeps/paper.toml --variations 5
    python scripts/sweep.py --model gemma4:31b --model qwen3.5:27b --temperature 0 --temperature 0.7

Flags override the spec; --model, --temperature, --think, --select-template and --code-template
may be repeated and replace that axis of the grid. One run folder per grid point under --out,
named from its settings: a finished point is skipped, an interrupted one resumed.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
from dataclasses import replace
from pathlib import Path

from meceng.cli import exit_now, parse_levels, parse_think, positive_int, print_summary
from meceng.logs import configure_logging
from meceng.pipeline import RunSettings, run_benchmark
from meceng.sweep import ModelSpec, grid_points, load_spec, unreachable_hosts, with_overrides

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_SPEC = ROOT / "sweeps" / "default.toml"


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--spec", type=Path, default=None, help=f"TOML sweep spec (default {DEFAULT_SPEC.name})")
    p.add_argument("--model", action="append", help="model name; repeat for several (gold = ground truth)")
    p.add_argument("--backend", choices=("ollama", "openai", "gold"), default=None)
    p.add_argument("--host", "--base-url", action="append", dest="host",
                   help="server URL (Ollama, or an OpenAI-compatible .../v1); repeat for several")
    p.add_argument("--temperature", action="append", type=float)
    p.add_argument("--think", action="append", type=parse_think)
    p.add_argument("--select-template", action="append")
    p.add_argument("--code-template", action="append")
    p.add_argument("--levels", type=parse_levels)
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
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    spec_path = args.spec or DEFAULT_SPEC
    try:
        spec = load_spec(spec_path)
    except (OSError, ValueError) as exc:
        print(f"error: cannot read sweep spec {spec_path}: {exc}", file=sys.stderr)
        return 2
    if args.model:
        hosts = tuple(args.host) if args.host else ("http://127.0.0.1:11434",)
        spec = replace(spec, models=tuple(
            ModelSpec(name=m, backend="gold" if m == "gold" else (args.backend or "ollama"), hosts=hosts,
                      batch_size=args.batch_size or 4) for m in args.model))
    elif args.host or args.batch_size:
        spec = replace(spec, models=tuple(replace(m, hosts=tuple(args.host) if args.host else m.hosts,
                                                  batch_size=args.batch_size or m.batch_size) for m in spec.models))
    spec = with_overrides(
        spec, temperatures=tuple(args.temperature) if args.temperature else None,
        thinks=tuple(args.think) if args.think else None,
        select_templates=tuple(args.select_template) if args.select_template else None,
        code_templates=tuple(args.code_template) if args.code_template else None,
        levels=args.levels, variations=args.variations, seed=args.seed, out=args.out, workers=args.workers,
        exec_timeout_s=args.timeout,
        only=tuple(x.strip() for part in args.only for x in part.split(",") if x.strip()) if args.only else None,
    )
    points = grid_points(spec)
    if not points:
        print("error: the sweep has no grid point (no models?)", file=sys.stderr)
        return 2
    if args.name and len(points) > 1:
        print("error: --name needs a single grid point", file=sys.stderr)
        return 2
    down = unreachable_hosts(points)
    if down:
        print(f"no LLM server answers at {', '.join(down)}: start `ollama serve` there, or check the harness "
              "offline with: python scripts/sweep.py --model gold", file=sys.stderr)
        return 3
    configure_logging(None)
    results = []
    for point in points:
        name = args.name or point.name(spec)
        run_dir = spec.out / name
        if (run_dir / "run.json").exists():
            print(f"{name}: finished earlier, skipped")
            results.append({"run": str(run_dir / "run.json"), "skipped": True})
            continue
        import os

        settings = RunSettings(
            llm=point.llm(levels=spec.levels), levels=spec.levels, only=spec.only, variations=spec.variations,
            seed=spec.seed,
            out=spec.out, run_name=name, workers=spec.workers or max(1, os.cpu_count() or 1),
            exec_timeout_s=spec.exec_timeout_s, select_template=point.select_template,
            code_template=point.code_template, progress=not args.no_progress,
            resume=(run_dir / "journal.jsonl").exists(), executor=args.executor,
        )
        try:
            path = asyncio.run(run_benchmark(settings))
        except Exception as exc:  # one grid point never ends the sweep
            print(f"{name}: failed: {exc}", file=sys.stderr)
            results.append({"run": str(run_dir), "error": str(exc)})
            continue
        print_summary(path)
        summary = json.loads(path.read_text())["summary"]
        results.append({"run": str(path), "overall": summary["rates"]["overall"]})
    print(json.dumps(results, indent=1))
    return 1 if any("error" in r for r in results) else 0


if __name__ == "__main__":
    exit_now(main())  # without the interpreter's teardown: see meceng.cli.exit_now
