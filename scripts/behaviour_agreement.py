#!/usr/bin/env python
"""The paper's verdict beside the behaviour verdict, over programs whose answer is known.

1. the alternatives (``meceng/tasks/alternatives.py``): the same system built another way; behaviour
   must pass every one, the paper's verdict fails some;
2. the repair drafts (``meceng/tasks/drafts.py``) of every level 1-2 task model at seed 0: one
   realistic fault each; behaviour must fail every draft whose motion differs;
3. the mutation corpora (``tests/corpus``) of levels 1 and 2 (and 3b with ``--assemblies``).

``--levels 3b --assemblies`` measures the assemblies alone (their parts are made first, ~15 s each).

Prints one table per set, the disagreements by name, and the totals.

    python scripts/behaviour_agreement.py [--assemblies] [--levels 1,2,3b] [--only alternatives,drafts,corpus]
                                          [--json FILE]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import shlex
import sys
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

from meceng.eval.chain import Tolerances, Verdict
from meceng.pipeline.evaluation import Evaluator
from meceng.tasks.alternatives import ALTERNATIVES
from meceng.tasks.base import TaskInstance
from meceng.tasks.drafts import candidate_drafts
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

ROOT = Path(__file__).resolve().parents[1]


async def grade(evaluator: Evaluator, instance: TaskInstance, program: str, parts: dict[str, dict[str, Path]],
                folder: Path) -> Verdict:
    files = None
    if instance.kind == "assembly":
        if instance.key not in parts:
            parts[instance.key] = await evaluator.ground_truth_parts(instance, folder / instance.key.replace("/", "_"))
        files = parts[instance.key]
    verdict = (await evaluator.evaluate(instance, program, None, None, files=files))[0]
    return verdict


def row(name: str, verdict: Verdict, expected: str) -> dict[str, Any]:
    behaviour = verdict.behaviour or {}
    largest = behaviour.get("largest") or {}
    return {"name": name, "expected": expected, "paper": verdict.overall, "first_failure": verdict.first_failure,
            "behaviour": behaviour.get("passed"), "quantity": largest.get("quantity"), "ratio": largest.get("ratio"),
            "detail": behaviour.get("detail", "")}


async def collect(only: set[str], assemblies: bool, levels: set[str] | None = None) -> dict[str, list[dict[str, Any]]]:
    levels = levels or {"1", "2", "3b"}
    registry = default_registry()
    pool = WarmPool(child_env())
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=300), Tolerances(), pool=pool)
    parts: dict[str, dict[str, Path]] = {}
    out: dict[str, list[dict[str, Any]]] = {"alternatives": [], "drafts": [], "corpus": []}
    with tempfile.TemporaryDirectory(prefix="meceng-agreement-") as tmp:
        folder = Path(tmp)
        try:
            if "alternatives" in only:
                for alternative in ALTERNATIVES:
                    instance = registry.get(alternative.slug).instance(0)
                    if (instance.kind == "assembly" and not assemblies) or instance.level not in levels:
                        continue
                    (folder / instance.key.replace("/", "_")).mkdir(exist_ok=True)
                    verdict = await grade(evaluator, instance, alternative.program(instance), parts, folder)
                    out["alternatives"].append({**row(alternative.id, verdict, "pass"), "kind": alternative.kind})
                    print(".", end="", file=sys.stderr, flush=True)
            if "drafts" in only:
                for model in registry.select(sorted(levels & {"1", "2"})) if levels & {"1", "2"} else []:
                    instance = model.instance(0)
                    for draft in candidate_drafts(instance):
                        verdict = await grade(evaluator, instance, draft.program, parts, folder)
                        out["drafts"].append({**row(f"{model.slug}/{draft.id}", verdict, "fail"),
                                              "fault": draft.fault})
                        print(".", end="", file=sys.stderr, flush=True)
                    evaluator.release(instance)
            if "corpus" in only:
                for path in sorted((ROOT / "tests" / "corpus").glob("*.py")):
                    level = path.name.split("_", 1)[0]
                    if level not in levels or (level == "3b" and not assemblies):
                        continue
                    fields = dict(item.split("=", 1) for item in
                                  shlex.split(path.read_text().splitlines()[0].removeprefix("# corpus: ")))
                    instance = registry.get(fields["task"]).instance(int(fields["seed"]))
                    (folder / instance.key.replace("/", "_")).mkdir(exist_ok=True)
                    verdict = await grade(evaluator, instance, path.read_text(), parts, folder)
                    out["corpus"].append(row(path.stem, verdict, fields["expect"]))
                    print(".", end="", file=sys.stderr, flush=True)
        finally:
            await pool.close()
    print(file=sys.stderr)
    return out


def table(rows: list[dict[str, Any]]) -> str:
    """Counts of (paper verdict, behaviour verdict) and the disagreements by name."""
    counts = Counter((r["paper"], r["behaviour"]) for r in rows)
    lines = ["| | behaviour passes | behaviour fails |", "|---|---:|---:|"]
    for paper in (True, False):
        lines.append(f"| paper {'passes' if paper else 'fails'} | {counts[(paper, True)]} | {counts[(paper, False)]} |")
    disagreements = [r for r in rows if r["paper"] != r["behaviour"]]
    if disagreements:
        lines.append("")
        lines.append("Disagreements:")
        for r in disagreements:
            paper = "passes" if r["paper"] else f"fails at {r['first_failure']}"
            said = f"paper {paper}, behaviour {'passes' if r['behaviour'] else 'fails'} " \
                   f"(largest: {r['quantity']} at {r['ratio']} of its tolerance)"
            lines.append(f"- {r['name']}: {said}")
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--assemblies", action="store_true", help="level 3b too (parts are made: ~15 s each)")
    parser.add_argument("--only", default="alternatives,drafts,corpus")
    parser.add_argument("--levels", default="1,2,3b", help="which levels' programs (3b needs --assemblies)")
    parser.add_argument("--json", type=Path, help="write every row here")
    args = parser.parse_args()
    out = asyncio.run(collect(set(args.only.split(",")), args.assemblies, set(args.levels.split(","))))
    for name, rows in out.items():
        if not rows:
            continue
        print(f"\n## {name} ({len(rows)})\n")
        print(table(rows))
        if name == "alternatives":
            failed = [r for r in rows if not r["behaviour"]]
            print(f"\nbehaviour passes {len(rows) - len(failed)}/{len(rows)} alternatives; the paper's verdict fails "
                  f"{sum(not r['paper'] for r in rows)}")
        if name == "corpus":
            wrong = [r for r in rows if (r["expected"] == "pass") != bool(r["behaviour"])]
            print(f"\nbehaviour agrees with the corpus label on {len(rows) - len(wrong)}/{len(rows)}")
    if args.json:
        args.json.write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
