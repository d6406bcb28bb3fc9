"""The agent's eyes: a scripted model that repairs only what the inspector or the picture shows.

Each scripted model reads the description's numbers (as a model would) and the tool's answer, and
changes its program only when the answer shows a difference: so a run passes only if the tool
showed the mistake. The three-body system is the RRR robot; the faults are ones models make (a
link's position without its half length, a cuboid's side lengths in the wrong order).
"""

from __future__ import annotations

import base64
import json
import re
from pathlib import Path

import numpy as np
import pytest
from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.inspect.answer import num
from meceng.inspect.forms import box_half_sizes
from meceng.inspect.view import build_view
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

ROBOT = "rrr_articulated_robot_with_3d_cubic_trajectory"
PLACED = "referencePosition=[length2 + 0.5 * length3, 0, length1]"
MISPLACED = "referencePosition=[length2 + length3, 0, length1]"  # the forearm's centre at its tip
TURNED = "sideLengths=[w, length2, w]"  # the upper arm's long side along y


def tool_call(name: str, **arguments) -> dict:
    body = chat_reply("")
    body["message"]["tool_calls"] = [{"function": {"name": name, "arguments": arguments}}]
    return body


def scripted(instance, draft: str, tool: str, wrong, seen: list[str]):
    """A model that calls ``tool`` on its draft and answers the ground truth only when ``wrong``
    finds the mistake in the tool's answer (else the draft again); the answers go to ``seen``."""
    def responder(body):
        messages = body["messages"]
        if "<components>" in messages[0]["content"]:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        results = [m for m in messages if m["role"] == "tool"]
        if not results:
            return 200, tool_call(tool, code=draft), {}
        seen.append(results[-1]["content"])
        repaired = wrong(results[-1]["content"])
        return 200, chat_reply(gold_code(instance.reference_program if repaired else draft)), {}
    return responder


def _floats(text: str) -> list[float]:
    return [float(x) for x in text.split(",")]


async def _agent_run(tmp_path: Path, responder, vision: bool = False) -> tuple[dict, list]:
    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="agent:1b", backend="ollama", hosts=(server.url,), vision=vision)
        settings = RunSettings(llm=llm, levels=("2",), only=(ROBOT,), variations=1, out=tmp_path, run_name="eyes",
                               progress=False, agent="loop", max_rounds=4)
        run = json.loads((await run_benchmark(settings)).read_text())
        return run["tasks"][0], server.requests


async def test_the_inspector_shows_the_third_body_and_the_model_repairs_it(tmp_path: Path) -> None:
    instance = default_registry().get(ROBOT).instance(0)
    draft = instance.reference_program.replace(PLACED, MISPLACED)
    assert draft != instance.reference_program
    p = instance.params
    stated = (p["length2"] + p["length3"] / 2, 0.0, p["length1"])  # link 3's position in the description
    seen: list[str] = []

    def wrong(answer: str) -> bool:
        match = re.search(r"#3 RigidBody: [^\n]*?position \(([^)]*)\)", answer)
        return bool(match) and not np.allclose(_floats(match.group(1)), stated, atol=1e-3)

    responder = scripted(instance, draft, "simulate", wrong, seen)
    task, _ = await _agent_run(tmp_path, responder)
    assert f"position ({num(p['length2'] + p['length3'])}, 0, {num(p['length1'])})" in seen[0]
    assert task["agent"]["first_overall"] is False and task["overall"] is True
    assert task["agent"]["tool_calls"] == {"simulate": 1}


async def test_simulate_shows_every_bodys_final_position_and_answers_requests() -> None:
    """On a three-body task the inspector was not built against (the four-bar with rigid links)."""
    held_out = default_registry().get("four_bar_mechanism_rigid_bodies").instance(3)
    text = (await Toolbox(held_out, rigid_catalog()).call("simulate", {"code": held_out.reference_program})).text
    end = held_out.sim.end_time
    for body in (1, 2, 3):
        assert re.search(rf"t={num(end)} #{body} RigidBody: position \(", text), body
    instance = default_registry().get(ROBOT).instance(1)
    toolbox = Toolbox(instance, rigid_catalog())
    focused = (await toolbox.call("simulate", {"code": instance.reference_program, "bodies": [3],
                                               "times": [0.5], "quantities": ["velocity"]})).text
    assert re.search(r"t=0\.5 #3 RigidBody: velocity \(", focused)
    assert "#1 RigidBody:" not in focused.split("connectors")[0] and "angles (" not in focused.split("motion")[1]


async def test_the_default_answer_of_the_largest_level_2_task_is_bounded_and_says_what_it_cut() -> None:
    instance = default_registry().get("grid_mesh_and_large_sphere_impact").instance(0)
    text = (await Toolbox(instance, rigid_catalog()).call("simulate", {"code": instance.reference_program})).text
    assert len(text) < 5000, len(text)
    assert "25 × MassPoint of mass 0.0405 (#1–#25): positions from (0.153, 0.153, 0) to (0.765, 0.765, 0)" in text
    assert "60 × SpringDamper" in text and "25 × SphereSphereContact" in text


async def test_a_shifted_centre_of_mass_shows() -> None:
    instance = default_registry().get("rigid_rotor_unbalanced").instance(0)
    text = (await Toolbox(instance, rigid_catalog()).call("simulate", {"code": instance.reference_program})).text
    line = next(x for x in text.splitlines() if x.strip().startswith("#1 RigidBody"))
    assert "centre of mass (0, 0, " in line and "from its reference point" in line


async def test_the_inertia_box_is_the_bodys_own() -> None:
    """Physics: a homogeneous cuboid's inertia-equivalent box is the cuboid itself."""
    instance = default_registry().get(ROBOT).instance(0)
    run = await execute(instance.reference_program, instance.sim.block(), ExecutionLimits(inspect_times=(0.5,)))
    view = build_view(run.items, run.system, run.inspection, run.trajectory, run.times)
    p = instance.params
    half = box_half_sizes(view.body(2))
    assert sorted(2 * half) == pytest.approx(sorted([p["length2"], 0.05, 0.05]), rel=1e-9)
    # the revolute joints' axes in global terms, as the description states them
    axes = [c.axis for c in view.connectors if c.kind == "RevoluteJoint"]
    assert axes[0] == pytest.approx((0, 0, 1)) and axes[1] == pytest.approx((0, -1, 0))


async def test_the_picture_shows_a_turned_box_and_the_model_repairs_it(tmp_path: Path) -> None:
    """Side lengths in the wrong order: same mass, same principal moments, same position; the
    snapshot's box is turned (the inspector's inertia in body axes shows it too, see
    test_inspector_reads_right)."""
    instance = default_registry().get(ROBOT).instance(0)
    draft = instance.reference_program.replace("sideLengths=[length2, w, w]", TURNED)
    assert draft != instance.reference_program
    seen: list[str] = []

    def wrong(answer: str) -> bool:
        match = re.search(r"#2 RigidBody at [^\n]*longest edge along \(([^)]*)\)", answer)
        return bool(match) and not np.allclose(np.abs(_floats(match.group(1))), (1, 0, 0), atol=1e-6)

    responder = scripted(instance, draft, "snapshot", wrong, seen)
    task, _ = await _agent_run(tmp_path, responder)
    assert "the picture in words" in seen[0] and "longest edge along (0, 1, 0)" in seen[0]
    assert task["agent"]["first_overall"] is False and task["overall"] is True


async def test_a_vision_model_gets_the_snapshot_as_a_png(tmp_path: Path) -> None:
    instance = default_registry().get(ROBOT).instance(0)
    answer = await Toolbox(instance, rigid_catalog(), vision=True).call(
        "snapshot", {"code": instance.reference_program, "time": 1.0})
    png = base64.b64decode(answer.images[0])
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 20000

    def responder(body):
        messages = body["messages"]
        if "<components>" in messages[0]["content"]:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        if not any(m["role"] == "tool" for m in messages):
            return 200, tool_call("snapshot", code=instance.reference_program), {}
        return 200, chat_reply(gold_code(instance.reference_program)), {}

    task, requests = await _agent_run(tmp_path, responder, vision=True)
    images = [image for r in requests for m in r["messages"] for image in m.get("images", [])]
    assert images and base64.b64decode(images[0]).startswith(b"\x89PNG")
    tool_entry = next(m for m in task["agent"]["transcript"] if m["role"] == "tool")
    assert tool_entry["images"][0].startswith("PNG, ") and "base64" not in json.dumps(task)[:0]
    assert task["overall"] is True


async def test_bad_tool_arguments_are_answered_not_raised() -> None:
    instance = default_registry().get("single_pendulum").instance(0)
    toolbox = Toolbox(instance, rigid_catalog())
    answer = (await toolbox.call("simulate", {"code": instance.reference_program, "times": ["soon"]})).text
    assert "bad arguments for tool simulate" in answer
    answer = (await toolbox.call("snapshot", {"code": instance.reference_program, "time": [1, 2]})).text
    assert "picture in words" in answer  # a list of times: the first inside the run is taken
    broken = (await toolbox.call("simulate", {"code": "import exudyn as exu\nraise ValueError('no')"})).text
    assert broken.startswith("stage: started; error: ") and "ValueError" in broken


async def test_the_part_snapshot_shows_the_agents_part_and_its_interfaces() -> None:
    from meceng.catalog.catalogs import part_catalog

    part = default_registry().get("flexible_beam_part").instance(0)
    other = re.sub(r"^beam_length = .*$", "beam_length = 0.3", part.reference_program, flags=re.M)
    words = (await Toolbox(part, part_catalog()).call("snapshot", {"code": other})).text
    assert "to (0.3, " in words and "interface 'right': centre (0.3, 0, 0), mean outward normal x" in words
    picture = await Toolbox(part, part_catalog(), vision=True).call("snapshot", {"code": other})
    assert base64.b64decode(picture.images[0]).startswith(b"\x89PNG")


async def test_a_program_that_replaces_exudyns_enums_is_read_with_the_real_ones() -> None:
    """The inspector reads the system with enums bound before the program ran: a program's own
    object in their place is never touched (its code would run while the harness reads), so the
    answer still has every body's state."""
    instance = default_registry().get("single_pendulum").instance(0)
    evil = instance.reference_program.replace("mbs.Assemble()", """
class Sneaky:
    def __getattr__(self, name):
        raise RuntimeError('the harness touched the program object ' + name)
exu.OutputVariableType = Sneaky()
exu.ConfigurationType = Sneaky()
mbs.Assemble()""")
    assert evil != instance.reference_program
    text = (await Toolbox(instance, rigid_catalog()).call("simulate", {"code": evil})).text
    assert "stage: solved" in text and "position (" in text and "touched" not in text
