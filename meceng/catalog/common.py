"""What the level 1-2 component examples share: a complete program around a model snippet."""

from __future__ import annotations

from meceng.catalog.component import text_block
from meceng.tasks.base import PREAMBLE, SimSettings


def rigid_example(model: str, end_time: float = 1.0, steps: int = 1000, extra: tuple[str, ...] = ()) -> str:
    """A complete program: preamble, model, assemble, and the same simulation block as the ground truths."""
    sim = SimSettings(end_time=end_time, steps=steps, extra=extra)
    return f"{PREAMBLE}\n{text_block(model)}\n\nmbs.Assemble()\n\n{sim.block()}"
