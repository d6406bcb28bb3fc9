#!/usr/bin/env python
"""Which task models behaviour compares at more than their steps, at what R, and what it costs.

For each task model (seed 0, or ``--seeds``) the ground truth runs at 1, 2, 4, ... x its steps as the
evaluator does (``pipeline/converged.find_convergence``: doubling until its self-error at R against 2R
no longer widens a tolerance, at most ``CONVERGE_CAP``). Printed per instance: R, whether it converged,
the self-error at each R tried (``STEP_MARGIN`` x the largest difference over the base tolerance: at
most 1 is converged), the nominal run's wall time, the ground truth's extra runs (beyond the nominal
run and the one with twice the steps that behaviour always had; once per instance, then in the
reference store) and a candidate's extra run at R x the steps (every graded program of that
instance). Then the task models with R > 1.

    python scripts/behaviour_convergence.py [--levels 1,2] [--slugs a,b] [--seeds 1] [--json FILE]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
from pathlib import Path
from typing import Any

from meceng.eval.behaviour import tolerance_for
from meceng.eval.chain import Tolerances
from meceng.pipeline.converged import at_steps, find_convergence
from meceng.pipeline.evaluation import Evaluator
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool


async def measure(evaluator: Evaluator, instance: TaskInstance) -> dict[str, Any]:
    walls: dict[int, float] = {}

    async def run_at(factor: int) -> Execution:
        if factor == 1:
            run = await evaluator.execute(instance.reference_program, instance, check=False)
        else:
            run = await evaluator.run_motion(instance.reference_program, at_steps(instance, factor), check=False)
        walls[factor] = run.wall_time
        return run

    found = await find_convergence(run_at, instance.sim.steps, tolerance_for(instance.slug))
    c = found.convergence
    extra_truth = sum(w for f, w in walls.items() if f > 2)
    return {"slug": instance.slug, "seed": instance.seed, "steps": instance.sim.steps, "factor": c.factor,
            "converged": c.converged, "checks": [x.to_json() for x in c.checks], "note": c.note,
            "nominal_s": walls.get(1, 0.0), "extra_truth_s": extra_truth,
            "extra_candidate_s": walls.get(c.factor, 0.0) if c.factor > 1 else 0.0}


async def run(instances: list[TaskInstance]) -> list[dict[str, Any]]:
    pool = WarmPool(child_env())
    evaluator = Evaluator(1, ExecutionLimits(timeout_s=300), Tolerances(), pool=pool)
    out = []
    try:
        for instance in instances:
            out.append(await measure(evaluator, instance))
            print(".", end="", file=sys.stderr, flush=True)
    finally:
        await pool.close()
    print(file=sys.stderr)
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--levels", default="1,2")
    parser.add_argument("--slugs", default="")
    parser.add_argument("--seeds", type=int, default=1, help="seeds 0..N-1 of each task model")
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    registry = default_registry()
    models = [registry.get(s) for s in args.slugs.split(",")] if args.slugs else registry.select(args.levels.split(","))
    rows = asyncio.run(run([m.instance(seed) for m in models for seed in range(args.seeds)]))
    print("| task model | seed | steps | R | converged | self-error at R = 1, 2, ... (3 x the step error over the base "
          "tolerance) | nominal run (s) | ground truth's extra runs (s, once) | "
          "candidate's extra run (s, each program) |")
    print("|---|---:|---:|---:|---|---|---:|---:|---:|")
    for r in rows:
        errors = ", ".join(f"{c['ratio']:.3g}" for c in r["checks"])
        print(f"| {r['slug']} | {r['seed']} | {r['steps']} | {r['factor']} | {'yes' if r['converged'] else 'no'} | "
              f"{errors} | {r['nominal_s']:.2f} | {r['extra_truth_s']:.2f} | {r['extra_candidate_s']:.2f} |")
    needing = [r for r in rows if r["factor"] > 1]
    print(f"\n{len(needing)} of {len(rows)} instances compare at R > 1: " +
          (", ".join(f"{r['slug']}@{r['seed']} R={r['factor']}" for r in needing) or "none"))
    if rows:
        nominal = sum(r["nominal_s"] for r in rows)
        candidate = sum(r["extra_candidate_s"] for r in rows)
        truth = sum(r["extra_truth_s"] for r in rows)
        print(f"added per task, averaged over these {len(rows)} instances: {candidate / len(rows):.3f} s of candidate "
              f"runs ({candidate / nominal:.2f} x the nominal runs' {nominal / len(rows):.3f} s), and once per "
              f"instance (then in the reference store) {truth / len(rows):.3f} s of ground-truth runs")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
