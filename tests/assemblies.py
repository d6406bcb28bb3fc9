"""Helpers for level 3b tests: make an assembly instance's parts, build its ground truth in-process."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import exudyn as exu
import numpy as np

from meceng.tasks.base import TaskInstance
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import execute


async def saved_parts(instance: TaskInstance, folder: Path) -> dict[str, Path]:
    """Mesh and reduce every part of the assembly (ground truths, isolated) and keep them as .npz."""
    files = {}
    for slot, part in instance.parts:
        path = folder / f"{slot}.npz"
        if not path.exists():
            run = await execute(part.reference_program, "", ExecutionLimits(mode="part", timeout_s=300,
                                                                             save_fem_to=str(path)), check=False)
            assert run.error is None and run.fem_file == str(path), run.error
        files[f"{slot}.npz"] = path
    return files


async def run_assembly(instance: TaskInstance, files: dict[str, Path], program: str | None = None) -> Execution:
    """Run the assembly's ground truth (or ``program``) as the pipeline does."""
    return await execute(program or instance.reference_program, instance.sim.block(), ExecutionLimits(timeout_s=300),
                         check=program is not None, files=files)


def build(instance: TaskInstance, files: dict[str, Path]) -> dict[str, Any]:
    """Execute the ground truth up to (not including) ``mbs.Assemble()`` in this process, loading
    the parts from ``files``; returns the namespace (``mbs``, ``SC``, the model's variables)."""
    program = instance.reference_program.split("\nmbs.Assemble()")[0]
    for name, path in files.items():
        program = program.replace(f"'{name}'", repr(str(path)))
    namespace: dict[str, Any] = {"__name__": "assembly"}
    exec(compile(program, f"<{instance.key}>", "exec"), namespace)
    return namespace


def joints(mbs: Any) -> list[int]:
    """The generic joints of a system, in creation order."""
    return [i for i in range(mbs.systemData.NumberOfObjects()) if mbs.GetObject(i)["objectType"] == "JointGeneric"]


def joint_offsets(mbs: Any) -> list[float]:
    """Distance between the two markers of every joint (after mbs.Assemble())."""
    position = exu.OutputVariableType.Position
    offsets = []
    for joint in joints(mbs):
        m0, m1 = mbs.GetObject(joint)["markerNumbers"]
        offsets.append(float(np.linalg.norm(np.subtract(mbs.GetMarkerOutput(m0, position),
                                                        mbs.GetMarkerOutput(m1, position)))))
    return offsets
