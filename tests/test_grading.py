"""Grading in the pool beside the workers gives the records grading on the parent's threads gives,
and a program the static check refuses (now checked in the worker) still never runs."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from records import normalized

from meceng.agents.llm import LLMSettings
from meceng.pipeline import RunSettings, rescore, run_benchmark
from meceng.tasks import default_registry
from meceng.tools.executor import execute


async def test_pool_and_threads_grade_alike(tmp_path: Path) -> None:
    settings = RunSettings(llm=LLMSettings(model="gold", backend="gold"), only=("3", "11", "23"), variations=1,
                           out=tmp_path, run_name="gold", workers=2, progress=False)
    run_json = await run_benchmark(settings)
    shutil.copytree(tmp_path / "gold", tmp_path / "again")
    graded = {}
    for folder, pool in (("gold", True), ("again", False)):
        tasks = json.loads((await rescore(tmp_path / folder, workers=2, grading_pool=pool)).read_text())["tasks"]
        graded[pool] = normalized([{k: v for k, v in t.items() if k != "files"} for t in tasks],
                                  ("time", "timing", "duration", "started", "stderr_tail", "wall"))
    assert graded[True] == graded[False]
    assert [t["overall"] for t in json.loads(run_json.read_text())["tasks"]] == [True, True, True]


async def test_a_refused_program_never_runs(tmp_path: Path) -> None:
    instance = default_registry().get("single_mass_oscillator").instance(0)
    marker = tmp_path / "ran"
    program = f"import os\nopen({str(marker)!r}, 'w').write('x')\n" + instance.reference_program
    refused = await execute(program, instance.sim.block(), check=True)
    assert refused.stage == "refused" and refused.error_kind == "safety" and not marker.exists()
