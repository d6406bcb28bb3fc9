"""What every level 3a part model and the part catalog must satisfy (no meshing here: fast)."""

from __future__ import annotations

import re

import pytest

from meceng.agents.prompts import code_prompt, select_prompt
from meceng.catalog.catalogs import part_catalog
from meceng.catalog.part import FEM, GEOMETRY
from meceng.tasks.base import slugify
from meceng.tasks.part_base import PART_PREAMBLE, PartModel
from meceng.tasks.registry import default_registry
from meceng.tools.meshcheck import check_mesh_size
from meceng.tools.safety import PART_IMPORT_ROOTS, check_program

PARTS = [m for m in default_registry() if isinstance(m, PartModel)]
FEM_NAMES = {"NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"}


def _geometry(program: str) -> object:
    namespace: dict = {}
    head, _, _ = program.partition("mesh = ngs.Mesh(")
    exec(head, namespace)  # builds the solid only; meshing stays out of the test process
    return namespace["shape"]


@pytest.mark.parametrize("component", GEOMETRY, ids=lambda c: c.name)
def test_geometry_examples_build_a_solid(component) -> None:
    namespace: dict = {}
    exec(component.example, namespace)
    assert namespace["shape"].mass > 0
    assert component.example.startswith(PART_PREAMBLE) and component.group == "part"


def test_fem_examples_hard_code_maxh_and_pass_the_checks() -> None:
    for component in FEM:
        assert check_mesh_size(component.example, 0.001).code == component.example
        assert check_program(component.example, PART_IMPORT_ROOTS)
    assert part_catalog().resolve(["HCBModes"])[-1].name == "HCBModes"
    assert {c.name for c in part_catalog().resolve(["HCBModes"])} == {"GenerateMesh", "ImportMeshToFEM", "HCBModes"}


def test_part_prompts_carry_description_menu_and_context() -> None:
    instance = PARTS[0].instance(0)
    catalog = part_catalog()
    select = select_prompt("PART1", instance.description, catalog.menu())
    code = code_prompt("PART1", instance.description, catalog.context(instance.required_components))
    assert instance.description in select and "- Extrude:" in select
    assert "### HCBModes" in code and "HARD-CODE maxh" in code


@pytest.mark.parametrize("model", PARTS, ids=lambda m: m.slug)
def test_part_model_contract(model: PartModel) -> None:
    assert 51 <= model.id <= 72 and model.level == "3a" and model.slug == slugify(model.name)
    assert set(model.components) >= FEM_NAMES and set(model.components) <= set(part_catalog().names)
    assert model.interfaces and len(set(model.interfaces)) == len(model.interfaces)
    assert set(model.master) <= {p.name for p in model.params}
    a, b, c = model.instance(3), model.instance(3), model.instance(4)
    assert a == b and a.params != c.params and a.kind == "part"
    assert "{" not in a.description and "}" not in a.description
    for name in model.interfaces:
        assert f"'{name}'" in a.description
    assert f"maxh = {a.part.maxh:g} m" in a.description
    assert check_program(a.reference_program, PART_IMPORT_ROOTS)
    mesh_check = check_mesh_size(a.reference_program, a.part.maxh / 2)
    assert mesh_check.maxh == (a.part.maxh,) and not mesh_check.raised
    for name, value in a.params.items():
        assert re.search(rf"^{name} = {re.escape(repr(value))}$", a.reference_program, re.M)


@pytest.mark.parametrize("model", PARTS, ids=lambda m: m.slug)
def test_ground_truth_geometry_is_one_solid_with_every_interface_named(model: PartModel) -> None:
    for seed in (0, 1):
        shape = _geometry(model.instance(seed).reference_program)
        assert len(shape.solids) == 1, "a part is one connected solid"
        names = {f.name for f in shape.faces}
        assert set(model.interfaces) <= names, f"interfaces not on faces: {set(model.interfaces) - names}"


def test_master_parameters_come_from_the_assembly() -> None:
    model = default_registry().get("flexible_beam_part")
    instance = model.instance(5, master={"beam_length": 0.777, "unrelated": 1.0}, origin="cantilever_beam@5")
    assert instance.params["beam_length"] == 0.777 and "unrelated" not in instance.params
    assert "0.777 m" in instance.description and instance.key == "cantilever_beam@5/flexible_beam_part@5"
