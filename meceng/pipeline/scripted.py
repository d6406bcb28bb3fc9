"""The scripted model of a run (``--model scripted:p=P``): its wrong answers are the tasks' drafts.

The backend lives with the others (``llm/backend_scripted.py``); the drafts come from the task room,
which the LLM room may not import, so the run hands them over here, keyed by instance.
"""

from __future__ import annotations

from meceng.llm.backend_scripted import ScriptedBackend, ScriptedDraft
from meceng.llm.types import LLMSettings
from meceng.tasks.base import TaskInstance
from meceng.tasks.drafts import candidate_drafts


def scripted_backend(settings: LLMSettings, instances: list[TaskInstance]) -> ScriptedBackend:
    """The scripted model for these instances: every draft each one's ground truth admits, in the
    order ``tasks/drafts.py`` writes them (the same-fault model takes the first)."""
    drafts = {instance.key: tuple(ScriptedDraft(d.id, d.label, d.program) for d in candidate_drafts(instance))
              for instance in instances}
    return ScriptedBackend(settings.model, settings.seed, drafts)
