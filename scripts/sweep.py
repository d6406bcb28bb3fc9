#!/usr/bin/env python
"""Sweep the benchmark over a grid: models x temperatures x thinking x prompt templates.

Examples:
    python scripts/sweep.py --model gold                                   # harness self-check
    python scripts/sweep.py --model gemma4:31b --model qwen3.5:27b --levels 1,2 --variations 20
    python scripts/sweep.py --model gpt-oss:20b --temperature 0 --temperature 0.7 --think off --think on

Every grid point is one run folder under --out; a grid point that fails is reported and the
sweep goes on. ``--model gold`` implies the gold backend.
"""

from __future__ import annotations

import argparse
import asyncio
import itertools
import json
import sys
from pathlib import Path

from meceng.cli import _think, add_run_arguments, llm_settings, print_summary, run_settings
from meceng.logs import configure_logging
from meceng.pipeline import run_benchmark


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_run_arguments(parser)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    grid = argparse.ArgumentParser(add_help=False)
    grid.add_argument("--model", action="append", default=None)
    grid.add_argument("--temperature", action="append", type=float, default=None)
    grid.add_argument("--think", action="append", type=_think, default=None)
    axes, rest = grid.parse_known_args(argv)
    args = parser.parse_args(rest)
    models = axes.model or ["gold"]
    temperatures = axes.temperature or [args.temperature]
    thinks = axes.think if axes.think is not None else [args.think]
    configure_logging(None)
    results = []
    points = list(itertools.product(models, temperatures, thinks))
    for model, temperature, think in points:
        llm = llm_settings(args, model=model, temperature=temperature, think=think)
        name = None
        if len(points) > 1 and args.name:
            name = f"{args.name}_{model}_T{temperature:g}_think-{think}".replace(":", "-").replace("/", "-")
        try:
            settings = run_settings(args, llm, name=name)
            path = asyncio.run(run_benchmark(settings))
        except Exception as exc:
            print(f"grid point model={model} T={temperature} think={think} failed: {exc}", file=sys.stderr)
            results.append({"model": model, "temperature": temperature, "think": think, "error": str(exc)})
            continue
        print_summary(path)
        summary = json.loads(Path(path).read_text())["summary"]
        results.append({"model": model, "temperature": temperature, "think": think, "run": str(path),
                        "overall": summary["rates"]["overall"]})
    print(json.dumps(results, indent=1))
    return 1 if any("error" in r for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
