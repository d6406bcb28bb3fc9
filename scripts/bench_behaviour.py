#!/usr/bin/env python
"""What the behaviour verdict costs per task: the child's extra time recording every body's motion,
the comparison's time in the parent, and the bytes an execution (and a stored ground truth) grows by.

For a few task models (seed 0) the ground truth runs in the warm fork server with and without the
motion record (median of ``--repeat`` runs each, interleaved); the comparison is timed on the two
records; sizes are the motion arrays and the pickled execution (what the reference store keeps).

    python scripts/bench_behaviour.py [--slugs a,b] [--repeat 5]
"""

from __future__ import annotations

import argparse
import asyncio
import pickle
import statistics
import time
from dataclasses import replace

from meceng.eval.behaviour import compare_behaviour, tolerance_for
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.recording import MOTION_SAMPLES
from meceng.tools.warm import WarmPool

SLUGS = "single_pendulum,double_pendulum_rigid_bodies,slider_crank_rigid_bodies,newtons_cradle," \
        "grid_mesh_and_large_sphere_impact"


async def bench(slugs: list[str], repeat: int) -> list[dict[str, float | str]]:
    pool = WarmPool(child_env())
    rows = []
    try:
        for slug in slugs:
            instance = default_registry().get(slug).instance(0)
            plain = ExecutionLimits(inspect_times=(instance.sim.end_time,))
            motion = replace(plain, motion_grid=(instance.sim.end_time, MOTION_SAMPLES))
            walls: dict[str, list[float]] = {"plain": [], "motion": []}
            runs = {}
            for _ in range(repeat):
                for name, limits in (("plain", plain), ("motion", motion)):
                    run = await execute(instance.reference_program, instance.sim.block(), limits, check=False,
                                        pool=pool)
                    walls[name].append(run.wall_time)
                    runs[name] = run
            t0 = time.perf_counter()
            for _ in range(20):
                compare_behaviour(runs["motion"].motion, runs["motion"].motion, tolerance_for(slug))
            compare_ms = (time.perf_counter() - t0) / 20 * 1000
            arrays = sum(v.nbytes for v in runs["motion"].motion.values() if hasattr(v, "nbytes"))
            rows.append({"slug": slug, "bodies": len(runs["motion"].motion["bodies"]),
                         "samples": len(runs["motion"].motion["t"]),
                         "run_ms": 1000 * statistics.median(walls["plain"]),
                         "run_motion_ms": 1000 * statistics.median(walls["motion"]), "compare_ms": compare_ms,
                         "motion_bytes": arrays, "pickle_bytes": len(pickle.dumps(runs["plain"])),
                         "pickle_motion_bytes": len(pickle.dumps(runs["motion"]))})
    finally:
        await pool.close()
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--slugs", default=SLUGS)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    rows = asyncio.run(bench(args.slugs.split(","), args.repeat))
    print("| task model | bodies | samples | run (ms) | run with motion (ms) | comparison (ms) | motion arrays (kB) |"
          " stored execution (kB): without | with |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['slug']} | {r['bodies']} | {r['samples']} | {r['run_ms']:.0f} | {r['run_motion_ms']:.0f} | "
              f"{r['compare_ms']:.1f} | {r['motion_bytes'] / 1000:.0f} | {r['pickle_bytes'] / 1000:.0f} | "
              f"{r['pickle_motion_bytes'] / 1000:.0f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
