"""The settings of a run: what defines it, written to settings.json and run.json as given."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from meceng.agents.prompts import DEFAULT_CODE, DEFAULT_PART_CODE, DEFAULT_PART_SELECT, DEFAULT_SELECT
from meceng.llm.types import LLMSettings


@dataclass(frozen=True)
class RunSettings:
    """Everything that defines a run; written to run.json as given."""

    llm: LLMSettings = field(default_factory=LLMSettings)
    levels: tuple[str, ...] = ("1", "2")
    only: tuple[str, ...] = ()
    variations: int = 3
    seed: int = 0
    out: Path = Path("runs")
    run_name: str | None = None
    workers: int = max(1, os.cpu_count() or 1)
    exec_timeout_s: float = 60.0  # CPU seconds per program; the wall clock bounds it at 3x + 10 s
    select_template: str = DEFAULT_SELECT
    code_template: str = DEFAULT_CODE
    solution_tolerance: float = 1e-5
    progress: bool = True
    resume: bool = False
    # a resume on a server the user named (--resume --host): prompts that did not fit the old
    # server's context are asked again; how a run is continued, not what it measures (not saved)
    retry_overflow: bool = False
    # check, before the first LLM request, that this machine can grade the levels (pipeline/preflight.py);
    # how a run is started, not what it measures (not saved)
    preflight: bool = True
    executor: str = "fork"
    agent: str = "pipeline"  # "pipeline": the paper's two steps; "loop": tool-calling agent that tests its code;
    # "repair": the repair benchmark (a draft with a seeded fault to find and fix); "consensus": K
    # independent programs per task grouped by behaviour, the largest group's answer (levels 1-2)
    repair_tools: bool = True  # --agent repair: the agent's tools, or a single answer
    drafts_per_task: int = 1
    samples: int = 5  # --agent consensus: independent programs per task
    # --agent consensus across models: sample k is written by model k mod M (llm/ensemble.py); empty:
    # every sample by ``llm``. When given, ``llm`` is its first model (the run's name and window)
    consensus_models: tuple[LLMSettings, ...] = ()
    max_rounds: int = 6
    token_budget: int = 30000
    part_select_template: str = DEFAULT_PART_SELECT
    part_code_template: str = DEFAULT_PART_CODE
    part_timeout_s: float = 300.0  # meshing + HCB of a part; the paper's parts take seconds
    # which task text: "paper" (says how to write the program) or "open" (the system in an engineer's
    # words, levels 1-2 only, graded by behaviour: issue 36)
    texts: str = "paper"

    @classmethod
    def from_json(cls, data: dict[str, Any], out: Path, run_name: str) -> RunSettings:
        """Rebuild the settings a run was started with (for ``--resume``)."""
        pipeline = data["pipeline"]
        return cls(
            llm=_llm(data["llm"]), levels=tuple(pipeline["levels"]), only=tuple(pipeline["only"]),
            variations=pipeline["variations"], seed=pipeline["seed"], out=out, run_name=run_name,
            workers=pipeline["workers"], exec_timeout_s=pipeline["exec_timeout_s"],
            solution_tolerance=pipeline["solution_tolerance"], select_template=data["prompt"]["select_template"],
            code_template=data["prompt"]["code_template"], resume=True,
            executor=pipeline.get("executor", "fork"), agent=pipeline.get("agent", "pipeline"),
            max_rounds=pipeline.get("max_rounds", 6), token_budget=pipeline.get("token_budget", 30000),
            repair_tools=pipeline.get("repair_tools", True), drafts_per_task=pipeline.get("drafts_per_task", 1),
            samples=pipeline.get("samples", 5),
            consensus_models=tuple(_llm(m) for m in pipeline.get("consensus_models", ())),
            part_timeout_s=pipeline.get("part_timeout_s", 300.0), texts=pipeline.get("texts", "paper"),
            part_select_template=data["prompt"].get("part_select_template", DEFAULT_PART_SELECT),
            part_code_template=data["prompt"].get("part_code_template", DEFAULT_PART_CODE),
        )

    def to_json(self) -> dict[str, Any]:
        return {
            "llm": self.llm.to_json(),
            "pipeline": {
                "executor": self.executor, "agent": self.agent, "max_rounds": self.max_rounds,
                "token_budget": self.token_budget, "repair_tools": self.repair_tools,
                "drafts_per_task": self.drafts_per_task, "samples": self.samples,
                "levels": list(self.levels), "only": list(self.only), "variations": self.variations,
                "seed": self.seed, "workers": self.workers, "exec_timeout_s": self.exec_timeout_s,
                "solution_tolerance": self.solution_tolerance, "part_timeout_s": self.part_timeout_s,
                "texts": self.texts,
                # only when given: the settings of every earlier run stay as they were
                **({"consensus_models": [m.to_json() for m in self.consensus_models]}
                   if self.consensus_models else {}),
            },
            "prompt": {"select_template": self.select_template, "code_template": self.code_template,
                       "part_select_template": self.part_select_template,
                       "part_code_template": self.part_code_template},
        }

    @property
    def sample_models(self) -> tuple[LLMSettings, ...]:
        """The models that write a consensus run's samples, in the order of the k mod M rule."""
        return self.consensus_models or (self.llm,)

    def templates(self, kind: str) -> tuple[str, str]:
        """The (selection, code) prompt templates for a task kind: parts have their own."""
        if kind == "part":
            return self.part_select_template, self.part_code_template
        return self.select_template, self.code_template


def _llm(data: dict[str, Any]) -> LLMSettings:
    return LLMSettings(**{**data, "hosts": tuple(data["hosts"])})
