"""The shape of a level 3b assembly model (paper section 2.3, Flexible MBS Assembly).

An assembly names the parts it needs (slots, each loaded by the program from ``<slot>.npz``),
draws its parameters once and hands its master parameters to every part, so that the rotor's
shaft fits the bearing's bore. The parts are generated first (level 3a flow); the assembly's own
text gets the part descriptions and the paper's "Part Loading Info" note appended.

The ground truth is program text like a rigid task's: preamble, parameters, the model (loading the
parts with ``FEMinterface.LoadFromFile`` and adding them with ``mbs.CreateFFRFReducedOrderObject``),
``mbs.Assemble()`` and the simulation block. Both the LLM's and the ground-truth program load the
same LLM-made parts, so the verdict measures the assembly alone.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from typing import Any

import numpy as np

from meceng.tasks.base import PREAMBLE, Param, SimSettings, TaskInstance, program_header, slugify
from meceng.tasks.part_base import PartModel
from meceng.tasks.parts import part_model

#: The paper's note (section 2.3), word for word, appended before the part descriptions. What follows
#: it departs from the paper's "descriptions of the parts": one line per part with its name, the call
#: that loads it (``fem.LoadFromFile('<name>.npz')``, so no model guesses how a name becomes a file),
#: its geometry and material without the meshing instructions, and its interfaces (docs/prompts.md).
PART_LOADING_INFO = (
    "Part Loading Info: You already have the {count} needed machine part(s) available as a Finite Element "
    "Method (FEM) model. Load the corresponding FEM interface(s) with their/its according name(s)!"
)

_NUMBERS = {1: "one", 2: "two", 3: "three", 4: "four"}


@dataclass(frozen=True)
class PartSlot:
    """A part the assembly needs: loaded from ``<name>.npz``; one of ``choices`` (part slugs) is
    drawn per variation when there are several (the flexible pendulum's arm)."""

    name: str
    choices: tuple[str, ...]


@dataclass(frozen=True)
class AssemblyModel:
    """A parameterized flexible multibody system built on level 3a parts.

    ``params`` include the master parameters the parts share. ``model_code`` uses the parameter
    names (and those of ``derive`` and ``from_parts``) as variables and loads each part from
    ``'<slot>.npz'``. ``from_parts(values, {slot: part values})`` adds values that depend on a
    part's own dimensions (the centre of an interface the text must state).
    """

    id: int
    name: str
    description: str
    params: tuple[Param, ...]
    parts: tuple[PartSlot, ...]
    components: tuple[str, ...]
    model_code: str
    sim: SimSettings
    derive: Any = None  # Callable[[dict], dict] | None
    from_parts: Any = None  # Callable[[dict, dict[str, dict]], dict] | None: values taken from the parts
    level: str = "3b"

    @property
    def slug(self) -> str:
        return slugify(self.name)

    def sample_params(self, seed: int) -> dict[str, Any]:
        rng = np.random.default_rng([self.id, seed])
        values: dict[str, Any] = {p.name: p.sample(rng) for p in self.params}
        if self.derive is not None:
            values.update(self.derive(dict(values)))
        return values

    def choose_parts(self, seed: int) -> tuple[tuple[str, str], ...]:
        """(slot, part slug) per slot; a slot with several choices draws one, seeded."""
        rng = np.random.default_rng([self.id, seed, 3])
        return tuple((slot.name, slot.choices[int(rng.integers(len(slot.choices)))] if len(slot.choices) > 1
                      else slot.choices[0]) for slot in self.parts)

    def instance(self, seed: int, models: dict[str, PartModel] | None = None) -> TaskInstance:
        """The assembly instance with its part instances (drawn with this instance's master values)."""
        if models is None:
            models = {slug: part_model(slug) for _, slug in self.choose_parts(seed)}
        values = self.sample_params(seed)
        key = f"{self.slug}@{seed}"
        parts = tuple((slot, models[slug].instance(seed, master=values, origin=key))
                      for slot, slug in self.choose_parts(seed))
        if self.from_parts is not None:  # e.g. a joint point that depends on a part's own dimensions
            values.update(self.from_parts(dict(values), {slot: dict(part.params) for slot, part in parts}))
        text = " ".join(self.description.format(**values).split())
        text += f" Simulate the system for {self.sim.end_time:g} s using {self.sim.steps} time steps."
        count = len(parts)
        listing = "\n".join(
            f"- '{slot}' (load it with fem.LoadFromFile('{slot}.npz')): {part.part.geometry_text} "
            f"Interfaces: {', '.join(repr(n) for n in part.part.interfaces)}."
            for slot, part in parts)
        description = (f"{text}\n\n{PART_LOADING_INFO.format(count=_NUMBERS.get(count, str(count)))}\n{listing}")
        return TaskInstance(
            task_id=self.id, slug=self.slug, name=self.name, level=self.level, seed=seed, params=values,
            description=description, required_components=self.components, sim=self.sim,
            reference_program=self.reference_program(values, description, seed), kind="assembly", parts=parts,
        )

    def reference_program(self, values: dict[str, Any], description: str, seed: int) -> str:
        header = program_header(f"reference program: {self.id} {self.name}, seed {seed}", description)
        param_lines = "\n".join(f"{k} = {v!r}" for k, v in values.items())
        model = textwrap.dedent(self.model_code).strip("\n")
        return (f"{header}\n{PREAMBLE}from exudyn.FEM import FEMinterface\n\n# parameters\n{param_lines}\n\n"
                f"{model}\n\nmbs.Assemble()\n\n{self.sim.block()}")
