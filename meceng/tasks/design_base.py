"""Level 4: design tasks. The system is given, one or two values are left open, and the motion must
meet a specification that only a simulation can confirm.

A *design model* builds on a level-1/2 system: the system in an engineer's words (its open text)
with the design variables named but not valued, their allowed ranges, and a specification on the
motion (a quantity, its target and a tolerance). Each instance draws the system's parameters and a
hidden design inside the range, runs our own reference with that design here in this process
(``design_sim``) and takes the quantity it gives as the target: every instance has a feasible
design by construction, and the gold answer is that design.

The answer's form: a complete program that builds the system with the chosen values, declares them
at top level as a literal ``DESIGN = {"name": value, ...}`` and runs exactly one simulation.
"""

from __future__ import annotations

import importlib
import textwrap
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from meceng.tasks.base import (
    PREAMBLE,
    Param,
    SimSettings,
    TaskInstance,
    TaskModel,
    program_header,
    round_significant,
    slugify,
)

#: The quantity kinds a specification can be on (the issue's five, kept as words in the records).
QUANTITY_KINDS = ("event_time", "position", "extreme", "period", "settling_time")

#: A measurement: (step times, ODE2 coordinates q_ref + q per step, the program's values) -> quantity.
Measure = Callable[[np.ndarray, np.ndarray, dict[str, Any]], float]
#: An engineer's closed-form estimate: (system values, target) -> a design.
Estimate = Callable[[dict[str, Any], float], dict[str, float]]


def closest_on_grid(grid: np.ndarray, predict: Callable[[float], float], target: float) -> float:
    """The grid value whose predicted quantity is closest to ``target`` (the first of equals): how an
    estimate is solved for its design where its closed form has no inverse, or several."""
    return float(grid[int(np.argmin([abs(predict(float(x)) - target) for x in grid]))])


@dataclass(frozen=True)
class DesignVariable:
    """One value left open: its name in the program and in ``DESIGN``, and its allowed range."""

    name: str
    low: float
    high: float
    unit: str
    meaning: str  # "the constant drive torque on the crank"

    def to_json(self) -> list[float]:
        return [self.low, self.high]

    def describe(self) -> str:
        unit = f" {self.unit}" if self.unit else ""
        return f"{self.name} in [{self.low:g}, {self.high:g}]{unit}: {self.meaning}"


@dataclass(frozen=True)
class Spec:
    """What the motion must do: ``quantity`` (words), measured by ``measure``, within a relative
    ``tolerance`` of the instance's target."""

    quantity: str
    kind: str
    unit: str
    measure: Measure
    tolerance: float = 0.01  # relative to the target

    def __post_init__(self) -> None:
        if self.kind not in QUANTITY_KINDS:
            raise ValueError(f"unknown quantity kind {self.kind!r}: choose one of {', '.join(QUANTITY_KINDS)}")


@dataclass(frozen=True)
class DesignTask:
    """An instance's design problem: what every room after ``tasks`` needs to grade a design."""

    variables: tuple[DesignVariable, ...]
    spec: Spec
    target: float
    gold: dict[str, float]
    system: str  # the level-1/2 task model the system is taken from
    model: DesignModel = field(repr=False)
    values: dict[str, Any] = field(repr=False)

    @property
    def tolerance(self) -> float:
        """The spec's absolute tolerance."""
        return abs(self.target) * self.spec.tolerance

    def program(self, design: dict[str, float]) -> str:
        """The reference program built with ``design`` (the design verdict runs it)."""
        return self.model.program(self.values, design, "design check")

    def measure(self, times: np.ndarray, q: np.ndarray, design: dict[str, float]) -> float:
        return float(self.spec.measure(times, q, {**self.values, **design}))

    def verdict(self, value: float) -> tuple[bool, float]:
        """Passed, and the margin: the tolerance left (positive: inside, in units of the tolerance)."""
        if not np.isfinite(value):
            return False, float("-inf")
        margin = 1.0 - abs(value - self.target) / self.tolerance
        return margin >= 0.0, margin

    def to_json(self) -> dict[str, Any]:
        return {"variables": {v.name: v.to_json() for v in self.variables},
                "spec": {"quantity": self.spec.quantity, "kind": self.spec.kind, "unit": self.spec.unit,
                         "target": self.target, "tolerance": self.tolerance,
                         "relative_tolerance": self.spec.tolerance},
                "system": self.system}


@dataclass(frozen=True)
class DesignModel:
    """A design task model: a level-1/2 system with design variables and a spec on its motion.

    ``model_code`` uses the parameter names and the design variables' names as Python variables
    (usually the base system's own code, a parameter of which became a design variable).
    ``estimate`` is the best closed-form design an engineer would compute without simulating,
    described in ``estimate_text``; the design docs show how often it passes.
    """

    id: int
    name: str
    system: TaskModel
    open_description: str  # the system in an engineer's words; design variables named, not valued
    params: tuple[Param, ...]
    variables: tuple[DesignVariable, ...]
    spec: Spec
    spec_text: str  # what must hold, in words, with {target} and {tolerance_percent}
    estimate: Estimate
    estimate_text: str
    model_code: str = ""  # "" : the system's own model code
    sim: SimSettings | None = None  # None: the system's own
    derive: Any = None  # Callable[[dict], dict] | None, as TaskModel.derive
    #: components the design adds to its system's (a friction or a nonlinear law the system lacks);
    #: they are required and documented in the prompt like the system's own
    extra_components: tuple[str, ...] = ()
    #: where in each variable's range the hidden design is drawn (fractions of the range)
    draw: tuple[float, float] = (0.15, 0.85)
    level: str = "4"
    _targets: dict[int, tuple[dict[str, float], float]] = field(default_factory=dict, compare=False, hash=False,
                                                                 repr=False)

    @property
    def slug(self) -> str:
        return slugify(self.name)

    def __reduce__(self) -> tuple[Any, tuple[str]]:
        """Pickled by name (instances travel to the grading processes): the model is its module's
        ``TASK``, and a module of ``meceng.tasks.design`` is named after its model's slug."""
        return _design_model, (self.slug,)

    @property
    def components(self) -> tuple[str, ...]:
        return self.system.components + tuple(c for c in self.extra_components if c not in self.system.components)

    @property
    def settings(self) -> SimSettings:
        return self.sim or self.system.sim

    @property
    def open_text(self) -> str:  # the registry's test for "has an open text"
        return self.open_description

    def sample_params(self, seed: int) -> dict[str, Any]:
        rng = np.random.default_rng([self.id, seed])
        values: dict[str, Any] = {p.name: p.sample(rng) for p in self.params}
        if self.derive is not None:
            values.update(self.derive(dict(values)))
        return values

    def hidden_design(self, seed: int) -> dict[str, float]:
        """The design the target is measured from (the gold answer), inside ``draw`` of each range."""
        rng = np.random.default_rng([self.id, seed, 4])
        lo, hi = self.draw
        return {v.name: round_significant(float(v.low + (v.high - v.low) * rng.uniform(lo, hi)), 4)
                for v in self.variables}

    def model_source(self) -> str:
        return textwrap.dedent(self.model_code or self.system.model_code).strip("\n")

    def program(self, values: dict[str, Any], design: dict[str, float], title: str, description: str = "") -> str:
        """A complete program: the system with ``values``, ``DESIGN`` declared and unpacked, one solve."""
        header = program_header(f"{title}: {self.id} {self.name}", description) if description else (
            f"# MecEng {title}: {self.id} {self.name}\n")
        param_lines = "\n".join(f"{k} = {v!r}" for k, v in values.items())
        design_lines = "\n".join(f"{v.name} = DESIGN[{v.name!r}]" for v in self.variables)
        literal = "{" + ", ".join(f"{k!r}: {design[k]!r}" for k in (v.name for v in self.variables)) + "}"
        return (f"{header}\n{PREAMBLE}\nDESIGN = {literal}\n\n# parameters\n{param_lines}\n{design_lines}\n\n"
                f"{self.model_source()}\n\nmbs.Assemble()\n\n{self.settings.block()}")

    def target(self, seed: int, values: dict[str, Any]) -> tuple[dict[str, float], float]:
        """The hidden design and the target it gives, simulated here once per seed."""
        if seed not in self._targets:
            from meceng.tasks.design_sim import simulate

            design = self.hidden_design(seed)
            times, q = simulate(self.program(values, design, "target"))
            value = float(self.spec.measure(times, q, {**values, **design}))
            if not np.isfinite(value):
                raise ValueError(f"design task {self.slug} seed {seed}: the hidden design {design} gives no "
                                 f"{self.spec.quantity}")
            self._targets[seed] = (design, round_significant(value, 4))
        return self._targets[seed]

    def describe(self, values: dict[str, Any], target: float) -> str:
        system = " ".join(self.open_description.format(**values).split())
        spec = " ".join(self.spec_text.format(**values, target=f"{target:g}",
                                              tolerance_percent=f"{100 * self.spec.tolerance:g}").split())
        names = ", ".join(f'"{v.name}": ...' for v in self.variables)
        variables = "; ".join(v.describe() for v in self.variables)
        sim = self.settings
        solver = "".join(f" {line.strip()}" for line in sim.extra)
        return (f"{system} Design task: choose {variables}. Requirement: {spec} "
                f"Simulate the system for {sim.end_time:g} s using {sim.steps} time steps"
                + (f", with the solver settings{solver}" if solver else "") + ". "
                f"Answer with a complete program that builds the system with your chosen values, declares them "
                f"at top level as a literal DESIGN = {{{names}}} (numbers only, no expressions) and runs exactly "
                f"one simulation (one mbs.SolveDynamic call).")

    def instance(self, seed: int, texts: str = "open") -> TaskInstance:
        values = self.sample_params(seed)
        gold, target = self.target(seed, values)
        description = self.describe(values, target)
        design = DesignTask(variables=self.variables, spec=self.spec, target=target, gold=gold,
                            system=self.system.slug, model=self, values=values)
        return TaskInstance(
            task_id=self.id, slug=self.slug, name=self.name, level=self.level, seed=seed,
            params={**values, "target": target}, description=description,
            required_components=self.components, sim=self.settings,
            reference_program=self.program(values, gold, f"reference program, seed {seed}", description),
            texts="open", design=design,
        )


def _design_model(slug: str) -> DesignModel:
    return importlib.import_module(f"meceng.tasks.design.{slug}").TASK
