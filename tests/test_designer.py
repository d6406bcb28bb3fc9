"""The ``designer`` model: a design task's estimate first, then corrected with ``simulate``'s sensors.

Its parts are checked on their own (reading a sensor table back, writing its programs, the next
value it tries), and the whole through ``meceng run --agent loop``: the first program (the
estimate) misses, the final one meets the requirement, and the tools never told it the target."""

from __future__ import annotations

import asyncio
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from meceng.llm.backend_designer import PROBE_NAME, DesignerBackend, DesignPlan, program_with, sensor_table
from meceng.llm.types import ChatRequest
from meceng.tasks.registry import default_registry

SLUG = "flying_bars_late_gap"


def instance(seed: int = 5):
    registry = default_registry()
    return registry.instance_of(registry.get(SLUG), seed, "open")


def linear_plan(target: float = 10.0) -> DesignPlan:
    """A made-up system whose quantity is 3 x + 1 while the estimate believes 2 x."""
    return DesignPlan((("x", 0.0, 10.0),), target, 0.01 * target, lambda value: {"x": value / 2.0},
                      lambda t, q, design: float(q[-1, 0]))


def test_sensor_table_reads_the_probes_rows_back_from_a_simulate_answer() -> None:
    answer = "\n".join([
        "stage: solved (no error)",
        "Sensors (values interpolated between the stored steps; window 0 to 1 s, 3 times):",
        "- #0 other: Body sensor: Position of body #1; stored every 0.001 s",
        "  t, column 0",
        "  0, 5",
        "  1, 6",
        f"- #1 {PROBE_NAME}: UserFunction sensor: the values its sensorUserFunction returns; stored every 0.001 s",
        "  column 0, over every stored step from 0 to 1 s: largest 2 at t = 1 s, smallest 0 at t = 0 s",
        "  t, column 0, column 1",
        "  0, 0, -1e-05",
        "  0.5, 1, 2.5",
        "  1, 2, 3",
        "- #2 last: Body sensor",
    ])
    rows = sensor_table(answer)
    assert rows is not None and rows.shape == (3, 3)
    assert rows[0].tolist() == [0.0, 0.0, -1e-05] and rows[-1].tolist() == [1.0, 2.0, 3.0]
    assert sensor_table(answer.replace(PROBE_NAME, "renamed")) is None


def test_its_programs_declare_its_values_and_measure_only_while_it_measures() -> None:
    gold = instance().reference_program
    trying = program_with(f"```python\n{gold}\n```", {"stiffness": 2500.0}, probe=True)
    assert [line for line in trying.splitlines() if line.startswith("DESIGN = ")] == ['DESIGN = {"stiffness": 2500.0}']
    assert trying.index(PROBE_NAME) < trying.index("mbs.Assemble()")
    answer = program_with(gold, {"stiffness": 2500.0}, probe=False)
    assert PROBE_NAME not in answer and 'DESIGN = {"stiffness": 2500.0}' in answer
    assert str(instance().design.gold["stiffness"]) not in answer.split("DESIGN = ")[1].splitlines()[0]


def test_the_next_value_comes_from_the_estimates_sensitivity_then_the_secant() -> None:
    backend, plan = DesignerBackend({}), linear_plan()
    first = backend.next_design(plan, [])
    assert first == {"x": 5.0}  # the estimate: 2 x = 10
    # it measured 16 at x = 5: the estimate would change x by (10 - 16) / 2 = -3
    second = backend.next_design(plan, [(first, 16.0)])
    assert second == {"x": 2.0}
    # the secant through (5, 16) and (2, 7) hits 3 x + 1 = 10 exactly
    third = backend.next_design(plan, [(first, 16.0), (second, 7.0)])
    assert third["x"] == pytest.approx(3.0)
    # clipped to the range, and a run that never showed the quantity moves on along the range
    assert backend.next_design(linear_plan(100.0), [])["x"] == 10.0
    assert backend.next_design(plan, [({"x": 5.0}, float("nan"))])["x"] == pytest.approx(6.0)


def request(messages: list[dict]) -> ChatRequest:
    gold = "```python\nDESIGN = {'x': 7.0}\nmbs.Assemble()\nmbs.SolveDynamic(simulationSettings)\n```"
    return ChatRequest(tuple(messages), "code", "k", gold=gold, tools=({"name": "simulate"},))


def probe_answer(value: float) -> str:
    return (f"- #0 {PROBE_NAME}: UserFunction sensor\n  t, column 0\n  0, 0\n  1, {value}\n")


def test_it_answers_once_a_run_lands_within_a_third_of_the_tolerance_and_never_with_the_gold_value() -> None:
    backend = DesignerBackend({"k": linear_plan()})
    messages: list[dict] = [{"role": "user", "content": "design x"}]
    response = asyncio.run(backend.chat(request(messages)))
    assert response.tool_calls and response.tool_calls[0].name == "simulate"
    for value in (16.0, 7.0, 10.02):  # 3 x + 1 at x = 5, 2 and 3.0067
        messages += [{"role": "assistant", "content": response.content,
                      "tool_calls": [c.to_json() for c in response.tool_calls]},
                     {"role": "tool", "content": probe_answer(value)}]
        response = asyncio.run(backend.chat(request(messages)))
    assert not response.tool_calls, response.content
    assert 'DESIGN = {"x": 3.0}' in response.content and PROBE_NAME not in response.content
    assert "7.0" not in response.content


def run_designer(tmp_path: Path, agent: str) -> dict:
    out = tmp_path / agent
    done = subprocess.run([sys.executable, "-m", "meceng", "run", "--model", "designer", "--levels", "4", "--agent",
                           agent, "--only", SLUG, "--seed", "5", "--variations", "1", "--out", str(out)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    journal = next(out.glob("*/journal.jsonl"))
    return json.loads(journal.read_text().splitlines()[0])


def test_through_the_loop_its_estimate_misses_and_its_corrected_value_meets_the_requirement(tmp_path: Path) -> None:
    record = run_designer(tmp_path, "loop")
    agent, design = record["agent"], record["design"]
    assert agent["first_design"]["passed"] is False  # the estimate alone (24 tolerances off)
    assert design["passed"] is True and record["overall"] is True, design
    calls = agent["tool_calls"].get("simulate", 0)
    assert 2 <= calls <= 5, agent["tool_calls"]
    assert design["values"]["stiffness"] != instance().design.gold["stiffness"]


@pytest.mark.slow  # a second whole run (~40 s); the loop's run above covers the default suite
def test_without_tools_it_answers_the_estimate_the_task_models_check_measures(tmp_path: Path) -> None:
    from meceng.tasks.design_check import check_estimate

    record = run_designer(tmp_path, "pipeline")
    check = check_estimate(instance())
    assert record["design"]["values"] == pytest.approx(check.design, rel=1e-5)
    assert record["design"]["passed"] is check.passed is False
    assert np.isclose(record["design"]["value"], check.value, rtol=1e-5)  # the values agree to 1e-5 above
