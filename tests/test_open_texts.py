"""The lint of the open texts (issue 36): each level-1/2 task model says its system a second time, in
an engineer's words, and this checks what can be checked mechanically.

- it names no Exudyn item, catalog component, helper function or program variable (no CamelCase or
  camelCase word, no ``mbs``/``exu``), and no way of writing the program: no creation or marker
  order, no reference point, no local axis;
- every parameter of the task model appears in it (as a ``{placeholder}``), so every drawn value is
  in the text;
- every number in it, at seeds 0-3, is one the ground truth uses: a drawn or derived value, a
  literal of the ground-truth program or of the paper's text, or the simulation settings — a stray
  number would be a second system.

Gold programs passing behaviour on open-text tasks is checked in tests/test_gold.py.
"""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import pytest

from meceng.catalog.catalogs import rigid_catalog
from meceng.catalog.names import OBJECT_NAMES
from meceng.tasks.base import TaskModel
from meceng.tasks.registry import default_registry

SEEDS = (0, 1, 2, 3)

#: Catalog names that are plain English words; capitalised at a sentence start they say nothing.
ENGLISH = frozenset({"Ground", "Force", "Torque", "Sensor"})

#: Words that tell how to write the program rather than what the system is.
DICTATING = {
    "creation order": re.compile(
        r"\b(creat(e|es|ed|ing|ion)|add(s|ed|ing)?|in (this|that|the following) order)\b", re.I
    ),
    "markers": re.compile(r"\bmarkers?\b", re.I),
    "reference point": re.compile(r"\breference (point|position|rotation|configuration)s?\b", re.I),
    "local axes": re.compile(r"\blocal (axis|axes|[xyz]|frame|coordinates?)\b", re.I),
    "program words": re.compile(r"\b(mbs|exu|exudyn|user function|helper|component|item)s?\b", re.I),
}

CODE_WORD = re.compile(r"\b([a-z]+[A-Z]\w*|[A-Z][a-z]+[A-Z]\w*)\b")
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")
EXPONENT = re.compile(r"\^\(?-?\d+\)?")


def rigid_models() -> list[TaskModel]:
    return [m for m in default_registry().select(levels=("1", "2")) if isinstance(m, TaskModel)]


@cache
def forbidden_names() -> frozenset[str]:
    names = set(rigid_catalog().names) | set(OBJECT_NAMES) | set(OBJECT_NAMES.values())
    return frozenset(names - ENGLISH)


def numbers(text: str) -> list[float]:
    return [abs(float(n)) for n in NUMBER.findall(EXPONENT.sub("", text))]


def allowed_numbers(model: TaskModel, seed: int) -> list[float]:
    values = model.sample_params(seed)
    allowed = [model.sim.end_time, float(model.sim.steps)]
    for value in values.values():
        if isinstance(value, (int, float)):
            allowed.append(abs(float(value)))
        elif isinstance(value, (list, tuple, np.ndarray)):
            allowed += [abs(float(v)) for v in np.ravel(np.asarray(value, dtype=float))]
    allowed += numbers(model.model_code) + numbers(model.describe(values, "paper"))
    return allowed


def known(number: float, allowed: list[float]) -> bool:
    return any(math.isclose(number, a, rel_tol=1e-9, abs_tol=1e-12) for a in allowed)


def test_every_rigid_model_has_an_open_text() -> None:
    missing = [m.slug for m in rigid_models() if not m.open_description.strip()]
    assert len(rigid_models()) == 50
    assert not missing, f"no open text: {missing}"


@pytest.mark.parametrize("model", rigid_models(), ids=lambda m: m.slug)
def test_open_text_names_no_implementation(model: TaskModel) -> None:
    text = model.open_description
    problems = [f"{what}: {m.group(0)!r}" for what, rx in DICTATING.items() for m in rx.finditer(text)]
    problems += [f"code word: {w!r}" for w in CODE_WORD.findall(text)]
    problems += [f"catalog name: {w!r}" for w in re.findall(r"\b\w+\b", text) if w in forbidden_names()]
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("model", rigid_models(), ids=lambda m: m.slug)
def test_open_text_has_every_parameter(model: TaskModel) -> None:
    placeholders = set(re.findall(r"\{(\w+)", model.open_description))
    missing = [p.name for p in model.params if p.name not in placeholders]
    assert not missing, f"parameters not in the open text: {missing}"


@pytest.mark.parametrize("model", rigid_models(), ids=lambda m: m.slug)
def test_open_text_numbers_are_the_ground_truths(model: TaskModel) -> None:
    for seed in SEEDS:
        text = model.describe(model.sample_params(seed), "open")
        allowed = allowed_numbers(model, seed)
        stray = [n for n in numbers(text) if not known(n, allowed)]
        assert not stray, f"seed {seed}: numbers the ground truth does not use: {stray}\n{text}"


def test_the_lint_catches_what_it_guards_against() -> None:
    """A paper text fails each check: it dictates the program, so the lint can fail."""
    model = default_registry().get("single_pendulum_rigid_body")
    assert isinstance(model, TaskModel)
    text = model.description
    assert CODE_WORD.search(text) and DICTATING["creation order"].search(text)
    assert DICTATING["reference point"].search(text) and DICTATING["local axes"].search(text)
    stray = model.describe(model.sample_params(0), "paper") + " a second link of 0.123456 m"
    assert not known(0.123456, allowed_numbers(model, 0)) and 0.123456 in numbers(stray)
