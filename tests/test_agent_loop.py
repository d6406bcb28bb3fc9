"""The self-validating agent against a fake Ollama server that scripts tool-calling conversations."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import part_catalog, rigid_catalog
from meceng.inspect.answer import num
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

SLUG = "single_mass_oscillator"


def tool_call(name: str, **arguments) -> dict:
    body = chat_reply("")
    body["message"]["tool_calls"] = [{"function": {"name": name, "arguments": arguments}}]
    return body


def broken(program: str) -> str:
    return program.replace("mass=mass)", "mas=mass)")  # a hallucinated keyword: fails before assemble


async def _run(tmp_path: Path, responder, max_rounds: int = 4) -> dict:
    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="agent:1b", backend="ollama", hosts=(server.url,))
        settings = RunSettings(llm=llm, only=(SLUG,), variations=1, out=tmp_path, run_name="agent", progress=False,
                               agent="loop", max_rounds=max_rounds)
        run_json = await run_benchmark(settings)
        return {"run": json.loads(run_json.read_text()), "requests": server.requests}


async def test_agent_repairs_its_program_after_simulating(tmp_path: Path) -> None:
    instance = default_registry().get(SLUG).instance(0)

    def responder(body):
        messages = body["messages"]
        prompt = messages[0]["content"]
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        assert body["tools"] and {t["function"]["name"] for t in body["tools"]} >= {"simulate", "self_check"}
        tool_results = [m for m in messages if m["role"] == "tool"]
        if not tool_results:
            return 200, tool_call("simulate", code=broken(instance.reference_program)), {}
        assert "TypeError" in tool_results[-1]["content"]  # the agent sees its own error
        return 200, chat_reply("Fixed the keyword.\n" + gold_code(instance.reference_program)), {}

    result = await _run(tmp_path, responder)
    task = result["run"]["tasks"][0]
    agent = task["agent"]
    assert agent["first_overall"] is False and agent["first_failure"] == "finished_assemble"
    assert task["overall"] is True
    assert agent["rounds"] == 2 and agent["tool_calls"] == {"simulate": 1} and agent["stop_reason"] == "answered"
    roles = [m["role"] for m in agent["transcript"]]
    assert roles == ["user", "assistant", "tool", "assistant"]
    summary = result["run"]["summary"]["agent"]
    assert summary["first_overall"] == 0.0 and summary["final_overall"] == 1.0 and summary["uplift"] == 1.0
    assert summary["repaired"] == 1
    # the tool result went back as Ollama expects it
    last = result["requests"][-1]["messages"]
    assert last[-1]["role"] == "tool" and last[-1]["tool_name"] == "simulate"
    assert last[-2]["role"] == "assistant" and last[-2]["tool_calls"][0]["function"]["name"] == "simulate"


async def test_agent_without_tools_and_endless_agent_are_bounded(tmp_path: Path) -> None:
    instance = default_registry().get(SLUG).instance(0)

    def endless(body):
        prompt = body["messages"][0]["content"]
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, tool_call("self_check", code=instance.reference_program), {}

    result = await _run(tmp_path / "endless", endless, max_rounds=3)
    agent = result["run"]["tasks"][0]["agent"]
    assert agent["rounds"] == 3 and agent["stop_reason"] == "max_rounds"
    assert agent["tool_calls"] == {"self_check": 3}
    assert result["run"]["tasks"][0]["overall"] is True  # its last program is graded

    def direct(body):
        prompt = body["messages"][0]["content"]
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        return 200, chat_reply(gold_code(broken(instance.reference_program))), {}

    result = await _run(tmp_path / "direct", direct)
    task = result["run"]["tasks"][0]
    assert task["agent"]["rounds"] == 1 and task["agent"]["tool_calls"] == {}
    assert task["overall"] is False and task["agent"]["first_overall"] is False


async def test_simulate_reports_the_agents_program_never_the_ground_truth() -> None:
    instance = default_registry().get("double_mass_oscillator").instance(2)
    program = instance.reference_program
    for name in ("mass1", "mass2", "length1"):
        value = instance.params[name]
        program = program.replace(f"\n{name} = {value!r}\n", f"\n{name} = {value * 1.37!r}\n")
    toolbox = Toolbox(instance, rigid_catalog())
    text = (await toolbox.call("simulate", {"code": program})).text
    own_mass = (instance.params["mass1"] + instance.params["mass2"]) * 1.37
    assert f"total mass {num(own_mass)}" in text
    assert f"mass {num(instance.params['mass1'] * 1.37)}," in text
    assert f"position ({num(instance.params['length1'] * 1.37)}, 0, 0)" in text
    assert f"mass {num(instance.params['mass1'])}," not in text
    assert "stage: solved (no error)" in text and "motion (sampled):" in text
    assert "reference" not in text.lower().replace("reference point", "").replace("referencelength", "")


async def test_self_check_reports_the_agents_program() -> None:
    instance = default_registry().get("double_mass_oscillator").instance(2)
    text = (await Toolbox(instance, rigid_catalog()).call("self_check", {"code": instance.reference_program})).text
    assert text.startswith("stage: solved;") and "findings:\n  - no problem found" in text


async def test_agent_through_the_openai_compatible_backend(tmp_path: Path) -> None:
    from fake_ollama import openai_reply

    from meceng.llm.backend_openai import OpenAIBackend

    instance = default_registry().get(SLUG).instance(0)

    def responder(body):
        messages = body["messages"]
        if "<components>" in messages[0]["content"]:
            return 200, openai_reply(gold_selection(instance.required_components)), {}
        assert body["tools"][0]["type"] == "function"
        if not any(m["role"] == "tool" for m in messages):
            reply = openai_reply("", finish_reason="tool_calls")
            reply["choices"][0]["message"]["tool_calls"] = [{
                "id": "call_1", "type": "function",
                "function": {"name": "simulate", "arguments": json.dumps({"code": instance.reference_program})}}]
            return 200, reply, {}
        tool = next(m for m in messages if m["role"] == "tool")
        assert tool["tool_call_id"] == "call_1" and "stage: solved (no error)" in tool["content"]
        return 200, openai_reply(gold_code(instance.reference_program)), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="served", backend="openai", hosts=(server.url + "/v1",))
        settings = RunSettings(llm=llm, only=(SLUG,), variations=1, out=tmp_path, run_name="oa", progress=False,
                               agent="loop")
        run_json = await run_benchmark(settings, backend=OpenAIBackend(llm))
    task = json.loads(run_json.read_text())["tasks"][0]
    assert task["overall"] is True and task["agent"]["rounds"] == 2 and task["agent"]["tool_calls"] == {"simulate": 1}


async def test_self_check_energy_is_the_programs_own() -> None:
    """Energy from the agent's program: kept by a pendulum, lost by a damped oscillator."""
    registry = default_registry()
    pendulum = registry.get("single_pendulum").instance(1)
    toolbox = Toolbox(pendulum, rigid_catalog())
    report = await toolbox.self_check(pendulum.reference_program)  # the numbers behind the words
    p = pendulum.params
    import math

    height = -p["length"] * math.cos(math.radians(p["angle_deg"]))
    assert abs(report["energy"]["start"] - p["mass"] * p["gravity"] * height) < 1e-9  # m g y at rest
    assert abs(report["energy"]["relative_change"]) < 1e-4

    oscillator = registry.get("single_mass_oscillator")
    values = oscillator.sample_params(1)
    values["damping"] = 5.0
    damped = oscillator.reference_program(values, "", 1)
    report = await Toolbox(oscillator.instance(1), rigid_catalog()).self_check(damped)
    assert abs(report["energy"]["start"] - 0.5 * values["stiffness"] * values["displacement"] ** 2) < 1e-9
    assert report["energy"]["relative_change"] < -0.5


async def test_part_agent_repairs_an_interface_after_meshing(tmp_path: Path) -> None:
    """Level 3a: the agent meshes a part whose right face is unnamed, reads the tool's report, fixes it."""
    part = default_registry().get("flexible_beam_part").instance(0)
    wrong = part.reference_program.replace("shape.faces.Max(X).name = 'right'", "shape.faces.Max(X).name = 'end'")
    wrong = wrong.replace("['left', 'right']", "['left', 'end']")

    def responder(body):
        messages = body["messages"]
        if "<components>" in messages[0]["content"]:
            return 200, chat_reply(gold_selection(part.required_components)), {}
        assert {t["function"]["name"] for t in body["tools"]} == {"mesh_part", "snapshot", "list_components",
                                                                  "component_docs"}
        results = [m for m in messages if m["role"] == "tool"]
        if not results:
            return 200, tool_call("mesh_part", code=wrong), {}
        report = json.loads(results[-1]["content"])
        assert set(report["interfaces"]) == {"left", "end"}  # what it made, so it can see the mistake
        return 200, chat_reply(gold_code(part.reference_program)), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="agent:1b", backend="ollama", hosts=(server.url,))
        settings = RunSettings(llm=llm, levels=("3a",), only=("flexible_beam_part",), variations=1, out=tmp_path,
                               run_name="part-agent", progress=False, agent="loop", max_rounds=3)
        run = json.loads((await run_benchmark(settings)).read_text())
    task = run["tasks"][0]
    assert task["overall"] is True and task["agent"]["first_overall"] is False
    assert task["agent"]["first_failure"] == "interface_name_match"
    assert task["agent"]["tool_calls"] == {"mesh_part": 1} and run["summary"]["agent"]["uplift"] == 1.0


async def test_mesh_part_reports_the_agents_part_never_the_ground_truth() -> None:
    part = default_registry().get("flexible_beam_part").instance(0)
    p = part.params
    other = re.sub(r"^beam_length = .*$", "beam_length = 0.3", part.reference_program, flags=re.M)
    other = other.replace("density=7850.0", "density=2700.0")
    report = json.loads((await Toolbox(part, part_catalog()).call("mesh_part", {"code": other})).text)
    assert report["error"] is None and report["stage"] == "reduced"
    volume = 0.3 * p["beam_width"] * p["beam_height"]
    assert report["volume"] == pytest.approx(volume, rel=1e-5)
    assert report["mass"] == pytest.approx(2700.0 * volume, rel=1e-5)
    assert report["bounding_box"][1][0] == pytest.approx(0.3)
    right = report["interfaces"]["right"]
    assert right["area"] == pytest.approx(p["beam_width"] * p["beam_height"], rel=1e-5)
    assert right["centre"] == pytest.approx([0.3, 0.0, 0.0], abs=1e-9)
    assert right["mean_normal"] == pytest.approx([1.0, 0.0, 0.0], abs=1e-9)
    assert right["geometry_faces"] == 1 and right["surface_triangles"] >= 2
    assert report["interfaces"]["left"]["mean_normal"] == pytest.approx([-1.0, 0.0, 0.0], abs=1e-9)
    assert len(report["eigenfrequencies_hz"]) >= 6 and "fixed-interface" in report["eigenfrequencies_are"]
    flagged = json.loads((await Toolbox(part, part_catalog()).call("mesh_part", {
        "code": other.replace(f"maxh={part.part.maxh!r}", "maxh=h")})).text)
    assert flagged["stage"] == "flagged"
    answer = (await Toolbox(part, part_catalog()).call("simulate", {"code": other})).text
    assert "simulate" in json.loads(answer)["error"]


@pytest.mark.parametrize("refused_round", [1, 2])
async def test_a_conversation_over_the_servers_context(tmp_path: Path, refused_round: int) -> None:
    """The task's first prompt refused for its length: nothing the model did, the task is not
    graded (context_exceeded). A later round refused: the conversation the model led outgrew the
    context, like the token budget; the program it had is graded."""
    from fake_ollama import openai_reply

    from meceng.llm.backend_openai import OpenAIBackend

    instance = default_registry().get(SLUG).instance(0)
    overflow = {"error": {"message": "This model's maximum context length is 4096 tokens. However, you requested "
                                     "4200 tokens (4136 in the messages, 64 in the completion).",
                          "code": "context_length_exceeded"}}

    def responder(body):
        messages = body["messages"]
        if "<components>" in messages[0]["content"]:
            return 200, openai_reply(gold_selection(instance.required_components)), {}
        if len(messages) >= 2 * refused_round - 1:
            return 400, overflow, {}
        reply = openai_reply("", finish_reason="tool_calls")
        reply["choices"][0]["message"]["tool_calls"] = [{"id": "call_1", "type": "function", "function": {
            "name": "simulate", "arguments": json.dumps({"code": broken(instance.reference_program)})}}]
        return 200, reply, {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="m", backend="openai", hosts=(server.url + "/v1",), num_predict=64)
        settings = RunSettings(llm=llm, only=(SLUG,), variations=1, out=tmp_path, run_name="agent", progress=False,
                               agent="loop", max_rounds=4)
        run = json.loads((await run_benchmark(settings, backend=OpenAIBackend(llm))).read_text())
    task = run["tasks"][0]
    if refused_round == 1:
        assert task["first_failure"] == "infrastructure" and task["context_exceeded"]["prompt_tokens"] == 4136
        assert run["summary"]["counted"] == 0 and run["summary"]["context_exceeded"] == 1
    else:
        assert task["first_failure"] == "finished_assemble" and "context_exceeded" not in task
        assert task["agent"]["stop_reason"] == "context_full" and task["agent"]["tool_calls"] == {"simulate": 1}
        assert run["summary"]["counted"] == 1
