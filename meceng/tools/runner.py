"""The child side of the executor: runs one program under the Exudyn harness.

Invoked as ``python -m meceng.tools.runner JOB.json`` in a fresh scratch directory. The harness
patches Exudyn before the program runs:

* ``MainSystem.Assemble`` records the stages *reached assemble* / *finished assemble* and
  remembers the system;
* every solver call of the program (``mbs.SolveDynamic``, ``exu.SolveDynamic``, static solves)
  hands control back to the harness instead of solving, so the program's own solver settings
  never take effect: the ground truth's simulation block is run instead, on the same system —
  this is how the paper's "solver block injected from the ground truth" is done without
  rewriting text;
* renderers and viewers become no-ops (headless they abort the process);
* a post-step hook records ``q_ref + q`` of all ODE2 coordinates at every step.

Progress is appended to ``stage.log`` as it happens, so a crash (segfault, kill) still tells how
far the program got. The result goes to ``result.json`` and ``trajectory.npy``.
"""

from __future__ import annotations

import json
import os
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from meceng.tools import guard
from meceng.tools.errors import PROGRAM_NAME, describe_exception
from meceng.tools.harness import HandOver, Harness, capture_items, capture_sensors, system_summary
from meceng.tools.pinning import pin_eigensolvers

# ----------------------------------------------------------------------------- main


def run(job_path: Path) -> int:
    job = json.loads(job_path.read_text())
    job_path.unlink()  # the token in it must not be readable by the program
    workdir = job_path.parent
    if job.get("check") and _refused(job, workdir):
        return 0
    if job.get("mode") == "part":
        from meceng.tools.part_runner import run_part

        return run_part(job, workdir)
    harness = Harness(workdir, token=str(job.get("token", "")))
    result: dict[str, Any] = {"stage": "started", "error": None, "error_type": None, "warnings": []}
    t_start = time.perf_counter()
    try:
        harness.install()
    except Exception as exc:
        result.update(error=f"harness setup failed: {exc}", error_type=type(exc).__name__)
        _write_result(workdir, result, harness)
        return 3

    namespace: dict[str, Any] = {"__name__": "__main__", "__file__": str(workdir / PROGRAM_NAME)}
    program_error: BaseException | None = None
    if job.get("guard", True):
        harness.guard = guard.install(str(workdir), harness.warnings.append)
    try:
        code = compile(job["program"], str(workdir / PROGRAM_NAME), "exec")
        harness.guard(True)
        exec(code, namespace)
    except HandOver:
        pass
    except SystemExit as exc:
        program_error = exc
    except BaseException as exc:  # everything the program raises is a verdict
        program_error = exc
    finally:
        harness.guard(False)

    if program_error is not None and harness.stage != "finished_assemble":
        result.update(describe_exception(program_error, workdir, job["program"]), stage=harness.stage)
        result["program_time"] = time.perf_counter() - t_start
        _write_result(workdir, result, harness)
        return 0
    if program_error is not None:
        harness.warnings.append(
            f"program raised after assemble: {describe_exception(program_error, workdir, job['program'])['error']}")
    if harness.mbs is None or harness.stage not in ("finished_assemble",):
        result.update(stage=harness.stage, error="the program never called mbs.Assemble()",
                      error_type="NoAssemble")
        result["program_time"] = time.perf_counter() - t_start
        _write_result(workdir, result, harness)
        return 0

    result["network"] = os.environ.get("MECENG_NETWORK", "shared")
    result["items"] = capture_items(harness.mbs, harness.api)
    result["system"] = system_summary(harness.mbs, harness.api)
    result["program_time"] = time.perf_counter() - t_start
    if job.get("inspect_times") is not None:
        harness.inspector = start_inspection(harness, job["inspect_times"], result, bool(job.get("inspect_loads")))
    if job.get("motion") is not None:
        harness.motion = start_motion(harness, job["motion"], result)
    harness.sensor_rows = job.get("sensor_rows")
    t_solve = time.perf_counter()
    try:
        harness.guard(True)  # the program's user functions run inside the solver
        harness.solve(job["sim_block"], namespace)
    except BaseException as exc:
        result.update(describe_exception(exc, workdir, job["program"]))
    finally:
        harness.guard(False)
    result["solve_time"] = time.perf_counter() - t_solve
    if harness.sensor_rows:
        try:
            result["sensors"] = capture_sensors(harness.mbs, harness.api, int(harness.sensor_rows))
        except Exception as exc:
            result["warnings"].append(f"sensors unavailable: {exc}")
    if harness.inspector is not None:
        result["inspection"] = harness.inspector.result()
    result["stage"] = harness.stage
    _write_result(workdir, result, harness)
    return 0


def start_inspection(harness: Harness, times: list[float], result: dict[str, Any], loads: bool = False) -> Any:
    """The inspector's recorder with the state at t = 0; None (and a warning) if Exudyn refuses."""
    from meceng.tools.inspection import InspectionRecorder

    def start() -> Any:
        recorder = InspectionRecorder(harness.mbs, harness.api, list(times), loads=loads)
        recorder.take(0.0, initial=True)
        return recorder

    return _start_recorder(harness, result, start, "model inspector")


def start_motion(harness: Harness, grid: dict[str, Any], result: dict[str, Any]) -> Any:
    """The bodies' motion recorder with the state at t = 0; None (and a warning) if Exudyn refuses."""
    from meceng.tools.motion import MotionRecorder

    def start() -> Any:
        recorder = MotionRecorder(harness.mbs, harness.api, float(grid["end"]), int(grid["samples"]))
        recorder.after_step(0.0, initial=True)
        return recorder

    return _start_recorder(harness, result, start, "motion recorder")


def _start_recorder(harness: Harness, result: dict[str, Any], start: Callable[[], Any], what: str) -> Any:
    """A recorder made and given its first state under the program's guard (the system is the
    program's); a recorder Exudyn refuses is a warning, never a failed run."""
    try:
        harness.guard(True)
        return start()
    except Exception as exc:
        result.setdefault("warnings", []).append(f"{what} unavailable: {exc}")
        return None
    finally:
        harness.guard(False)


def _refused(job: dict[str, Any], workdir: Path) -> bool:
    """The static check, here in the worker before the program runs (in the parent it was the
    largest serial cost of a task: ~14 ms of AST walks that no worker could take over)."""
    from meceng.tools.safety import ALLOWED_IMPORT_ROOTS, PART_IMPORT_ROOTS, check_program

    roots = PART_IMPORT_ROOTS if job.get("mode") == "part" else ALLOWED_IMPORT_ROOTS
    verdict = check_program(job["program"], roots)
    if verdict:
        return False
    where = f" (line {verdict.line})" if verdict.line else ""
    token = str(job.get("token", ""))
    tmp = workdir / f"result-{token}.json.tmp"
    tmp.write_text(json.dumps({"stage": "refused", "error": f"{verdict.reason}{where}", "error_kind": "safety",
                               "token": token}))
    os.replace(tmp, workdir / f"result-{token}.json")
    return True


def _write_result(workdir: Path, result: dict[str, Any], harness: Harness) -> None:
    harness.guard(False)
    result["token"] = harness.token
    result["warnings"] = result.get("warnings", []) + harness.warnings
    rows = [r for r in harness.rows if r[1] is not None]
    if rows:
        times = np.array([t for t, _ in rows], dtype=float)
        width = max(len(q) for _, q in rows)
        if all(len(q) == width for _, q in rows):
            q = np.vstack([r for _, r in rows])
            np.save(workdir / f"trajectory-{harness.token}.npy", np.column_stack([times, q]))
            result["trajectory_rows"] = len(rows)
    if harness.motion is not None:
        result["motion"] = {"bodies": harness.motion.bodies, "failed": harness.motion.failed}
        np.savez(workdir / f"motion-{harness.token}.npz", **harness.motion.arrays())
    tmp = workdir / f"result-{harness.token}.json.tmp"
    tmp.write_text(json.dumps(result))
    os.replace(tmp, workdir / f"result-{harness.token}.json")


_CLONE_NEWUSER = 0x10000000
_CLONE_NEWNET = 0x40000000


def unshare_network() -> str:
    """Move this process into an empty network namespace (no interface, not even loopback).

    Works as root, or unprivileged where user namespaces are enabled; elsewhere the audit hook's
    socket refusal is the remaining barrier. Done first thing, while the process has one thread.
    """
    import ctypes

    try:
        libc = ctypes.CDLL(None, use_errno=True)
    except OSError:
        return "unavailable"
    if libc.unshare(_CLONE_NEWNET) == 0:
        return "netns"
    if libc.unshare(_CLONE_NEWUSER | _CLONE_NEWNET) == 0:
        return "userns+netns"
    return "refused by the kernel"


def main() -> None:
    if len(sys.argv) != 2:
        sys.stderr.write("usage: python -m meceng.tools.runner JOB.json\n")
        raise SystemExit(2)
    os._exit(enter(Path(sys.argv[1])))


def enter(job_path: Path) -> int:
    """Shared entry of the cold and the warm child: network isolation, then the harness."""
    try:
        isolate = json.loads(job_path.read_text()).get("isolate_network", True)
    except (OSError, ValueError):
        isolate = True
    if isolate:
        os.environ["MECENG_NETWORK"] = unshare_network()
    pin_eigensolvers()  # the same ARPACK start vector in every child, cold or warm (tools/pinning.py)
    code = run(job_path)
    sys.stdout.flush()
    sys.stderr.flush()
    return code


if __name__ == "__main__":
    main()
