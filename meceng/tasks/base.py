"""The shape of a task model and of one sampled task instance.

A *task model* is the paper's parameterized template: description text with ``{placeholders}``,
parameter ranges, the simulation components a correct answer needs, a ground-truth model written
as Exudyn code over the same parameter names, and the simulation settings. A *task instance* is
one draw of the parameters (seeded, so the same seed always gives the same instance).

The ground truth is kept as program text, not as a builder function, because the same text is
(1) the reference program saved with every run, (2) the ``gold`` backend's answer and (3) the
source of the simulation block that replaces the LLM's own. Writing it the way the description and
the component context tell an LLM to write it is what makes a faithful answer produce the same
system graph.
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass
from typing import Any

import numpy as np

#: The kinds of task text: the paper's, which says how to write the program, and an engineer's.
TEXTS = ("paper", "open")

#: Lines every program starts with; the LLM is told to use the same names.
PREAMBLE = """\
import exudyn as exu
from exudyn.utilities import *
import exudyn.graphics as graphics
import numpy as np

SC = exu.SystemContainer()
mbs = SC.AddSystem()
"""


@dataclass(frozen=True)
class Param:
    """One randomized parameter: a uniform draw in [low, high], rounded so text and code agree.

    ``digits`` is the number of significant digits kept; an integer parameter draws from
    ``low..high`` inclusive.
    """

    name: str
    low: float
    high: float
    unit: str = ""
    integer: bool = False
    digits: int = 3

    def sample(self, rng: np.random.Generator) -> float | int:
        if self.integer:
            return int(rng.integers(int(self.low), int(self.high) + 1))
        value = float(rng.uniform(self.low, self.high))
        return round_significant(value, self.digits)


def round_significant(value: float, digits: int) -> float:
    """Round to ``digits`` significant digits; the result prints exactly as it is used."""
    if value == 0.0:
        return 0.0
    decimals = digits - 1 - math.floor(math.log10(abs(value)))
    return float(round(value, decimals))


@dataclass(frozen=True)
class SimSettings:
    """The ground truth's solver settings; they replace whatever the LLM wrote.

    ``extra`` are additional assignment lines on ``simulationSettings`` (e.g. for contact).
    """

    end_time: float
    steps: int
    extra: tuple[str, ...] = ()

    def block(self) -> str:
        lines = [
            "simulationSettings = exu.SimulationSettings()",
            f"simulationSettings.timeIntegration.endTime = {self.end_time!r}",
            f"simulationSettings.timeIntegration.numberOfSteps = {self.steps}",
            "simulationSettings.timeIntegration.verboseMode = 0",
            "simulationSettings.solution.file.write = False",
            *self.extra,
            "mbs.SolveDynamic(simulationSettings)",
        ]
        return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class TaskInstance:
    """One concrete task: what every other room receives. Frozen and JSON-friendly."""

    task_id: int
    slug: str
    name: str
    level: str
    seed: int
    params: dict[str, Any]
    description: str
    required_components: tuple[str, ...]
    sim: SimSettings | None  # None for a part: it is meshed, not simulated
    reference_program: str
    kind: str = "rigid"  # "rigid" (levels 1, 2), "part" (3a), "assembly" (3b)
    part: Any = None  # PartSpec of a part instance
    origin: str = ""  # key of the assembly instance a part was drawn for
    parts: tuple[tuple[str, TaskInstance], ...] = ()  # an assembly's (slot, part instance)
    draft: Any = None  # a repair task's Draft (tasks.drafts): the program with a seeded fault
    texts: str = "paper"  # which description: the paper's, or "open" (an engineer's words)
    design: Any = None  # a level-4 instance's DesignTask (tasks.design_base): variables, spec, target

    @property
    def key(self) -> str:
        own = f"{self.slug}@{self.seed}" + (f"~{self.draft.id}" if self.draft is not None else "")
        return f"{self.origin}/{own}" if self.origin else own

    def to_json(self) -> dict[str, Any]:
        return {
            "id": self.task_id,
            "slug": self.slug,
            "name": self.name,
            "level": self.level,
            "seed": self.seed,
            "params": self.params,
            "description": self.description,
            "required_components": list(self.required_components),
            "kind": self.kind,
            **({"texts": self.texts} if self.texts != "paper" else {}),
            **({"sim": {"end_time": self.sim.end_time, "steps": self.sim.steps}} if self.sim else {}),
            **({"part": self.part.to_json()} if self.part is not None else {}),
            **({"origin": self.origin} if self.origin else {}),
            **({"parts": {slot: part.key for slot, part in self.parts}} if self.parts else {}),
            **({"design": self.design.to_json()} if self.design is not None else {}),
        }


@dataclass(frozen=True)
class TaskModel:
    """A parameterized task model, as in the paper's template (section 2.1).

    ``model_code`` is Exudyn code that uses the parameter names (and the names returned by
    ``derive``) as Python variables, between the standard preamble and ``mbs.Assemble()``.
    ``derive`` computes values the text and code need beyond the raw draws (e.g. an initial
    angle in radians); they become variables of the program too.
    """

    id: int
    name: str
    level: str
    description: str
    params: tuple[Param, ...]
    components: tuple[str, ...]
    model_code: str
    sim: SimSettings
    derive: Any = None  # Callable[[dict], dict] | None; Any keeps the dataclass hashable
    #: The same system in an engineer's words: every parameter and the initial state, but no
    #: Exudyn or catalog names, no creation or marker order, no reference points or local axes.
    #: Graded by behaviour, since the paper's graph stages compare how a program is written.
    open_description: str = ""

    @property
    def slug(self) -> str:
        return slugify(self.name)

    def sample_params(self, seed: int) -> dict[str, Any]:
        rng = np.random.default_rng([self.id, seed])
        values: dict[str, Any] = {p.name: p.sample(rng) for p in self.params}
        if self.derive is not None:
            values.update(self.derive(dict(values)))
        return values

    def describe(self, values: dict[str, Any], texts: str = "paper") -> str:
        """The task text for drawn ``values``: the paper's (``texts="paper"``) or the open one."""
        if texts not in TEXTS:
            raise ValueError(f"unknown texts {texts!r}: choose one of {', '.join(TEXTS)}")
        template = self.description if texts == "paper" else self.open_description
        if not template:
            raise ValueError(f"task model {self.slug!r} has no {texts} text")
        description = " ".join(template.format(**values).split())
        return description + (
            f" Simulate the system for {self.sim.end_time:g} s using {self.sim.steps} time steps."
        )

    def instance(self, seed: int, texts: str = "paper") -> TaskInstance:
        values = self.sample_params(seed)
        description = self.describe(values, texts)
        return TaskInstance(
            task_id=self.id,
            slug=self.slug,
            name=self.name,
            level=self.level,
            seed=seed,
            params=values,
            description=description,
            required_components=self.components,
            sim=self.sim,
            reference_program=self.reference_program(values, description, seed),
            texts=texts,
        )

    def reference_program(self, values: dict[str, Any], description: str, seed: int) -> str:
        header = program_header(f"reference program: {self.id} {self.name}, seed {seed}", description)
        param_lines = "\n".join(f"{k} = {v!r}" for k, v in values.items())
        model = textwrap.dedent(self.model_code).strip("\n")
        return (
            f"{header}\n{PREAMBLE}\n# parameters\n{param_lines}\n\n{model}\n\n"
            f"mbs.Assemble()\n\n{self.sim.block()}"
        )


def program_header(title: str, description: str) -> str:
    """A comment block with the task description, so a saved program explains itself."""
    wrapped = textwrap.wrap(description, width=96)
    lines = [f"# MecEng {title}", "#", *(f"# {line}" for line in wrapped), "#"]
    return "\n".join(lines) + "\n"


def slugify(name: str) -> str:
    """The paper's model name as an identifier: 'Newton's cradle' -> 'newtons_cradle'."""
    out = []
    prev_sep = False
    for ch in name.lower().replace("'", "").replace("’", ""):
        if ch.isalnum():
            out.append(ch)
            prev_sep = False
        elif not prev_sep:
            out.append("_")
            prev_sep = True
    return "".join(out).strip("_")
