"""The prompts a model gets for one task instance, as a run would send them, for reading them
(``meceng tasks prompt``) and for checking them (the prompt lint in ``tests/test_prompt_lint.py``).

Nothing is written twice: the templates come from the run settings (a part always takes the part
templates), the catalog from the task kind and the texts from the functions the LLM steps and the
agent loop build their prompts with. The code prompt is the one after choosing exactly the task's
required components.
"""

from __future__ import annotations

from dataclasses import dataclass

from meceng.agents.loop import agent_prompt
from meceng.agents.steps import generation_prompt, selection_prompt
from meceng.catalog.catalogs import catalog_for
from meceng.tasks.base import TaskInstance

from .settings import RunSettings


@dataclass(frozen=True)
class RenderedPrompt:
    """One prompt as the model reads it: whose (instance key), which step, which template."""

    key: str
    kind: str
    stage: str  # "select" or "code"
    template: str
    text: str


def instance_prompts(instance: TaskInstance, settings: RunSettings) -> list[RenderedPrompt]:
    """Every prompt of the instance in the order a run sends them: an assembly's parts first (a part
    the assembly uses twice once), then its own; per task the selection, then the code prompt."""
    parts = list({part.key: part for _, part in instance.parts}.values())
    return [prompt for task in (*parts, instance) for prompt in _task_prompts(task, settings)]


def _task_prompts(instance: TaskInstance, settings: RunSettings) -> list[RenderedPrompt]:
    catalog = catalog_for(instance.kind)
    select_template, code_template = settings.templates(instance.kind)
    names = instance.required_components
    if settings.agent == "loop":
        code = agent_prompt(instance, catalog, names, code_template)
    else:
        code = generation_prompt(instance, catalog, names, code_template)
    return [RenderedPrompt(instance.key, instance.kind, "select", select_template,
                           selection_prompt(instance, catalog, select_template)),
            RenderedPrompt(instance.key, instance.kind, "code", code_template, code)]
