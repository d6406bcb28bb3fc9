"""What one program run may use (``ExecutionLimits``) and what it produced (``Execution``): the
types the executor hands to the evaluation, the agent's tools and the pure verdicts in ``eval/``.

A program is graded by the CPU time it uses, not by the wall clock: on a server that shares its
cores with an inference server and other sweeps, a wall-clock limit grades the machine's load
(issue 45). The wall clock still bounds every run, well above the CPU limit, so that a program
that sleeps or blocks is stopped; a run stopped there with its CPU time under the limit was the
machine's failure (``error_kind == "wall_timeout"``), never the model's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class ExecutionLimits:
    """Hard limits of one program run.

    ``timeout_s`` is the CPU time the program may use (all its threads, and the processes it
    started and waited for), enforced by the kernel (RLIMIT_CPU, in whole seconds: rounded up);
    the paper's 60 s were measured on an unloaded workstation, where CPU and wall time agree.
    ``wall_timeout_s`` bounds the run on the wall clock (None: ``WALL_FACTOR`` times the CPU limit
    plus ``WALL_MARGIN_S``): what it stops is an infrastructure failure unless the CPU limit was
    reached as well.
    """

    timeout_s: float = 60.0
    wall_timeout_s: float | None = None
    memory_bytes: int = 6 * 1024**3
    file_bytes: int = 256 * 1024**2
    output_bytes: int = 64 * 1024
    keep_scratch: bool = False
    guard: bool = True
    isolate_network: bool = True
    mode: str = "rigid"  # "part": a level 3a program, captured by the part runner
    n_modes: int = 6
    save_fem_to: str | None = None  # part mode: keep the program's reduced FEMinterface here (.npz)
    # the model inspector: body and marker states at t = 0 and at these times (None: not recorded)
    inspect_times: tuple[float, ...] | None = None
    # the inspector also calls the program's user-function loads at those states, to show their values:
    # the agent's tools only; a graded run never calls a program's function outside its solver (a
    # function that keeps state would then move differently)
    inspect_loads: bool = False
    # the behaviour comparison: every body's motion on a grid of (end time, samples) (None: not recorded)
    motion_grid: tuple[float, int] | None = None
    # the agent's simulate: the program's own sensors stored over the run, at most this many rows each
    # (None: not recorded; the sensors then only observe, as in every graded run)
    sensor_rows: int | None = None

    @property
    def cpu_limit_s(self) -> int:
        """The CPU seconds the kernel allows (RLIMIT_CPU counts whole seconds)."""
        return max(1, math.ceil(self.timeout_s))

    @property
    def wall_s(self) -> float:
        """The wall-clock bound: room for a program that gets a third of a core on a loaded machine."""
        if self.wall_timeout_s is not None:
            return self.wall_timeout_s
        return WALL_FACTOR * self.timeout_s + WALL_MARGIN_S


#: the default wall-clock bound is this many times the CPU limit, plus the margin (start-up, I/O)
WALL_FACTOR = 3.0
WALL_MARGIN_S = 10.0


@dataclass(frozen=True)
class Execution:
    """What running one program produced.

    ``stage`` is the last stage reached: refused (static check), started, reached_assemble,
    finished_assemble, solver_started, solved. ``error_kind`` tells infrastructure from program
    faults: safety, exception, timeout (the CPU limit: the program's), wall_timeout (stopped by
    the wall clock with its CPU time under the limit: the machine's), crash, no_result.
    ``cpu_time`` is the child's own CPU time (user + system, every thread, from ``wait4``; None
    when the program never ran in a child), ``wall_time`` the child's lifetime.
    """

    stage: str
    error: str | None = None
    error_kind: str | None = None
    error_line: int | None = None  # the program's line the error was raised at
    items: dict[str, list[dict[str, Any]]] | None = None
    system: dict[str, Any] = field(default_factory=dict)
    times: np.ndarray | None = None
    trajectory: np.ndarray | None = None
    warnings: tuple[str, ...] = ()
    part: dict[str, Any] | None = None
    surface: tuple[np.ndarray, np.ndarray] | None = None
    fine_surface: tuple[np.ndarray, np.ndarray] | None = None  # the solid's surface, meshed finer (metric)
    part_times: dict[str, float] = field(default_factory=dict)
    fem_file: str | None = None
    stdout_tail: str = ""
    stderr_tail: str = ""
    returncode: int | None = None
    wall_time: float = 0.0
    cpu_time: float | None = None
    solve_time: float | None = None
    inspection: dict[str, Any] | None = None  # the model inspector's states (ExecutionLimits.inspect_times)
    # the bodies' motion (ExecutionLimits.motion_grid): "bodies" (index, type, mass, inertia, com),
    # "t" (n,) and "states" (n, bodies, 18: centre of mass, velocity, angular velocity, rotation)
    motion: dict[str, Any] | None = None
    # the program's sensors (ExecutionLimits.sensor_rows): index, name, what it reads, rows [t, values...]
    sensors: list[dict[str, Any]] | None = None

    @property
    def finished_assemble(self) -> bool:
        return self.stage in ("finished_assemble", "solver_started", "solved")

    @property
    def solved(self) -> bool:
        return self.stage == "solved" and self.error is None

    @property
    def lost_to_machine(self) -> bool:
        """Stopped by the wall clock before its CPU time reached the limit: not the program's doing."""
        return self.error_kind == "wall_timeout"

    def summary(self) -> dict[str, Any]:
        """The JSON-friendly part, for the task record."""
        return {
            "stage": self.stage,
            "error": self.error,
            "error_kind": self.error_kind,
            "error_line": self.error_line,
            "warnings": list(self.warnings),
            "returncode": self.returncode,
            "wall_time": round(self.wall_time, 4),  # kept for readers of older records: = wall_s
            "cpu_s": None if self.cpu_time is None else round(self.cpu_time, 4),
            "wall_s": round(self.wall_time, 4),
            "solve_time": None if self.solve_time is None else round(self.solve_time, 4),
            "steps": None if self.times is None else len(self.times),
            "system": self.system,
            "stderr_tail": self.stderr_tail[-2000:],
            **({"part": self.part, "part_times": self.part_times, "fem_file": self.fem_file}
               if self.part is not None else {}),
        }
