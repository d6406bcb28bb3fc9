"""Level 4 (design tasks): the DESIGN literal and the one simulation read statically, the spec
judged on the reference built with the answer's values, behaviour against that reference; every
design model's instances are feasible and its gold answer passes; the target measured here in
this process is what the sandbox measures."""

from __future__ import annotations

import asyncio
import importlib
import json
import pickle
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from meceng.eval.design import count_simulations, judge_design, read_design
from meceng.tasks.design_base import DesignModel
from meceng.tasks.design_measures import first_crossing, mean_period, settling_time
from meceng.tasks.registry import default_registry

RANGES = {"torque": (1.0, 4.0)}
GOLD = "flying_bars_late_gap"


def test_design_literal_is_read_with_its_names_and_ranges() -> None:
    assert read_design("DESIGN = {'torque': 2.5}\n", RANGES).values == {"torque": 2.5}
    assert read_design("DESIGN: dict = {'torque': 2}\n", RANGES).values == {"torque": 2.0}


@pytest.mark.parametrize(("code", "words"), [
    ("x = 1\n", "no top-level DESIGN"),
    ("def f():\n    DESIGN = {'torque': 2.0}\n", "not at the program's top level"),
    ("t = 2.0\nDESIGN = {'torque': t}\n", "not a literal"),
    ("DESIGN = {'torque': 2 * 1.1}\n", "not a literal"),
    ("DESIGN = {'torque': 5.0}\n", "outside its range [1, 4]"),
    ("DESIGN = {'torque': True}\n", "not a finite number"),
    ("DESIGN = {'torque': float('nan')}\n", "not a literal"),
    ("DESIGN = {'torque': 2.0, 'mass': 1.0}\n", "not a design variable: mass"),
    ("DESIGN = {}\n", "missing torque"),
    ("DESIGN = [2.0]\n", "not a dict"),
    ("DESIGN = {'torque': 2.0}\nDESIGN['torque'] = 3.0\n", "more than once"),
    ("DESIGN = {'torque': 2.0}\nDESIGN.update(torque=3.0)\n", "more than once"),
    ("DESIGN = {'torque': 2.0\n", "does not parse"),
])
def test_a_bad_design_is_refused_with_its_reason(code: str, words: str) -> None:
    declared = read_design(code, RANGES)
    assert declared.values is None and words in (declared.error or "")


@pytest.mark.parametrize(("code", "count", "words"), [
    ("mbs.SolveDynamic(s)\n", 1, None),
    ("exu.SolveDynamic(mbs, s)\n", 1, None),
    ("x = 1\n", 0, "runs no simulation"),
    ("mbs.SolveStatic(s)\nmbs.SolveDynamic(s)\n", 2, "2 solver calls"),
    ("for k in range(3):\n    mbs.SolveDynamic(s)\n", 1, "inside a loop"),
    ("while True:\n    mbs.SolveDynamic(s)\n    break\n", 1, "inside a loop"),
    ("solver = exu.MainSolverImplicitSecondOrder()\nmbs.SolveDynamic(s)\n", 1, "solver object"),
])
def test_exactly_one_simulation(code: str, count: int, words: str | None) -> None:
    found = count_simulations(code)
    assert found.count == count
    assert (found.error is None) if words is None else (words in (found.error or ""))


def test_the_spec_verdict_and_its_margin() -> None:
    inside = judge_design(1.005, 1.0, 0.01, {"torque": 2.0}, "time", "s")
    assert inside.passed and inside.margin == pytest.approx(0.5)
    outside = judge_design(1.02, 1.0, 0.01, {"torque": 2.0}, "time", "s")
    assert not outside.passed and outside.margin == pytest.approx(-1.0) and "+2.00 %" in outside.detail
    assert not judge_design(float("nan"), 1.0, 0.01, {"torque": 2.0}, "time", "s").passed


def test_measurements_on_signals_with_known_answers() -> None:
    t = np.linspace(0.0, 2.0, 2001)
    assert first_crossing(t, t**2, 1.0) == pytest.approx(1.0, abs=1e-6)
    assert np.isnan(first_crossing(t, t**2, 9.0))
    assert mean_period(t, np.sin(2 * np.pi * 5 * t)) == pytest.approx(0.2, rel=1e-4)
    decay = np.exp(-3 * t)
    assert settling_time(t, decay, 0.0, np.exp(-3.0)) == pytest.approx(1.0, abs=2e-3)


def _design_models() -> list[DesignModel]:
    return [m for m in default_registry() if isinstance(m, DesignModel)]


def test_an_estimate_is_solved_on_its_grid_for_the_closest_value_the_first_of_equals() -> None:
    from meceng.tasks.design_base import closest_on_grid

    grid = np.linspace(0.0, 2.0, 201)
    assert closest_on_grid(grid, lambda x: x**2, 2.0) == pytest.approx(1.41)
    assert closest_on_grid(grid, lambda x: (x - 1.0) ** 2, 0.25) == pytest.approx(0.5)  # 1.5 predicts the same


def test_level_4_is_big_enough_and_every_module_is_named_after_its_slug() -> None:
    models = _design_models()
    assert len(models) >= 20, [m.slug for m in models]
    assert len({m.system.slug for m in models}) >= 12
    assert {m.spec.kind for m in models} >= {"event_time", "position", "extreme", "period", "settling_time"}
    assert any(len(m.variables) >= 2 for m in models)
    for model in models:
        assert importlib.import_module(f"meceng.tasks.design.{model.slug}").TASK is model
        assert model.estimate_text and model.spec_text and model.level == "4"
        assert all(v.low < v.high for v in model.variables)


@pytest.mark.parametrize("model", _design_models(), ids=lambda m: m.slug)
def test_every_instance_has_a_feasible_gold_design_inside_its_range(model: DesignModel) -> None:
    for seed in (0, 1):
        instance = model.instance(seed)
        task = instance.design
        for variable in task.variables:
            assert variable.low <= task.gold[variable.name] <= variable.high
        assert np.isfinite(task.target) and task.target != 0
        # the text states the target and the range, never the gold design
        assert f"{task.target:g}" in instance.description and "DESIGN = {" in instance.description
        assert pickle.loads(pickle.dumps(instance)).design.target == task.target


@pytest.mark.parametrize("model", _design_models(), ids=lambda m: m.slug)
def test_the_prompt_documents_every_call_and_user_function_the_gold_program_needs(model: DesignModel) -> None:
    """A reader that knows only the prompt can write the gold program: each ``mbs.CreateX`` and each
    ``...UserFunction=`` keyword the reference uses is in the code prompt (round 6's readers wrote a
    cubic spring's and a hardening shaft's user functions from memory)."""
    from meceng.pipeline import RunSettings, instance_prompts

    text = instance_prompts(model.instance(0), RunSettings(levels=("4",)))[-1].text
    source = model.model_source()
    needed = set(re.findall(r"mbs\.(Create\w+)\(", source)) | set(re.findall(r"(\w+UserFunction)=", source))
    assert needed, source
    assert {name for name in needed if name not in text} == set()


def _evaluate(slug: str, seed: int, program: str, tmp_path: Path) -> tuple[int, dict]:
    path = tmp_path / "answer.py"
    path.write_text(program)
    done = subprocess.run([sys.executable, "-m", "meceng", "evaluate", slug, "--seed", str(seed), "--code",
                           str(path), "--json"], capture_output=True, text=True, timeout=600)
    return done.returncode, json.loads(done.stdout)


def test_gold_passes_and_the_sandbox_measures_the_target_measured_here(tmp_path: Path) -> None:
    instance = default_registry().get(GOLD).instance(2)
    status, data = _evaluate(GOLD, 2, instance.reference_program, tmp_path)
    assert status == 0 and data["overall"], data["stages"]
    design = data["design"]
    assert design["passed"] and design["values"] == instance.design.gold
    assert design["target"] == instance.design.target and design["tolerance"] == pytest.approx(
        0.01 * instance.design.target)
    assert abs(design["value"] - instance.design.target) < 5e-4 * instance.design.target  # rounding to 4 digits


def test_a_missed_spec_a_changed_system_and_a_second_simulation_fail_at_their_stages(tmp_path: Path) -> None:
    instance = default_registry().get(GOLD).instance(2)
    gold = instance.reference_program
    literal = f"DESIGN = {{'stiffness': {instance.design.gold['stiffness']!r}}}"
    assert literal in gold
    missed = gold.replace(literal, "DESIGN = {'stiffness': 500.0}")
    status, data = _evaluate(GOLD, 2, missed, tmp_path)
    assert status == 1 and data["first_failure"] == "design_met" and not data["design"]["passed"]
    assert data["design"]["margin"] < 0
    # the spec met by another system: the declared value is right, the program runs a different stiffness
    other = gold.replace("stiffness = DESIGN['stiffness']", "stiffness = 1.1 * DESIGN['stiffness']")
    status, data = _evaluate(GOLD, 2, other, tmp_path)
    assert status == 1 and data["first_failure"] == "behaviour_match" and data["design"]["passed"]
    twice = gold + "mbs.SolveDynamic(simulationSettings)\n"
    status, data = _evaluate(GOLD, 2, twice, tmp_path)
    assert status == 1 and data["first_failure"] == "one_simulation" and data["infrastructure_error"] is None


def test_tasks_show_json_carries_the_design_block() -> None:
    done = subprocess.run([sys.executable, "-m", "meceng", "tasks", "show", GOLD, "--seed", "0", "--json"],
                          capture_output=True, text=True, timeout=300)
    design = json.loads(done.stdout)["design"]
    model = default_registry().get(GOLD)
    assert design["variables"] == {v.name: [v.low, v.high] for v in model.variables} == {"stiffness": design[
        "variables"]["stiffness"]}
    assert design["system"] == "spring_coupled_flying_rigid_bodies"
    assert design["spec"]["kind"] == "extreme" and design["spec"]["relative_tolerance"] == 0.01
    assert design["estimate"]["passed"] is False and design["estimate"]["error_in_tolerances"] > 1


def test_simulate_reads_the_programs_sensors_but_never_the_target() -> None:
    from meceng.agents.toolbox import Toolbox
    from meceng.catalog.catalogs import rigid_catalog

    instance = default_registry().get(GOLD).instance(2)
    program = instance.reference_program.replace("mbs.Assemble()", (
        "mbs.AddSensor(SensorBody(bodyNumber=oBody1, outputVariableType=exu.OutputVariableType.AngularVelocity,"
        " storeInternal=True))\nmbs.Assemble()"))
    answer = asyncio.run(Toolbox(instance, rigid_catalog()).call(
        "simulate", {"code": program, "sensor_window": [0.0, 0.1], "sensor_samples": 5})).text
    assert "Body sensor: AngularVelocity of body #0" in answer and "window 0 to 0.1 s, 5 times" in answer
    rows = [line for line in answer.splitlines() if line.startswith("  0.1, ")]
    assert rows, answer[-800:]
    assert str(instance.design.target) not in answer and "target" not in answer.lower()
    # the extremes say their window, and are taken over every stored step in it, not over the 5 rows shown
    extremes = next(line for line in answer.splitlines() if line.startswith("  column 2, "))
    assert "over every stored step from 0 to 0.1 s: largest" in extremes
    table = [[float(x) for x in line.split(", ")] for line in answer.splitlines()
             if line.startswith("  0") and line.count(", ") == 3]
    smallest = float(extremes.split("smallest ")[1].split(" ")[0])
    assert len(table) == 5 and smallest < min(row[3] for row in table)
