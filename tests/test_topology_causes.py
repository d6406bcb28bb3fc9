"""Why topology failed: missing and surplus item types, inert items (cannot affect the motion),
connections — on real programs graded against the ground truth, and the report's cause table."""

from __future__ import annotations

from typing import Any

import pytest

from meceng.eval.tables import topology_cause_rows
from meceng.pipeline import evaluate_program
from meceng.tasks.registry import default_registry


def edited(slug: str, old: str, new: str, seed: int = 1) -> tuple[Any, str]:
    instance = default_registry().get(slug).instance(seed)
    assert old in instance.reference_program
    return instance, instance.reference_program.replace(old, new, 1)


CASES = {
    # name: (slug, old, new, cause, surplus/missing types, inert item types)
    "unused ground": ("single_mass_oscillator", "mbs.Assemble()",
                      "oExtra = mbs.CreateGround(referencePosition=[5, 0, 0])\nmbs.Assemble()",
                      "surplus inert items only", {"object:Ground": 1}, {"object:Ground"}),
    "zero load": ("single_mass_oscillator", "mbs.Assemble()",
                  "mbs.CreateForce(bodyNumber=oMass, loadVector=[0, 0, 0])\nmbs.Assemble()",
                  "surplus inert items only", {"load:ForceVector": 1, "marker:BodyPosition": 1},
                  {"load:ForceVector", "marker:BodyPosition"}),
    "a real extra load": ("single_mass_oscillator", "mbs.Assemble()",
                          "mbs.CreateForce(bodyNumber=oMass, loadVector=[0, 0, 1.5])\nmbs.Assemble()",
                          "surplus item types", {"load:ForceVector": 1, "marker:BodyPosition": 1}, set()),
    "missing spring": ("single_mass_oscillator", "mbs.CreateSpringDamper(", "0 and mbs.CreateSpringDamper(",
                       "missing item types", {"object:ConnectorSpringDamper": 1, "marker:BodyPosition": 2},
                       {"object:Ground", "object:MassPoint", "node:Point"}),
    "spring to the wrong mass": ("double_mass_oscillator", "itemNumbers=[oMass1, oMass2]",
                                 "itemNumbers=[oGround, oMass2]", "connections", {}, set()),
}


@pytest.mark.parametrize("name", list(CASES))
async def test_topology_cause_of_a_wrong_program(name: str) -> None:
    slug, old, new, cause, types, inert = CASES[name]
    instance, program = edited(slug, old, new)
    verdict, _, _ = await evaluate_program(instance, program)
    assert verdict.first_failure == "topology_match"
    causes = verdict.topology_causes
    assert causes is not None and causes["cause"] == cause
    assert (causes["missing"] if cause == "missing item types" else causes["surplus"]) == types
    assert {item.split("#")[0] for item in causes["inert"]} == inert
    assert f"cause: {cause}" in verdict.stage("topology_match").detail


async def test_a_correct_program_has_no_topology_causes() -> None:
    instance = default_registry().get("double_mass_oscillator").instance(1)
    verdict, _, _ = await evaluate_program(instance, instance.reference_program)
    assert verdict.overall and verdict.topology_causes is None


def test_report_counts_topology_failures_by_cause_per_model() -> None:
    def record(cause: str | None) -> dict[str, Any]:
        return {"level": "1", "first_failure": "topology_match" if cause else None,
                "topology_causes": {"cause": cause} if cause else None}

    runs = {"model-a": [record("surplus inert items only"), record("surplus inert items only"),
                        record("connections"), record(None)],
            "model-b": [record("missing item types"), {"level": "1", "first_failure": "topology_match"}]}
    rows = {r["model"]: r for r in topology_cause_rows(runs)}
    assert rows["model-a"]["failures"] == 3 and rows["model-a"]["surplus inert items only"] == 2
    assert rows["model-a"]["connections"] == 1 and rows["model-a"]["missing item types"] == 0
    assert rows["model-b"]["failures"] == 2 and rows["model-b"]["missing item types"] == 1
    assert rows["model-b"]["unknown"] == 1  # a record graded before causes were recorded


async def test_task_page_says_why_the_topology_differs() -> None:
    from meceng.viewer.pages import task_page

    slug, old, new, *_ = CASES["unused ground"]
    instance, program = edited(slug, old, new)
    verdict, _, _ = await evaluate_program(instance, program)
    record = {"slug": slug, "seed": 1, "level": "1", **verdict.to_json()}
    page = task_page(record, run_label="r", root="../../", program=program, reference=instance.reference_program,
                     file_links={}, images={}, neighbours=(None, None))
    assert "topology: why it differs" in page and "surplus inert items only" in page
    assert "object:Ground#3" in page
