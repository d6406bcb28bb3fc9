#!/usr/bin/env python
"""How far correct formulations of a ground truth drift apart, and how far a fault moves it: the
figures behind the behaviour tolerance (``eval/behaviour.py``).

For each task model (seed 0) the ground truth is run as graded, then
- with every float parameter changed by a relative 1e-10 (signs drawn from the seed): round-off in
  the inputs, what another correct formulation of the same system amounts to;
- with twice the steps: the ground truth's own time-stepping error at the paper's step count;
- with each float parameter changed by +4 % in turn: what the smallest realistic fault does.
Each is compared with the behaviour comparison; printed is the largest deviation as a fraction of
the ground truth's scales (the quantity ``relative`` bounds; the tolerance is 1e-3), and for
round-off the time at which it first passes the tolerance (the horizon a sensitive task needs).

With ``--alternatives N``: instead, every level 1-2 alternative (``tasks/alternatives.py``) at seeds
0..N-1, compared over the whole simulated time (no horizon): when, if ever, round-off lets the
system built another way part from the ground truth (the scooter's unstable upright equilibrium).

    python scripts/behaviour_sensitivity.py [--levels 1,2] [--slugs a,b] [--alternatives N] [--json FILE]
"""

from __future__ import annotations

import argparse
import asyncio
import dataclasses
import json
import random
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np

from meceng.eval.behaviour import BehaviourTolerance, compare_behaviour
from meceng.eval.chain import Tolerances
from meceng.pipeline.evaluation import Evaluator
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env
from meceng.tools.warm import WarmPool

_PARAMETER = re.compile(r"^([a-z_][a-z0-9_]*) = (-?\d+\.\d*(?:e-?\d+)?)$", re.M)
RELATIVE = 1e-3


def _floats(program: str) -> list[tuple[str, float]]:
    head = program.split("\n# parameters\n", 1)[-1]
    block = head.split("\n\n", 1)[0]
    return [(m.group(1), float(m.group(2))) for m in _PARAMETER.finditer(block)]


def _changed(program: str, changes: dict[str, float]) -> str:
    for name, value in changes.items():
        program = re.sub(rf"^{name} = .*$", f"{name} = {value!r}", program, count=1, flags=re.M)
    return program


def _fraction(verdict: dict[str, Any]) -> tuple[float, float | None]:
    """The largest deviation as a fraction of the scales, and the time the tolerance was first passed."""
    largest = verdict.get("largest") or {}
    first = verdict.get("first_divergence") or {}
    return float(largest.get("ratio") or 0.0) * RELATIVE, first.get("time")


async def measure(evaluator: Evaluator, instance: TaskInstance) -> dict[str, Any]:
    truth = await evaluator.execute(instance.reference_program, instance, check=False)
    tolerance = BehaviourTolerance(relative=RELATIVE)

    async def against(program: str, inst: TaskInstance = instance) -> dict[str, Any]:
        run = await evaluator.execute(program, inst, check=False)
        return compare_behaviour(run.motion, truth.motion, tolerance).to_json()

    parameters = _floats(instance.reference_program)
    rng = random.Random(instance.key)
    roundoff = await against(_changed(instance.reference_program,
                                      {n: v * (1 + rng.choice((-1, 1)) * 1e-10) for n, v in parameters}))
    finer_instance = dataclasses.replace(instance, sim=dataclasses.replace(instance.sim, steps=2 * instance.sim.steps))
    finer = await against(instance.reference_program, finer_instance)
    faults = []
    for name, value in parameters:
        if value == 0.0:
            continue
        verdict = await against(_changed(instance.reference_program, {name: value * 1.04}))
        faults.append((name, _fraction(verdict)[0]))
    moving = [f for f in faults if f[1] > 1e-6]  # the others do not change the motion (a pendulum's mass)
    r, horizon = _fraction(roundoff)
    return {"slug": instance.slug, "roundoff": r, "roundoff_parts_at": horizon, "finer_steps": _fraction(finer)[0],
            "fault_min": min((f[1] for f in moving), default=None),
            "fault_min_parameter": min(moving, key=lambda f: f[1])[0] if moving else None,
            "fault_median": float(np.median([f[1] for f in moving])) if moving else None,
            "end_time": instance.sim.end_time}


async def run(slugs: list[str]) -> list[dict[str, Any]]:
    pool = WarmPool(child_env())
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=120), Tolerances(), pool=pool)
    out = []
    try:
        for slug in slugs:
            out.append(await measure(evaluator, default_registry().get(slug).instance(0)))
            print(".", end="", file=sys.stderr, flush=True)
    finally:
        await pool.close()
    print(file=sys.stderr)
    return out


async def alternatives(seeds: int) -> list[dict[str, Any]]:
    from meceng.tasks.alternatives import ALTERNATIVES

    pool = WarmPool(child_env())
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=120), Tolerances(), pool=pool)
    out = []
    try:
        for alternative in ALTERNATIVES:
            if default_registry().get(alternative.slug).level not in ("1", "2"):
                continue
            parts, largest = [], 0.0
            for seed in range(seeds):
                instance = default_registry().get(alternative.slug).instance(seed)
                truth = await evaluator.execute(instance.reference_program, instance, check=False)
                run = await evaluator.execute(alternative.program(instance), instance, check=False)
                verdict = compare_behaviour(run.motion, truth.motion, BehaviourTolerance(relative=RELATIVE)).to_json()
                fraction, at = _fraction(verdict)
                largest = max(largest, fraction)
                if at is not None:
                    parts.append((seed, at / instance.sim.end_time))
            out.append({"alternative": alternative.id, "seeds": seeds, "largest": largest, "parts": parts})
            print(".", end="", file=sys.stderr, flush=True)
    finally:
        await pool.close()
    print(file=sys.stderr)
    return out


def _g(value: float | None) -> str:
    return "-" if value is None else f"{value:.2g}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--levels", default="1,2")
    parser.add_argument("--slugs", default="")
    parser.add_argument("--alternatives", type=int, default=0, help="seeds per alternative (0: the sensitivity table)")
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    if args.alternatives:
        found = asyncio.run(alternatives(args.alternatives))
        print("| alternative | seeds | largest deviation (fraction of scales) | parts from the ground truth (seed: "
              "fraction of the time) |")
        print("|---|---:|---:|---|")
        for r in found:
            parts = ", ".join(f"{s}: {f:.2f}" for s, f in r["parts"]) or "never"
            print(f"| {r['alternative']} | {r['seeds']} | {_g(r['largest'])} | {parts} |")
        if args.json:
            args.json.write_text(json.dumps(found, indent=1))
        return 0
    slugs = args.slugs.split(",") if args.slugs else [m.slug for m in default_registry().select(args.levels.split(","))]
    rows = asyncio.run(run(slugs))
    print("| task model | round-off 1e-10 | parts at (s) | 2x steps | +4 % one parameter: least (which) | median |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['slug']} | {_g(r['roundoff'])} | {_g(r['roundoff_parts_at'])} of {r['end_time']:g} | "
              f"{_g(r['finer_steps'])} | {_g(r['fault_min'])} ({r['fault_min_parameter']}) | {_g(r['fault_median'])} |")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
