"""The preflight: can this machine grade the chosen levels? Asked before the first LLM request.

A stack that cannot grade (Exudyn's compiled module missing ``libGL.so.1`` on a headless GPU
image) used to be found only after every request was spent: each record said "harness setup
failed", after 200 requests and 51,200 generated tokens. The preflight runs, in the sandbox
exactly as the tasks will (the run's evaluator: its executor, environment, limits and worker
slots), one import probe of the simulation stack the levels need and one ground truth per task
kind (rigid, part, assembly), and stops with one message that names the missing system library
and the package that brings it. Only successes are remembered (per process, keyed by the kinds,
the executor and the child's environment), so a sweep's runs and the test suite pay it once and
a failure is always asked again.
"""

from __future__ import annotations

import asyncio
import re
import tempfile
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path

from meceng.eval.chain import Tolerances
from meceng.llm.types import LOCAL_BACKENDS
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.warm import WarmPool

from .evaluation import Evaluator
from .settings import RunSettings

KINDS = ("rigid", "part", "assembly")
#: what a kind's programs import (a rigid task Exudyn only; parts mesh with Netgen/NGSolve and are
#: compared with PyMeshLab; an assembly loads the reduced parts into Exudyn)
MODULES = {"rigid": ("exudyn",), "part": ("exudyn", "ngsolve", "netgen.occ", "pymeshlab"),
           "assembly": ("exudyn", "ngsolve", "netgen.occ", "pymeshlab")}

#: the system libraries the compiled modules of exudyn, netgen/ngsolve and pymeshlab load (``ldd``
#: on their ``.so`` files), with the package that brings each: Debian/Ubuntu, RHEL/Fedora. On
#: Debian ``libgl1`` pulls in libglx0, libglvnd0, libx11-6, libxcb1, libxau6 and libxdmcp6.
SYSTEM_LIBRARIES: dict[str, tuple[str, str]] = {
    "libGL.so": ("libgl1", "mesa-libGL"),
    "libGLX.so": ("libglx0", "libglvnd-glx"),
    "libGLdispatch.so": ("libglvnd0", "libglvnd"),
    "libGLU.so": ("libglu1-mesa", "mesa-libGLU"),
    "libEGL.so": ("libegl1", "libglvnd-egl"),
    "libX11.so": ("libx11-6", "libX11"),
    "libXext.so": ("libxext6", "libXext"),
    "libXrender.so": ("libxrender1", "libXrender"),
    "libxcb.so": ("libxcb1", "libxcb"),
    "libXau.so": ("libxau6", "libXau"),
    "libXdmcp.so": ("libxdmcp6", "libXdmcp"),
    "libSM.so": ("libsm6", "libSM"),
    "libICE.so": ("libice6", "libICE"),
    "libbsd.so": ("libbsd0", "libbsd"),
    "libmd.so": ("libmd0", "libmd"),
    "libuuid.so": ("libuuid1", "libuuid"),
    "libz.so": ("zlib1g", "zlib"),
    "libcom_err.so": ("libcom-err2", "libcom_err"),
    "libgomp.so": ("libgomp1", "libgomp"),
    "libstdc++.so": ("libstdc++6", "libstdc++"),
    "libgcc_s.so": ("libgcc-s1", "libgcc"),
}
_LIBRARY = re.compile(r"(lib[\w+.-]*?\.so(?:\.\d+)*)")


@dataclass(frozen=True)
class StackCheck:
    """One line of the preflight (and of ``meceng doctor``'s table)."""

    name: str
    ok: bool
    detail: str


class StackUnusable(RuntimeError):
    """This machine cannot grade the chosen levels; the message says why and what to install."""


def missing_library(text: str) -> str | None:
    """The system library an error names, with the package that brings it; None: none named."""
    for match in _LIBRARY.finditer(text or ""):
        name = match.group(1)
        base = re.sub(r"(\.\d+)+$", "", name)
        if base in SYSTEM_LIBRARIES:
            debian, rhel = SYSTEM_LIBRARIES[base]
            return f"{name} (Debian/Ubuntu: apt-get install {debian}; RHEL/Fedora: dnf install {rhel})"
        return f"{name} (find the package that provides it: apt-file search {name} / dnf provides '*/{name}')"
    return None


def unlinked_libraries(modules: tuple[str, ...]) -> dict[str, list[str]]:
    """System libraries (those of ``SYSTEM_LIBRARIES``) the compiled modules of ``modules`` need
    and the dynamic linker does not find (``ldd``'s "not found"), per module; found without
    importing anything. Only the system's: the wheels' own libraries (OpenCASCADE's ``libTK*``,
    OpenBLAS, the optional CUDA ones) are found at import time and ``ldd`` misses them. Empty
    where ``ldd`` is missing (not glibc): the import probe still tells."""
    import glob
    import importlib.util
    import shutil
    import subprocess

    ldd = shutil.which("ldd")
    missing: dict[str, list[str]] = {}
    for name in dict.fromkeys(m.split(".")[0] for m in modules):
        spec = importlib.util.find_spec(name)
        if ldd is None or spec is None or not spec.submodule_search_locations:
            continue
        for folder in spec.submodule_search_locations:
            for library in sorted(glob.glob(f"{folder}/*.so")):
                try:
                    out = subprocess.run([ldd, library], capture_output=True, text=True, timeout=30).stdout
                except (OSError, subprocess.SubprocessError):
                    continue
                for line in out.splitlines():
                    library_name = line.split()[0] if line.split() else ""
                    if "not found" in line and re.sub(r"(\.\d+)+$", "", library_name) in SYSTEM_LIBRARIES:
                        missing.setdefault(name, []).append(library_name)
    return {name: sorted(set(libs)) for name, libs in missing.items()}


def kinds_of(instances: list[TaskInstance]) -> tuple[str, ...]:
    present = {i.kind for i in instances}
    return tuple(k for k in KINDS if k in present)


def probe_program(modules: tuple[str, ...]) -> str:
    """A program that imports each module and says which failed (one line each on stdout)."""
    return ("import importlib\n"
            f"for name in {list(modules)!r}:\n"
            "    try:\n"
            "        importlib.import_module(name)\n"
            "        print('IMPORTED', name, flush=True)\n"
            "    except Exception as exc:\n"
            "        print('FAILED', name, type(exc).__name__, str(exc).replace(chr(10), ' '), flush=True)\n")


def _failure(execution: Execution) -> str:
    return " ".join(p for p in (execution.error, execution.stderr_tail[-600:]) if p) or f"stage {execution.stage}"


async def _probe(evaluator: Evaluator, modules: tuple[str, ...], example: TaskInstance) -> list[StackCheck]:
    limits = replace(evaluator.limits, inspect_times=None)
    run = await execute(probe_program(modules), example.sim.block() if example.kind != "part" else "",
                        limits, check=False, pool=evaluator.pool, slots=evaluator.slots)
    said = {line.split()[1]: line for line in run.stdout_tail.splitlines()
            if line.startswith(("IMPORTED ", "FAILED ")) and len(line.split()) > 1}
    checks = []
    for name in modules:
        line = said.get(name)
        if line is None:  # the program never ran: the harness's own import of exudyn failed
            checks.append(StackCheck(f"import {name}", False, _failure(run)))
        else:
            ok = line.startswith("IMPORTED")
            checks.append(StackCheck(f"import {name}", ok, "imported" if ok else line.partition(name)[2].strip()))
    return checks


async def _ground_truth(evaluator: Evaluator, instance: TaskInstance) -> StackCheck:
    """One ground truth of the kind, run as a task's would be, but past the reference store and
    the run's reference cache (a preflight's execution is never a graded task's)."""
    name = f"ground truth {instance.kind} ({instance.key})"
    try:
        if instance.kind == "part":
            run = await evaluator.execute_part(instance.reference_program, instance, check=False)
            ok = run.stage == "reduced" and run.error is None
        else:
            with tempfile.TemporaryDirectory(prefix="meceng-preflight-") as folder:
                files = (await evaluator.ground_truth_parts(instance, Path(folder))
                         if instance.kind == "assembly" else None)
                run = await evaluator.execute(instance.reference_program, instance, check=False, files=files)
            ok = run.solved
    except RuntimeError as exc:  # an assembly's ground-truth part failed
        return StackCheck(name, False, str(exc))
    detail = f"{run.stage} in {run.wall_time:.1f} s" if ok else _failure(run)
    return StackCheck(name, ok, detail)


@cache
def _cheapest(kind: str) -> TaskInstance:
    """The instance of ``kind`` likely quickest to run, among every task of the registry (the check
    is of the stack, not of the run's tasks): fewest parts, then the shortest ground-truth program
    (a short program builds a small system or part). Design tasks are left out: making one runs its
    reference in this process, which is what the check is about to find out can work."""
    registry = default_registry()
    models = [m for m in registry.select(None, None) if m.level != "4"]
    return min((i for i in registry.instances(models, 0, 1) if i.kind == kind),
               key=lambda i: (len(i.parts or ()), len(i.reference_program)))


async def check_stack(instances: list[TaskInstance], evaluator: Evaluator) -> list[StackCheck]:
    """The import probe and one ground truth per kind among ``instances``, in the run's sandbox."""
    kinds = kinds_of(instances)
    if not kinds:
        return []
    modules = tuple(dict.fromkeys(m for k in kinds for m in MODULES[k]))
    checks = await _probe(evaluator, modules, _cheapest(kinds[0]))
    if all(c.ok for c in checks):
        # an assembly's ground truth first makes its parts from theirs: it stands for the part kind too
        runs = [k for k in kinds if not (k == "part" and "assembly" in kinds)]
        checks.extend(await asyncio.gather(*(_ground_truth(evaluator, _cheapest(k)) for k in runs)))
    return checks


def explain(checks: list[StackCheck], kinds: tuple[str, ...]) -> str:
    """The one message a failed preflight stops with."""
    failed = [c for c in checks if not c.ok]
    lines = [f"this machine cannot grade the chosen tasks ({', '.join(kinds)}): stopped before any LLM request"]
    for check in failed:
        lines.append(f"  {check.name}: {check.detail[:400]}")
    libraries = dict.fromkeys(lib for c in failed if (lib := missing_library(c.detail)))
    for library in libraries:
        lines.append(f"  missing system library {library}")
    if not libraries:
        lines.append("  (run `meceng doctor` for the whole table)")
    return "\n".join(lines)


_PASSED: set[tuple[object, ...]] = set()  # (kind, fork server?, child environment) that passed


async def ensure_stack(instances: list[TaskInstance], evaluator: Evaluator) -> None:
    """Raise ``StackUnusable`` when the sandbox cannot import the stack or run a ground truth of
    every kind among ``instances``; the kinds that passed are remembered for this process."""
    where = (evaluator.pool is not None, tuple(sorted(child_env().items())))
    todo = [i for i in instances if (i.kind, *where) not in _PASSED]
    kinds = kinds_of(todo)
    if not kinds:
        return
    checks = await check_stack(todo, evaluator)
    if not all(c.ok for c in checks):
        raise StackUnusable(explain(checks, kinds))
    _PASSED.update((kind, *where) for kind in kinds)


async def ensure_sweep_stack(runs: list[RunSettings], pool: WarmPool | None, slots: asyncio.Semaphore) -> None:
    """The preflight once for a whole sweep (the union of its runs' kinds), on its shared fork
    server and worker slots, before any run starts; gold runs ask no server and are left out."""
    runs = [s for s in runs if s.preflight and s.llm.backend not in LOCAL_BACKENDS]
    if not runs:
        return
    registry = default_registry()
    instances = [i for s in runs for i in registry.instances(registry.select(s.levels, s.only or None), s.seed, 1)]
    evaluator = Evaluator(1, ExecutionLimits(timeout_s=max(s.exec_timeout_s for s in runs)), Tolerances(),
                          pool=pool, slots=slots, part_timeout_s=max(s.part_timeout_s for s in runs))
    await ensure_stack(instances, evaluator)
