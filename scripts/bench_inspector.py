"""The agent's eyes, measured: how long the inspector's and the snapshot's answers are and what
they cost.

For a few task models (the largest level-2 task among them) the ground-truth program is given to
the tools as an agent would: the inspector's default answer (characters and an estimate of its
tokens), the wall time of a ``simulate`` and a ``snapshot`` call, the snapshot's drawing alone,
and the viewer's SVG for one record. No tokenizer can be downloaded here: tokens are counted the
way GPT-style pre-tokenizers split text (a run of letters, of at most three digits, one other
character, each with its leading space), which is close to a BPE count for text of numbers and
short words; the characters / 4 rule is printed beside it.

    python scripts/bench_inspector.py [--repeats 3] [--json FILE]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import re
import statistics
import sys
import time
from pathlib import Path

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.inspect.scene import build_scene
from meceng.inspect.snapshot import draw
from meceng.inspect.view import build_view
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute
from meceng.viewer.systems import system_pictures

TASKS = ("grid_mesh_and_large_sphere_impact", "non_steerable_four_wheeled_car",
         "rrr_articulated_robot_with_3d_cubic_trajectory", "double_pendulum_rigid_bodies")
_PIECES = re.compile(r" ?[A-Za-z]+| ?\d{1,3}| ?[^\sA-Za-z\d]|\s+")


def estimate_tokens(text: str) -> int:
    return len(_PIECES.findall(text))


async def measure(slug: str, repeats: int) -> dict[str, float | int | str]:
    instance = default_registry().get(slug).instance(0)
    toolbox = Toolbox(instance, rigid_catalog())
    simulate, snapshot = [], []
    text = ""
    for _ in range(repeats):
        t0 = time.perf_counter()
        text = (await toolbox.call("simulate", {"code": instance.reference_program})).text
        simulate.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        await Toolbox(instance, rigid_catalog(), vision=True).call("snapshot", {"code": instance.reference_program})
        snapshot.append(time.perf_counter() - t0)
    end = instance.sim.end_time
    run = await execute(instance.reference_program, instance.sim.block(), ExecutionLimits(inspect_times=(end,)))
    view = build_view(run.items, run.system, run.inspection, run.trajectory, run.times)
    drawing = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        draw(view, (0.0, end))
        drawing.append(time.perf_counter() - t0)
    shapes = [[s.to_json() for s in build_scene(view, t)] for t in (0.0, end)]
    scenes = {"cand": {"times": [0.0, end], "shapes": shapes}}
    scenes["ref"] = scenes["cand"]
    t0 = time.perf_counter()
    for _ in range(repeats):
        system_pictures(json.dumps(scenes))
    svg = (time.perf_counter() - t0) / repeats
    return {"task": slug, "bodies": len(view.bodies), "connectors": len(view.connectors),
            "answer_chars": len(text), "answer_tokens_estimate": estimate_tokens(text), "chars_over_4": len(text) // 4,
            "simulate_s": statistics.median(simulate), "snapshot_s": statistics.median(snapshot),
            "draw_s": statistics.median(drawing), "viewer_svg_ms": svg * 1000}


async def main_async(repeats: int) -> list[dict[str, float | int | str]]:
    return [await measure(slug, repeats) for slug in TASKS]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=3, help="calls per figure (the median is printed)")
    parser.add_argument("--json", type=Path, default=None, help="write the figures to this file")
    args = parser.parse_args(argv)
    rows = asyncio.run(main_async(max(1, args.repeats)))
    header = ("task", "bodies", "connectors", "answer_chars", "answer_tokens_estimate", "chars_over_4", "simulate_s",
              "snapshot_s", "draw_s", "viewer_svg_ms")
    sys.stdout.write(" | ".join(header) + "\n")
    for row in rows:
        sys.stdout.write(" | ".join(f"{row[k]:.3f}" if isinstance(row[k], float) else str(row[k]) for k in header)
                         + "\n")
    if args.json:
        args.json.write_text(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
