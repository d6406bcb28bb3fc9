#!/usr/bin/env python
"""What consensus is worth, and whether its confidence can be trusted: ``--agent consensus`` with the
scripted models over every level-1/2 task model (``llm/backend_scripted.py``).

``scripted:p=P`` writes the ground truth with probability P and otherwise one of the task's labelled
repair drafts (``tasks/drafts.py``) drawn at random; ``scripted-same:p=P`` always writes the same
draft when it is wrong. For each model and P in 0.3, 0.5, 0.7 one consensus run (K samples per task,
seeded) is made; printed are the single-sample and the consensus accuracy (the paper's verdict and
the behaviour verdict), the expected calibration error, and the accuracy per confidence bin.

    python scripts/consensus_measure.py [--samples 5] [--variations 1] [--out DIR] [--json FILE] [--across]

``--across``: for P in 0.3, 0.5, ``scripted-same:p=P`` alone against a consensus run across three
same-fault models whose faults differ (``scripted-same:p=P:d=0``, ``d=1``, ``d=2``): does agreement
between models see what agreement within one model cannot?
"""

from __future__ import annotations

import argparse
import asyncio
import json
import re
import tempfile
from pathlib import Path
from typing import Any

from meceng.eval.calibration import accuracy, calibration, calibration_error
from meceng.eval.rates import load_runs
from meceng.llm.types import LLMSettings
from meceng.logs import configure_logging
from meceng.pipeline import RunSettings, run_benchmark

PS = (0.3, 0.5, 0.7)
MODELS = ("scripted", "scripted-same")


def percent(rate: Any) -> str:
    return "–" if rate.value is None else f"{100 * rate.value:.1f}"


async def one_row(out: Path, label: str, p: float, models: list[str], samples: int, variations: int,
                  seed: int) -> dict[str, Any]:
    """One consensus run (across ``models`` when there are several: sample k by model k mod M)."""
    llms = tuple(LLMSettings(model=m, backend="scripted", temperature=0.7, seed=42 + seed) for m in models)
    settings = RunSettings(llm=llms[0], levels=("1", "2"), variations=variations, seed=seed, out=out,
                           run_name=re.sub(r"[^A-Za-z0-9.=-]+", "_", f"{label}-p{p:g}"), progress=False,
                           agent="consensus", samples=samples,
                           consensus_models=llms if len(llms) > 1 else ())
    run = load_runs([await run_benchmark(settings)])[0]
    bins = calibration(run.tasks)
    return {"model": label, "p": p, "tasks": accuracy(run.tasks)["consensus"].n, **accuracy(run.tasks),
            "ece_paper": calibration_error(bins), "ece_behaviour": calibration_error(bins, "behaviour"), "bins": bins}


async def measure(out: Path, samples: int, variations: int, seed: int, across: bool) -> list[dict[str, Any]]:
    """The six rows of docs/consensus.md's table; ``across``: instead, one model that repeats one fault
    against three that each repeat a fault of their own (``scripted-same:p=P:d=N``, N = 0, 1, 2)."""
    if across:
        return [await one_row(out, label, p, models, samples, variations, seed) for p in PS[:2]
                for label, models in (("scripted-same", [f"scripted-same:p={p:g}"]),
                                      ("3 x scripted-same d=0,1,2",
                                       [f"scripted-same:p={p:g}:d={d}" for d in range(3)]))]
    return [await one_row(out, model, p, [f"{model}:p={p:g}"], samples, variations, seed)
            for model in MODELS for p in PS]


def tables(rows: list[dict[str, Any]], samples: int) -> str:
    lines = [f"K = {samples} samples per task; accuracy in % (n tasks; single: n x K samples)", "",
             "| model | p | tasks | single (paper) | consensus (paper) | single (behaviour) | consensus (behaviour) "
             "| calibration error (paper) | calibration error (behaviour) |", "|" + "---|" * 9]
    for r in rows:
        lines.append(f"| {r['model']} | {r['p']:g} | {r['tasks']} | {percent(r['single'])} | {percent(r['consensus'])} "
                     f"| {percent(r['single_behaviour'])} | {percent(r['consensus_behaviour'])} "
                     f"| {r['ece_paper']:.3f} | {r['ece_behaviour']:.3f} |")
    edges = [b["bin"] for b in rows[0]["bins"]]
    lines += ["", "Accuracy (paper / behaviour, %) per confidence bin, n tasks in brackets:", "",
              "| model | p | " + " | ".join(edges) + " |", "|" + "---|" * (2 + len(edges))]
    for r in rows:
        cells = [f"{percent(b['paper'])} / {percent(b['behaviour'])} ({b['n']})" if b["n"] else "–" for b in r["bins"]]
        lines.append(f"| {r['model']} | {r['p']:g} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--samples", type=int, default=5)
    parser.add_argument("--variations", type=int, default=1)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=None, help="keep the runs here (default: a temporary folder)")
    parser.add_argument("--json", type=Path, default=None)
    parser.add_argument("--across", action="store_true",
                        help="one same-fault model against three with a fault each, in one run across models")
    args = parser.parse_args()
    configure_logging(None)
    with tempfile.TemporaryDirectory() as tmp:
        out = args.out or Path(tmp)
        rows = asyncio.run(measure(out, args.samples, args.variations, args.seed, args.across))
    print(tables(rows, args.samples))
    if args.json:
        args.json.write_text(json.dumps([{k: (v.to_json() if hasattr(v, "to_json") else v) for k, v in r.items()
                                          if k != "bins"} for r in rows], indent=1))


if __name__ == "__main__":
    main()
