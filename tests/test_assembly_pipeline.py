"""Level 3b: the cantilever beam against beam theory, wrong assemblies fail, a failed part stops its assembly."""

from __future__ import annotations

import json
import re
from pathlib import Path

import exudyn as exu
import numpy as np
import pytest
from assemblies import build, run_assembly, saved_parts

from meceng.agents.prompts import gold_code
from meceng.eval.chain import evaluate_rigid
from meceng.llm.backend_gold import GoldBackend
from meceng.llm.types import ChatRequest, ChatResponse
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

STEEL_E, STEEL_RHO = 2.1e11, 7850.0


def _plain_beam_seed() -> int:
    model = default_registry().get("cantilever_beam")
    return next(s for s in range(50) if dict(model.choose_parts(s))["beam"] == "flexible_beam_part")


async def test_cantilever_static_deflection_is_bounded_by_beam_theory(tmp_path: Path) -> None:
    """Displacement FE models are stiffer than the exact solution and linear tetrahedra much so:
    the tip deflection lies between half and all of Euler-Bernoulli's (shear adds < 0.3 % here)."""
    instance = default_registry().get("cantilever_beam").instance(_plain_beam_seed())
    files = await saved_parts(instance, tmp_path)
    namespace = build(instance, files)
    mbs, beam = namespace["mbs"], namespace["beam"]
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.solution.file.write = False
    mbs.SolveStatic(settings)
    tip = mbs.GetMarkerOutput(beam["beam:right"], exu.OutputVariableType.Position)
    p = instance.params
    inertia = p["beam_width"] * p["beam_height"] ** 3 / 12
    weight = STEEL_RHO * p["g"] * p["beam_width"] * p["beam_height"]
    exact = p["tip_force"] * p["beam_length"] ** 3 / (3 * STEEL_E * inertia) + \
        weight * p["beam_length"] ** 4 / (8 * STEEL_E * inertia)
    assert 0.5 * exact < -tip[2] <= exact
    assert tip[0] == pytest.approx(p["beam_length"], abs=1e-6) and abs(tip[1]) < 1e-3 * exact + 1e-5

    # dynamically, released from the undeformed state, the tip swings about the static position
    run = await run_assembly(instance, files)
    assert run.solved, run.error
    assert run.system["degreeOfFreedom"] == run.system["nODE2"] - 7  # clamped: rigid frame fully locked


async def test_clamp_at_the_wrong_interface_fails(tmp_path: Path) -> None:
    instance = default_registry().get("cantilever_beam").instance(1)
    files = await saved_parts(instance, tmp_path)
    reference = await run_assembly(instance, files)
    wrong = instance.reference_program.replace("beam['beam:left']", "beam['beam:right']", 1)
    wrong = wrong.replace("markerNumber=beam['beam:right']", "markerNumber=beam['beam:left']")
    candidate = await run_assembly(instance, files, wrong)
    verdict = evaluate_rigid(candidate, reference, end_time=instance.sim.end_time, steps=instance.sim.steps,
                             selected=None, required=(), dependencies={})
    assert reference.solved and verdict.overall is False
    assert verdict.first_failure in ("graph_content_match", "solution_match", "topology_match")
    same = evaluate_rigid(reference, reference, end_time=instance.sim.end_time, steps=instance.sim.steps,
                          selected=None, required=(), dependencies={})
    assert same.overall


class BrokenFirstPart(GoldBackend):
    """Gold answers, except the part of variation 0, whose beam is 10 % too long."""

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.purpose == "code" and request.task_key.startswith("cantilever_beam@0/"):
            program = request.gold.split("```python\n", 1)[1].rsplit("```", 1)[0]
            program = re.sub(r"^beam_length = ", "beam_length = 1.1 * ", program, flags=re.M)
            return ChatResponse(content=gold_code(program), done_reason="stop", endpoint="script")
        return await super().chat(request)


def test_gold_assemblies_pass_and_a_failed_part_stops_its_assembly(tmp_path: Path) -> None:
    import asyncio

    settings = RunSettings(levels=("3b",), only=("cantilever_beam",), variations=2, out=tmp_path, run_name="asm",
                           progress=False, workers=2)
    run = json.loads(Path(asyncio.run(run_benchmark(settings, backend=BrokenFirstPart()))).read_text())
    records = {(r["level"], r["seed"]): r for r in run["tasks"]}
    assert len(run["tasks"]) == 4  # one part and one assembly per variation
    assert records[("3a", 0)]["overall"] is False and records[("3a", 0)]["origin"] == "cantilever_beam@0"
    stopped = records[("3b", 0)]
    assert stopped["overall"] is False and stopped["first_failure"] == "parts_overall"
    assert {s["name"]: s["passed"] for s in stopped["stages"]}["mbs_started"] is False
    assert "generation" not in stopped and stopped["tokens"]["completion"] == 0  # never asked, never run
    assert records[("3a", 1)]["overall"] and records[("3b", 1)]["overall"]
    assert records[("3b", 1)]["parts"] == {"beam": records[("3a", 1)]["origin"] + "/" +
                                           f"{records[('3a', 1)]['slug']}@1"}
    levels = run["summary"]["levels"]
    assert levels["3a"]["rates"]["overall"] == 0.5 and levels["3b"]["rates"]["mbs_started"] == 0.5
    assert np.isclose(levels["3b"]["rates"]["overall"], 0.5)


@pytest.mark.slow  # the part store's sharing and a rescore over a whole 3b run (~160 s)
def test_a_part_used_twice_is_made_once_and_rescoring_keeps_the_verdicts(tmp_path: Path) -> None:
    """Two identical bearing blocks: one part task, loaded into both slots; rescore grades parts and
    assembly again (with the assembly's master values and the saved parts) and agrees."""
    import asyncio

    from meceng.pipeline import rescore

    settings = RunSettings(levels=("3b",), only=("rotor_in_two_bearing_blocks_with_pedestal",), variations=1,
                           out=tmp_path, run_name="twice", progress=False, workers=2)
    run_json = Path(asyncio.run(run_benchmark(settings)))
    run = json.loads(run_json.read_text())
    parts = [t for t in run["tasks"] if t["level"] == "3a"]
    assembly = next(t for t in run["tasks"] if t["level"] == "3b")
    assert sorted(t["slug"] for t in parts) == ["balanced_rotor_part", "bearing_block_with_pedestal_part"]
    assert assembly["parts"]["block1"] == assembly["parts"]["block2"] and assembly["overall"]
    again = json.loads(asyncio.run(rescore(run_json.parent)).read_text())
    assert [(t["slug"], t["overall"], [s["passed"] for s in t["stages"]]) for t in again["tasks"]] == \
        [(t["slug"], t["overall"], [s["passed"] for s in t["stages"]]) for t in run["tasks"]]
    assert again["tasks"][-1]["execution"]["stage"] == "solved"
