"""The scripted models of a run: ``--model scripted:p=P`` (its wrong answers are the tasks' drafts)
and ``--model designer`` (a design task's estimate, corrected with the tools).

The backends live with the others (``llm/backend_scripted.py``, ``llm/backend_designer.py``); what
they need comes from the task room, which the LLM room may not import, so the run hands it over
here, keyed by instance.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from meceng.llm.backend_designer import DesignerBackend, DesignPlan
from meceng.llm.backend_scripted import ScriptedBackend, ScriptedDraft
from meceng.llm.types import Backend, LLMSettings
from meceng.tasks.base import TaskInstance
from meceng.tasks.design_base import DesignTask
from meceng.tasks.drafts import candidate_drafts


def scripted_backend(settings: LLMSettings, instances: list[TaskInstance]) -> Backend:
    """The scripted model for these instances: the designer, or the drafts' model with every draft
    each one's ground truth admits, in the order ``tasks/drafts.py`` writes them (the same-fault
    model takes the first)."""
    if settings.model == "designer":
        return DesignerBackend({i.key: design_plan(i.design) for i in instances if i.design is not None})
    drafts = {instance.key: tuple(ScriptedDraft(d.id, d.label, d.program) for d in candidate_drafts(instance))
              for instance in instances}
    return ScriptedBackend(settings.model, settings.seed, drafts)


def design_plan(task: DesignTask) -> DesignPlan:
    """What the designer knows: the prompt's variables, target and tolerance, the task model's
    estimate (as a function of the quantity's value) and its measurement."""

    def estimate(value: float) -> dict[str, float]:
        try:
            return {k: float(v) for k, v in task.model.estimate(task.values, value).items()}
        except (ValueError, ZeroDivisionError, FloatingPointError, OverflowError):
            return {v.name: float("nan") for v in task.variables}

    measure: Callable[[np.ndarray, np.ndarray, dict[str, float]], float] = task.measure
    return DesignPlan(tuple((v.name, v.low, v.high) for v in task.variables), task.target, task.tolerance,
                      estimate, measure)
