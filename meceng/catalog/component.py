"""The component catalog the LLM chooses from (paper section 2.2).

Each component has a short description shown in the selection prompt, a context text with a
working example shown in the code-generation prompt when it was chosen, and the components it
brings along (a joint brings ground and rigid body). Dependencies are data, used both for the
context and for the 'choose components' metric.
"""

from __future__ import annotations

import textwrap
from collections.abc import Iterable, Iterator
from dataclasses import dataclass


def text_block(text: str) -> str:
    """A component text written indented in its module, as the model reads it."""
    return textwrap.dedent(text).strip()


@dataclass(frozen=True)
class Component:
    name: str
    description: str
    context: str
    example: str
    dependencies: tuple[str, ...] = ()
    group: str = "rigid"


@dataclass(frozen=True)
class Catalog:
    components: tuple[Component, ...]

    def __post_init__(self) -> None:
        names = [c.name for c in self.components]
        if len(names) != len(set(names)):
            raise ValueError("duplicate component names")
        known = set(names)
        for c in self.components:
            unknown = set(c.dependencies) - known
            if unknown:
                raise ValueError(f"{c.name} depends on unknown components {sorted(unknown)}")

    def __iter__(self) -> Iterator[Component]:
        return iter(self.components)

    def __len__(self) -> int:
        return len(self.components)

    def __contains__(self, name: object) -> bool:
        return any(c.name == name for c in self.components)

    def get(self, name: str) -> Component:
        for c in self.components:
            if c.name == name:
                return c
        raise KeyError(name)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.components)

    def dependency_map(self) -> dict[str, tuple[str, ...]]:
        return {c.name: c.dependencies for c in self.components}

    def resolve(self, names: Iterable[str]) -> list[Component]:
        """Chosen components plus their dependencies, in catalog order (unknown names skipped)."""
        wanted: set[str] = set()
        stack = [n for n in names if n in self]
        while stack:
            name = stack.pop()
            if name not in wanted:
                wanted.add(name)
                stack.extend(self.get(name).dependencies)
        return [c for c in self.components if c.name in wanted]

    def menu(self) -> str:
        """The list shown in the selection prompt: one line per component."""
        return "\n".join(f"- {c.name}: {c.description}" for c in self.components)

    def context(self, names: Iterable[str]) -> str:
        """Context text for the code prompt: each chosen component with its example."""
        blocks = []
        for c in self.resolve(names):
            blocks.append(f"### {c.name}\n{c.context.strip()}\nExample:\n```python\n{c.example.strip()}\n```")
        return "\n\n".join(blocks)
