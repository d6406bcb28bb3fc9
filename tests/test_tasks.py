import re

import pytest

from meceng.tasks.base import slugify
from meceng.tasks.registry import default_registry


def test_registry_has_all_fifty_rigid_models_with_paper_names() -> None:
    registry = default_registry()
    assert [m.id for m in registry.select(["1"])] == list(range(1, 31))
    assert [m.id for m in registry.select(["2"])] == list(range(31, 51))
    names = {}
    with open_tasks_csv() as rows:
        for row in rows:
            names[int(row["id"])] = row["name"]
    for model in registry:
        if model.level == "4":  # design tasks are ours, not the paper's: they build on its systems
            assert model.system.name == names[model.system.id]
            continue
        assert model.name == names[model.id]
        assert model.slug == slugify(names[model.id])


def open_tasks_csv():
    import contextlib
    import csv
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "shared" / "tasks.csv"
    if not path.exists():
        pytest.skip("shared/tasks.csv not beside the checkout")

    @contextlib.contextmanager
    def rows():
        with path.open() as f:
            yield csv.DictReader(f)

    return rows()


@pytest.mark.parametrize(("name", "slug"), [
    ("Newton's cradle", "newtons_cradle"),
    ("slider crank / point masses", "slider_crank_point_masses"),
    ("2R SCARA robot", "2r_scara_robot"),
    ("sphere-sphere and sphere-ground impact", "sphere_sphere_and_sphere_ground_impact"),
])
def test_slugify(name: str, slug: str) -> None:
    assert slugify(name) == slug


def test_same_seed_same_instance_and_different_seeds_differ() -> None:
    for model in default_registry().select(["1", "2"]):
        a, b, c = model.instance(7), model.instance(7), model.instance(8)
        assert a == b
        assert a.params != c.params
        assert "{" not in a.description and "}" not in a.description
        assert re.search(r"Simulate the system for [0-9.]+ s using \d+ time steps", a.description)
        for name, value in a.params.items():
            assert f"{name} = {value!r}" in a.reference_program


def test_parameters_stay_in_their_ranges() -> None:
    for model in default_registry():
        for seed in range(30):
            values = model.sample_params(seed)
            for p in model.params:
                slack = 0.01 * max(abs(p.low), abs(p.high))  # rounding to significant digits
                assert p.low - slack <= values[p.name] <= p.high + slack


def test_required_components_exist_in_catalog() -> None:
    from meceng.catalog.catalogs import assembly_catalog, part_catalog, rigid_catalog

    catalogs = {"1": rigid_catalog(), "2": rigid_catalog(), "3a": part_catalog(), "3b": assembly_catalog(),
                "4": rigid_catalog()}
    for model in default_registry():
        catalog = catalogs[model.level]
        for name in model.components:
            assert name in catalog, f"{model.slug} needs unknown component {name}"
