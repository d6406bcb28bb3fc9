"""Run a program and record every body's motion: the one step the behaviour verdict, the agent's
``compare`` tool and a consensus of several programs all need before they compare motions
(``eval/behaviour.py``, ``eval/agreement.py``).

The recording itself happens in the child (``tools/motion.MotionRecorder``, asked for by
``ExecutionLimits.motion_grid``); here are only the grid every caller uses and the call, so that two
programs compared with each other are sampled at the same times.
"""

from __future__ import annotations

import asyncio
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path

from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import execute
from meceng.tools.warm import WarmPool

#: Samples of the bodies' motion per execution (fewer when a system has many bodies:
#: ``tools/motion.MOTION_BUDGET``).
MOTION_SAMPLES = 201
#: A program's own time-stepping error is measured against a run with this many times the steps.
REFINE = 2


def recording(limits: ExecutionLimits, end_time: float, samples: int = MOTION_SAMPLES) -> ExecutionLimits:
    """``limits`` with the motion recorded on ``samples`` points from 0 to ``end_time``."""
    return replace(limits, motion_grid=(end_time, samples))


async def run_recorded(program: str, sim_block: str, end_time: float, limits: ExecutionLimits | None = None, *,
                       check: bool = True, pool: WarmPool | None = None, files: Mapping[str, Path] | None = None,
                       slots: asyncio.Semaphore | None = None, samples: int = MOTION_SAMPLES) -> Execution:
    """Run ``program`` with ``sim_block`` as its solver block (the caller's: the description's end
    time and steps, or ``REFINE`` times the steps for a program's own step error) and record its
    motion; ``Execution.motion`` is None when the program never reached its solve."""
    return await execute(program, sim_block, recording(limits or ExecutionLimits(), end_time, samples),
                         check=check, pool=pool, files=files, slots=slots)
