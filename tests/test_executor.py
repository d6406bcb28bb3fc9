"""The isolated executor: every way a program can fail is a recorded verdict, never a crash."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

HEAD = "import exudyn as exu\nfrom exudyn.utilities import *\nSC = exu.SystemContainer()\nmbs = SC.AddSystem()\n"
MODEL = "o = mbs.CreateMassPoint(referencePosition=[0,0,0], mass=1, gravity=[0,0,-9.81])\n"
SIM = ("simulationSettings = exu.SimulationSettings()\nsimulationSettings.timeIntegration.endTime = 0.1\n"
       "simulationSettings.timeIntegration.numberOfSteps = 100\nsimulationSettings.solution.file.write = False\n"
       "mbs.SolveDynamic(simulationSettings)\n")


async def test_solver_block_is_replaced_and_trajectory_recorded() -> None:
    llm_sim = SIM.replace("numberOfSteps = 100", "numberOfSteps = 7").replace("endTime = 0.1", "endTime = 5")
    result = await execute(HEAD + MODEL + "mbs.Assemble()\n" + llm_sim, SIM)
    assert result.solved, result.error
    assert result.trajectory is not None and result.trajectory.shape == (101, 3)
    assert result.times[0] == 0.0 and abs(result.times[-1] - 0.1) < 1e-12
    # free fall: z(t) = -g t^2 / 2
    assert abs(result.trajectory[-1, 2] + 9.81 * 0.1**2 / 2) < 1e-6
    assert result.items is not None and result.items["objects"][0]["objectType"] == "MassPoint"


async def test_program_without_own_solve_and_in_main_guard() -> None:
    code = HEAD + "if __name__ == '__main__':\n    " + MODEL + "    mbs.Assemble()\n"
    result = await execute(code, SIM)
    assert result.solved, result.error


@pytest.mark.parametrize(("body", "stage", "kind", "text"), [
    ("mbs.CreateMassPoint(referencePosition=[0,0,0], mas=1)\nmbs.Assemble()\n", "started", "exception", "TypeError"),
    (MODEL + "raise SystemExit(0)\nmbs.Assemble()\n", "started", "exception", "exit"),
    (MODEL, "started", "exception", "never called mbs.Assemble"),
    (MODEL + "mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[0, 5], stiffness=1))\nmbs.Assemble()\n",
     "reached_assemble", "exception", "ModelError"),
])
async def test_failures_before_and_during_assemble(body: str, stage: str, kind: str, text: str) -> None:
    result = await execute(HEAD + body, SIM)
    assert result.stage == stage and result.error_kind == kind and text in (result.error or "")
    assert not result.finished_assemble


async def test_endless_loop_is_killed_with_its_children(tmp_path) -> None:
    code = HEAD + MODEL + "mbs.Assemble()\nwhile True:\n    pass\n"
    t0 = time.perf_counter()
    result = await execute(code, SIM, ExecutionLimits(timeout_s=2.0), check=False)
    assert time.perf_counter() - t0 < 10
    assert result.error_kind == "timeout" and result.stage == "finished_assemble"


@pytest.mark.parametrize("warm", [False, True])
async def test_segfault_is_a_verdict(warm: bool) -> None:
    # the audit hook would refuse ctypes; switch it off to see the process-level containment
    from meceng.tools.executor import child_env
    from meceng.tools.warm import WarmPool

    pool = WarmPool(child_env()) if warm else None
    code = "import ctypes\nctypes.string_at(0)\n"
    try:
        result = await execute(code, SIM, ExecutionLimits(guard=False), check=False, pool=pool)
        if pool is not None:  # the fork server survives its child's crash and serves the next one
            after = await execute(HEAD + MODEL + "mbs.Assemble()\n", SIM, pool=pool)
            assert after.solved
    finally:
        if pool is not None:
            await pool.close()
    assert result.error_kind == "crash" and "SIGSEGV" in (result.error or "")


async def test_static_check_refuses_before_running(tmp_path) -> None:
    canary = tmp_path / "canary.txt"
    result = await execute(HEAD + f"open({str(canary)!r}, 'w').write('x')\n", SIM)
    assert result.stage == "refused" and result.error_kind == "safety"
    assert not canary.exists()


async def test_secrets_are_not_in_the_child_environment(monkeypatch) -> None:
    monkeypatch.setenv("OPENAI_API_KEY", "sk-secret")
    code = "import os\nprint(sorted(os.environ))\nraise RuntimeError(os.environ.get('OPENAI_API_KEY', 'absent'))\n"
    result = await execute(code, SIM, check=False)
    assert "absent" in (result.error or "") and "sk-secret" not in result.stdout_tail
    assert os.environ["OPENAI_API_KEY"] == "sk-secret"


async def test_solver_failure_after_assemble() -> None:
    instance = default_registry().get("single_pendulum").instance(0)
    # a constraint distance that contradicts the initial position: the solver cannot start
    code = instance.reference_program.replace("distance=length)", "distance=length * 3)")
    result = await execute(code, instance.sim.block(), ExecutionLimits(timeout_s=60))
    assert result.finished_assemble and not result.solved


@pytest.mark.parametrize("warm", [False, True])
async def test_a_cancelled_execution_kills_its_program(warm: bool, tmp_path) -> None:
    """A reference execution whose task was lost is cancelled: its program must not run on."""
    import asyncio

    from meceng.tools.executor import child_env
    from meceng.tools.warm import WarmPool

    pool = WarmPool(child_env()) if warm else None
    program = "import os, time\nopen('pid', 'w').write(str(os.getpid()))\ntime.sleep(60)\n"
    limits = ExecutionLimits(timeout_s=90, guard=False, keep_scratch=True)
    running = asyncio.ensure_future(execute(program, "", limits, scratch_root=tmp_path, check=False, pool=pool))
    try:
        deadline = time.monotonic() + 60
        while not list(tmp_path.glob("*/pid")) or not next(tmp_path.glob("*/pid")).read_text():
            assert time.monotonic() < deadline and not running.done(), "the program never started"
            await asyncio.sleep(0.05)
        pid = int(next(tmp_path.glob("*/pid")).read_text())
        running.cancel()
        with pytest.raises(asyncio.CancelledError):
            await running
        for _ in range(100):  # killed, then reaped by its parent
            try:
                os.kill(pid, 0)
            except ProcessLookupError:
                break
            await asyncio.sleep(0.05)
        else:
            pytest.fail(f"program {pid} still runs after its execution was cancelled")
    finally:
        if pool is not None:
            await pool.close()


async def test_a_closed_fork_server_starts_no_new_one() -> None:
    """Executions that come late (after the run closed its services) fail instead of leaving a
    fork server behind that nobody stops."""
    from meceng.tools.executor import child_env
    from meceng.tools.warm import WarmPool

    pool = WarmPool(child_env())
    await pool.start()
    await pool.close()
    with pytest.raises(RuntimeError, match="closed"):
        await pool.start()
    assert not os.path.exists(pool.socket_path)


def test_reading_a_trajectory_waits_for_the_parse_lock(tmp_path: Path) -> None:
    """numpy reads an .npy header with ast.literal_eval, which races any other parse in CPython
    3.11 ('AST constructor recursion depth mismatch'): the parent reads results behind the lock."""
    import json as json_module
    import threading

    import numpy as np

    from meceng import syntax
    from meceng.tools.execution import ExecutionLimits
    from meceng.tools.executor import _collect

    token = "t0k3n"
    (tmp_path / f"result-{token}.json").write_text(json_module.dumps({"stage": "solved", "error": None}))
    np.save(tmp_path / f"trajectory-{token}.npy", np.zeros((3, 2)))
    done = threading.Event()
    with syntax.parsing():
        reader = threading.Thread(target=lambda: (_collect(tmp_path, 0, False, b"", b"", 0.0, None,
                                                           ExecutionLimits(), token), done.set()))
        reader.start()
        assert not done.wait(0.3)
    reader.join(10)
    assert done.is_set()
