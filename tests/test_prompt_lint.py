"""The prompt lint: every prompt a model can receive, rendered as a run renders it, checked for what
can be checked mechanically (issue 26).

Rendered: all task models of every level, seeds 0 to 3, the selection templates CI1-CI6, the code
templates MBS1-MBS4, with and without the agent loop's note, parts and assemblies (an assembly's
prompts include its parts'). Checked:

- a file rule must not forbid a file load the description requires (assemblies load their parts);
- every catalog component a description names is among the components its code prompt documents,
  or is named in the selection menu's line of one of them (the text's "GenericJoint" is what
  InterfaceJoint documents), and every other Exudyn name a description uses exists;
- every call a description or a catalog text shows exists in the installed Exudyn with the
  arguments shown (``exudyn_api.call_problems``);
- a component whose Exudyn object the assemblies use on flexible parts' markers does not document
  itself as rigid-only;
- where a description orders markers ("the first-named marker first"), no documentation in the same
  prompt states another order, and the description names the ground first where the ground truth
  puts it first;
- a documented rule gives one answer: the length of a through hole's cutting cylinder, the centre of
  mass of a body whose inertia is a sum;
- every example of the part and assembly catalogs runs (the rigid catalog's: tests/test_catalog.py).

Each check was seen to fail on the contradiction it guards against (the audit's list in
docs/prompts.md).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from functools import cache
from pathlib import Path

import exudyn as exu
import exudyn.utilities as exu_utilities
import pytest
from exudyn.FEM import FEMinterface
from exudyn_api import MAIN_SYSTEM, call_problems, parameters

from meceng.agents.prompts import CODE_TEMPLATES, SELECT_TEMPLATES
from meceng.catalog.catalogs import assembly_catalog, catalog_for, part_catalog, rigid_catalog
from meceng.catalog.component import Catalog
from meceng.catalog.flexible import BEAM_PART
from meceng.catalog.flexible import COMPONENTS as FLEXIBLE
from meceng.catalog.part import FEM
from meceng.pipeline import RenderedPrompt, RunSettings, instance_prompts
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry

SEEDS = (0, 1, 2, 3)  # seeds 0-3 draw each of the four beams of the cantilever (parts vary per seed)


@cache
def instances() -> tuple[TaskInstance, ...]:
    """Every task instance a run can draw at these seeds, an assembly's parts included."""
    out: list[TaskInstance] = []
    for model in default_registry():
        for seed in SEEDS:
            instance = model.instance(seed)
            out.extend(part for _, part in instance.parts)
            out.append(instance)
    return tuple(out)


@cache
def prompts() -> tuple[RenderedPrompt, ...]:
    """Every prompt of every instance under every template and both agents (a part always gets
    PART1, so its prompts repeat across the rigid templates; each distinct text is kept once)."""
    seen: dict[str, RenderedPrompt] = {}
    pairs = list(zip(SELECT_TEMPLATES, [*CODE_TEMPLATES] * 2, strict=False))  # every template at least once
    for model in default_registry():
        for seed in SEEDS:
            instance = model.instance(seed)
            for select, code in pairs:
                for agent in ("pipeline", "loop"):
                    settings = RunSettings(select_template=select, code_template=code, agent=agent)
                    for prompt in instance_prompts(instance, settings):
                        seen.setdefault(prompt.text, prompt)
    return tuple(seen.values())


def descriptions() -> dict[str, TaskInstance]:
    return {i.key: i for i in instances()}


# --- file rules -------------------------------------------------------------------------------

_RULE_SPLIT = re.compile(r"\n(?=\s*(?:- |\d+\. ))|(?<=\.)\s+")
_BAN = re.compile(r"(?i)\b(do not|don't|no|forbidden)\b")
_READ = re.compile(r"(?i)\bread(ing)?\b[^.;]*\bfiles?\b|\bfile i/o\b|\bfile reading\b")
_EXCEPTION = re.compile(r"(?i)\bexcept\b|\bother than\b")


def file_read_bans(text: str) -> list[str]:
    """The sentences of a prompt that forbid reading files without an exception."""
    return [s.strip() for s in _RULE_SPLIT.split(text)
            if _BAN.search(s) and _READ.search(s) and not _EXCEPTION.search(s)]


def test_no_file_rule_forbids_a_required_load() -> None:
    checked = 0
    for prompt in prompts():
        if prompt.stage != "code" or "LoadFromFile(" not in prompt.text:
            continue
        checked += 1
        assert file_read_bans(prompt.text) == [], f"{prompt.key} {prompt.template}"
    assert checked >= 12 * len(SEEDS) * len(CODE_TEMPLATES)  # every assembly under every code template


def test_the_file_rule_check_finds_a_flat_ban() -> None:
    assert file_read_bans("Rules:\n- Do not read or write files, do not import os.\n- Return it.")
    assert file_read_bans("No file I/O, no graphics.")
    assert not file_read_bans("No file I/O except loading the part files the description names.")
    assert not file_read_bans("Do not write files or open a renderer.")


# --- component names --------------------------------------------------------------------------

#: a code name: two capitals and a small letter (InertiaCylinder, FEMinterface), or a called
#: lowerCamel name (mbs.GetObjectOutputBody is caught by its own capitals)
_CAMEL = re.compile(r"\b(?=\w*[A-Z]\w*[A-Z])(?=\w*[a-z])([A-Za-z]\w*)\b")


@cache
def create_arguments() -> frozenset[str]:
    """Every argument of the ``mbs.Create...`` functions (a description may name one)."""
    names: set[str] = set()
    for attribute in dir(MAIN_SYSTEM):
        if attribute.startswith("Create"):
            names |= parameters(getattr(MAIN_SYSTEM, attribute)) or set()
    return frozenset(names)


@cache
def settings_names() -> frozenset[str]:
    """Every attribute name in Exudyn's simulation settings tree (a design task's text names the
    solver settings its reference sets, e.g. timeIntegration.discontinuous.useRecommendedStepSize)."""
    names: set[str] = set()

    def walk(node: object, depth: int) -> None:
        for name in dir(node):
            if name.startswith("_"):
                continue
            names.add(name)
            value = getattr(node, name, None)
            if depth < 4 and type(value).__module__.startswith("exudyn"):
                walk(value, depth + 1)

    walk(exu.SimulationSettings(), 0)
    return frozenset(names)


def exudyn_has(name: str) -> bool:
    import exudyn.FEM as exu_fem
    import netgen.occ as occ

    places = (exu_utilities, exu, exu_fem, MAIN_SYSTEM, FEMinterface, occ, exu.OutputVariableType)
    return (name in create_arguments() or any(hasattr(where, name) for where in places)
            or name in settings_names())


def naming_problems(instance: TaskInstance, catalog: Catalog) -> list[str]:
    """Names in the description that the prompts do not account for."""
    documented = catalog.resolve(instance.required_components)
    documented_names = {c.name for c in documented}
    problems = []
    for name in sorted(set(_CAMEL.findall(instance.description))):
        if name in catalog:
            if name in documented_names:
                continue
            if not any(re.search(rf"\b{name}\b", c.description) for c in documented):
                problems.append(f"names the component {name}, which the prompts neither document nor map")
        elif not exudyn_has(name):
            problems.append(f"names {name}, which is neither a component nor in the installed Exudyn")
    return problems


def test_every_name_a_description_uses_is_a_documented_component_or_exists() -> None:
    problems = {key: found for key, instance in descriptions().items()
                if (found := naming_problems(instance, catalog_for(instance.kind)))}
    assert problems == {}


def test_the_naming_check_finds_an_unmapped_component() -> None:
    instance = default_registry().get("rotor_in_bearing_block").instance(0)
    bare = Catalog(tuple(c if c.name != "InterfaceJoint" else
                         type(c)(c.name, "joint at a flexible part's interface", c.context, c.example,
                                 c.dependencies, c.group) for c in assembly_catalog()))
    assert any("GenericJoint" in p for p in naming_problems(instance, bare))


def test_a_text_without_a_ground_object_says_so() -> None:
    """An unused ground object fails the topology (an inert surplus item), so a task whose ground
    truth has none says so; the catalog's Ground text is in its prompt only if chosen."""
    # a design task (level 4) is graded by behaviour: an unused ground object costs it nothing
    silent = [i.key for i in instances() if i.kind == "rigid" and i.design is None
              and "CreateGround(" not in i.reference_program and not re.search(r"(?i)\bno ground\b", i.description)]
    assert silent == []


# --- calls shown in descriptions and catalogs -------------------------------------------------


def test_every_call_a_description_shows_exists_with_its_arguments() -> None:
    problems = {key: found for key, instance in descriptions().items()
                if (found := call_problems(instance.description))}
    assert problems == {}


@pytest.mark.parametrize("catalog", [rigid_catalog(), part_catalog(), assembly_catalog()],
                         ids=["rigid", "part", "assembly"])
def test_every_call_a_catalog_shows_exists_with_its_arguments(catalog: Catalog) -> None:
    problems = {c.name: found for c in catalog if (found := call_problems(c.context + "\n" + c.example))}
    assert problems == {}


# --- what assemblies do with rigid components' objects ----------------------------------------

_ON_MARKER = re.compile(r"\b(?:AddObject|AddLoad)\((\w+)\(markerNumbers?=")
_RIGID_ONLY = re.compile(r"(?i)\bonly rigid bodies\b|\brigid bodies only\b")


def rigid_only_claims(catalog: Catalog, programs: list[str]) -> dict[str, str]:
    """Components whose Exudyn object the programs put on markers (flexible parts' interfaces)
    while their documentation admits rigid bodies only and says nothing of flexible parts."""
    used = {name for program in programs for name in _ON_MARKER.findall(program)}
    return {c.name: c.context for c in catalog
            if c.name in used and _RIGID_ONLY.search(c.context) and "flexible" not in c.context}


def test_objects_used_on_flexible_parts_are_not_documented_as_rigid_only() -> None:
    programs = [i.reference_program for i in instances() if i.kind == "assembly"]
    assert {"GenericJoint", "Force", "Torque"} <= {n for p in programs for n in _ON_MARKER.findall(p)}
    assert rigid_only_claims(assembly_catalog(), programs) == {}


# --- marker order -----------------------------------------------------------------------------

_ORDER_RULE = "the first-named marker first"
_OTHER_CONVENTION = re.compile(r"(?i)\bconventionally\b[^.]*\bfirst\b")
_PART_NAMED_BEFORE_GROUND = re.compile(r"(?i)(?:'\w+'\)?|\binterface '\w+'\)) (?:is|are) clamped to the ground")


def marker_order_problems(prompt_text: str, description: str) -> list[str]:
    if _ORDER_RULE not in description:
        return []
    problems = [f"documentation: {m.group(0)!r}" for m in _OTHER_CONVENTION.finditer(prompt_text)]
    problems += [f"description names the part before the ground: {m.group(0)!r}"
                 for m in _PART_NAMED_BEFORE_GROUND.finditer(description)]
    return problems


def test_marker_order_has_one_rule_in_every_prompt() -> None:
    by_key = descriptions()
    ruled = [p for p in prompts() if p.kind == "assembly" and _ORDER_RULE in by_key[p.key].description]
    assert len({p.key for p in ruled}) >= 8 * len(SEEDS)
    problems = {(p.key, p.template): found for p in ruled
                if (found := marker_order_problems(p.text, by_key[p.key].description))}
    assert problems == {}


def test_the_marker_order_check_finds_a_second_convention() -> None:
    description = f"Joints ({_ORDER_RULE}): (1) the block's bottom (interface 'bottom') is clamped to the ground."
    assert len(marker_order_problems("(conventionally the ground comes first)", description)) == 2


# --- rules with one answer --------------------------------------------------------------------

_SENTENCE = re.compile(r"(?<=[.;])\s+|\n\s*- ")


def sentences(catalog: Catalog) -> list[tuple[str, str]]:
    return [(c.name, s) for c in catalog for s in _SENTENCE.split(c.context) if s.strip()]


def two_hole_lengths(sentence: str) -> bool:
    """A sentence that asks for a cutting cylinder longer than the wall and exactly as long as it,
    not as alternatives ('..., or ...')."""
    longer = re.search(r"(?i)\blonger\b", sentence)
    exact = re.search(r"(?i)wall thickness|spans the wall exactly", sentence)
    return bool(longer and exact) and not re.search(r",\s+or\b|\beither\b", sentence)


def test_a_through_hole_has_one_length_rule() -> None:
    assert [s for name, s in sentences(part_catalog()) if two_hole_lengths(s)] == []
    old = ("make it a little longer than the wall only if the description says the hole goes through (then "
           "start it on the surface and use the wall thickness as h)")
    assert two_hole_lengths(old)


_COM_AT_REFERENCE = re.compile(r"(?i)cent(?:er|re) of mass[^.;]{0,30}\b(?:is|at)\b[^.;]{0,20}\breference point"
                               r"|\breference point[^.;]{0,10}\bis\b[^.;]{0,40}cent(?:er|re) of mass")
_QUALIFIED = re.compile(r"(?i)\balone\b|\bone helper\b|\bsingle\b|Translated")


def unqualified_com_claims(catalog: Catalog) -> list[str]:
    """Sentences that put the centre of mass at the reference point without saying when."""
    return [f"{name}: {s}" for name, s in sentences(catalog)
            if _COM_AT_REFERENCE.search(s) and not _QUALIFIED.search(s)]


def test_the_centre_of_mass_rule_admits_a_summed_inertia() -> None:
    summed = [i.key for i in instances() if ".Translated(" in i.description]
    assert summed, "the unbalanced rotor sums inertias"
    assert unqualified_com_claims(rigid_catalog()) == []
    assert unqualified_com_claims(Catalog((type(rigid_catalog().get("InertiaSphere"))(
        "X", "x", "- With these helpers the center of mass is the body's reference point.", ""),)))


# --- every example runs -----------------------------------------------------------------------


def _run(program: str, folder: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", program], cwd=folder, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "MPLBACKEND": "Agg"})


def test_every_part_and_assembly_example_runs(tmp_path: Path) -> None:
    """The FEM examples mesh and reduce the beam; the assembly examples load it as beam.npz."""
    for component in FEM:
        result = _run(component.example, tmp_path)
        assert result.returncode == 0, f"{component.name}: {result.stderr[-2000:]}"
    made = _run(BEAM_PART + "fem.SaveToFile('beam.npz')\n", tmp_path)
    assert made.returncode == 0, made.stderr[-2000:]
    for component in FLEXIBLE:
        result = _run(component.example, tmp_path)
        assert result.returncode == 0, f"{component.name}: {result.stderr[-2000:]}"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["beam.npz"]  # no example writes a file
