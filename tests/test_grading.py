"""Grading in the pool beside the workers gives the records grading on the parent's threads gives,
and a program the static check refuses (now checked in the worker) still never runs."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from records import normalized

from meceng.llm.types import LLMSettings
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
                                  ("time", "timing", "duration", "started", "stderr_tail", "wall", "cpu_s"))
    assert graded[True] == graded[False]
    assert [t["overall"] for t in json.loads(run_json.read_text())["tasks"]] == [True, True, True]


async def test_a_refused_program_never_runs(tmp_path: Path) -> None:
    instance = default_registry().get("single_mass_oscillator").instance(0)
    marker = tmp_path / "ran"
    program = f"import os\nopen({str(marker)!r}, 'w').write('x')\n" + instance.reference_program
    refused = await execute(program, instance.sim.block(), check=True)
    assert refused.stage == "refused" and refused.error_kind == "safety" and not marker.exists()


@pytest.mark.parametrize(("script", "guarded"), [
    ("import asyncio\nfrom meceng.pipeline import run_benchmark\n\nasync def main():\n    pass\n\n"
     "if __name__ == '__main__':\n    asyncio.run(main())\n", True),
    ("import asyncio\n\nasync def main():\n    pass\n\nasyncio.run(main())\n", False),
    ("import asyncio\nresult = asyncio.run(main())\n", False),
    ("from pathlib import Path\nROOT = Path(__file__).resolve().parents[1]\n\nif __name__ == '__main__':\n"
     "    print(ROOT)\n", True),
    ('"""A docstring."""\nLIMIT = 3\n', True),
])
def test_a_script_that_runs_at_its_top_level_gets_no_grading_pool(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                  script: str, guarded: bool) -> None:
    """The pool's fork server imports the script that started us: one that runs a benchmark at its
    top level would run it again there (every task of such a run was lost to BrokenProcessPool)."""
    import sys
    import types

    from meceng.pipeline import grading

    path = tmp_path / "script.py"
    path.write_text(script)
    main = types.ModuleType("__main__")
    main.__file__ = str(path)
    main.__spec__ = None
    monkeypatch.setitem(sys.modules, "__main__", main)
    assert grading.main_script_is_guarded() is guarded
    pool = grading.grading_pool(1)
    assert (pool is not None) is guarded
    if pool is not None:
        pool.close()


POOL_USER = """
import asyncio, multiprocessing.forkserver, os, sys, time
from meceng.pipeline.grading import GradingPool

async def main():
    pool = GradingPool(2)
    await pool.warm()
    server = multiprocessing.forkserver._forkserver._forkserver_pid
    print(server, flush=True)
    time.sleep(600)

if __name__ == "__main__":
    asyncio.run(main())
"""


def _running(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return False
    return state != "Z"  # a zombie has ended; reaping it is its new parent's business


def test_the_pool_leaves_with_a_killed_parent(tmp_path: Path) -> None:
    """SIGKILL of the process using the pool: its processes (children of the pool's fork server,
    waiting for work on a pipe nobody closes) and the fork server end too, instead of staying
    behind with their memory after every killed sweep."""
    import signal
    import subprocess
    import sys
    import time

    script = tmp_path / "user.py"
    script.write_text(POOL_USER)
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    assert proc.stdout is not None
    server = int(proc.stdout.readline())
    pids = [server, *(int(p) for p in Path(f"/proc/{server}/task/{server}/children").read_text().split())]
    assert len(pids) == 3 and all(_running(p) for p in pids)  # the fork server and the pool's 2 processes
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    deadline = time.monotonic() + 20
    while any(_running(p) for p in pids) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not [p for p in pids if _running(p)]
