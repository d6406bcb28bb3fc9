"""Grading programs: a changed parameter fails at graph content with the right category; a
different order of adding items (same body order) still passes topology and content."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from meceng.eval.graph import compare_graphs
from meceng.pipeline import evaluate_program
from meceng.tasks.registry import default_registry

CRADLE_REORDERED = '''
import exudyn as exu
from exudyn.utilities import *
import numpy as np
SC = exu.SystemContainer()
mbs = SC.AddSystem()
m, r, L, g, k, e = {mass!r}, {radius!r}, {length!r}, {gravity!r}, {stiffness!r}, {restitution!r}
spheres = []
for i in range(4):
    p = [-L, 0, L] if i == 0 else [i * (2 * r + 0.002), 0, 0]
    spheres.append(mbs.CreateMassPoint(referencePosition=p, mass=m, gravity=[0, 0, -g]))
# contacts before the constraints, in reverse order, and the ground created late
for i in reversed(range(3)):
    mbs.CreateSphereSphereContact(itemNumbers=[spheres[i], spheres[i + 1]], spheresRadii=[r, r],
                                  contactStiffness=k, contactDamping=0, impactModel=2,
                                  restitutionCoefficient=e)
ground = mbs.CreateGround()
for i in reversed(range(4)):
    mbs.CreateDistanceConstraint(itemNumbers=[ground, spheres[i]],
                                 localPosition0=[i * (2 * r + 0.002), 0, L], distance=L)
mbs.Assemble()
sim = exu.SimulationSettings()
sim.timeIntegration.numberOfSteps = 10   # replaced by the ground truth's block
mbs.SolveDynamic(sim)
'''


async def test_reordered_items_pass_topology_content_and_solution() -> None:
    instance = default_registry().get("newtons_cradle").instance(2)
    code = CRADLE_REORDERED.format(**instance.params)
    verdict, candidate, _ = await evaluate_program(instance, code)
    assert candidate.solved, candidate.error
    assert verdict.stage("topology_match").passed
    assert verdict.stage("graph_content_match").passed, verdict.stage("graph_content_match").detail
    assert verdict.stage("solution_match").passed, verdict.stage("solution_match").detail
    assert verdict.overall


async def test_wrong_body_order_passes_graph_but_fails_solution() -> None:
    instance = default_registry().get("double_mass_oscillator").instance(1)
    program = instance.reference_program
    lines = program.splitlines()
    first = next(i for i, ln in enumerate(lines) if "oMass1 = mbs.CreateMassPoint" in ln)
    second = next(i for i, ln in enumerate(lines) if "oMass2 = mbs.CreateMassPoint" in ln)
    assert first < second
    block1 = lines[first:second]
    end2 = second + 1
    while end2 < len(lines) and lines[end2].startswith(" "):
        end2 += 1
    block2 = lines[second:end2]
    swapped = "\n".join(lines[:first] + block2 + block1 + lines[end2:])
    verdict, _, _ = await evaluate_program(instance, swapped)
    assert verdict.stage("topology_match").passed and verdict.stage("graph_content_match").passed
    assert verdict.stage("solution_match").passed is False


@pytest.mark.parametrize(("slug", "param", "category"), [
    ("single_mass_oscillator", "stiffness", "connector/constraint"),
    ("single_pendulum", "gravity", "gravity and load"),
    ("flying_mass_point", "mass", "inertia and mass"),
])
async def test_changed_parameter_fails_graph_content(slug: str, param: str, category: str) -> None:
    instance = default_registry().get(slug).instance(4)
    value = instance.params[param]
    program = instance.reference_program.replace(f"\n{param} = {value!r}\n", f"\n{param} = {value * 1.05!r}\n")
    assert program != instance.reference_program
    verdict, _, _ = await evaluate_program(instance, program)
    assert verdict.first_failure == "graph_content_match"
    assert category in verdict.error_categories
    assert verdict.stage("topology_match").passed


def test_graph_counts_and_topology_levels() -> None:
    base = {"nodes": [{"nodeType": "Point", "referenceCoordinates": [0, 0, 0]}],
            "objects": [{"objectType": "MassPoint", "mass": 1.0, "nodeNumber": 0}],
            "markers": [], "loads": [], "sensors": []}
    extra = json.loads(json.dumps(base))
    extra["objects"].append({"objectType": "Ground", "referencePosition": [0, 0, 0]})
    assert compare_graphs(extra, base).counts_match is False
    rewired = json.loads(json.dumps(base))
    rewired["nodes"].append({"nodeType": "Point", "referenceCoordinates": [0, 0, 0]})
    rewired["objects"].append({"objectType": "MassPoint", "mass": 1.0, "nodeNumber": 0})
    ref = json.loads(json.dumps(rewired))
    ref["objects"][1]["nodeNumber"] = 1
    result = compare_graphs(rewired, ref)
    assert result.counts_match and result.topology_match is False


def test_cli_evaluate_reports_stages_as_json(tmp_path: Path) -> None:
    instance = default_registry().get("single_mass_oscillator").instance(3)
    value = instance.params["mass"]
    wrong = instance.reference_program.replace(f"\nmass = {value!r}\n", f"\nmass = {value * 2!r}\n")
    path = tmp_path / "wrong.py"
    path.write_text(wrong)
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "evaluate", "single_mass_oscillator", "--seed", "3",
                           "--code", str(path), "--json"], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1, proc.stderr
    data = json.loads(proc.stdout)
    assert [s["name"] for s in data["stages"]] == ["choose_components", "finished_assemble", "topology_match",
                                                   "graph_content_match", "solver_success", "solution_match"]
    assert data["overall"] is False and data["first_failure"] == "graph_content_match"
    assert data["error_categories"] == ["inertia and mass"]
    right = tmp_path / "right.py"
    right.write_text(instance.reference_program)
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "evaluate", "3", "--seed", "3", "--code", str(right)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0 and "overall: success" in proc.stdout


async def test_symmetric_grid_in_another_order_is_compared_quickly() -> None:
    """A net of identical springs: items in another order still match, and a wrong stiffness is
    reported on the springs only (the partner mapping follows the geometry). Quickly: the graph
    comparison is timed (the runs are not: behaviour compares this contact model at 8 x its steps)."""
    import time

    instance = default_registry().get("grid_mesh_and_large_sphere_impact").instance(3)
    lines = instance.reference_program.splitlines()
    rows = next(k for k, ln in enumerate(lines) if ln.startswith("for j in range(1, n + 1):")
                and "range(0, n + 1)" in lines[k + 1])
    cols = next(k for k, ln in enumerate(lines) if ln.startswith("for i in range(1, n + 1):")
                and "range(0, n + 1)" in lines[k + 1])
    swapped = "\n".join(lines[:rows] + lines[cols:cols + 3] + lines[rows:rows + 3] + lines[cols + 3:])
    verdict, candidate, reference = await evaluate_program(instance, swapped)
    assert verdict.stage("graph_content_match").passed and verdict.stage("solution_match").passed
    k = instance.params["spring_stiffness"]
    wrong = swapped.replace(f"\nspring_stiffness = {k!r}\n", f"\nspring_stiffness = {k * 1.05!r}\n")
    verdict, other, _ = await evaluate_program(instance, wrong)
    assert verdict.first_failure == "graph_content_match"
    assert verdict.error_categories == ("connector/constraint",)
    t0 = time.perf_counter()
    for run in (candidate, other):
        compare_graphs(run.items, reference.items)
    assert time.perf_counter() - t0 < 30
