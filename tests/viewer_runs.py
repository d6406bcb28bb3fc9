"""Real runs for the viewer's tests: a fake Ollama server answers with ground truths for some tasks
and with broken programs for others, at every level, and an agent run repairs one program and
fails another. The flow keeps trajectories and part surfaces (traces/), so the pages have their plots.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

#: (slug, seed) -> what the fake model answers; everything else gets the ground truth
SCENARIOS = {
    ("double_mass_oscillator", 0): "wrong_mass",
    ("free_fall_mass_point", 0): "no_code",
    ("flying_mass_point", 1): "syntax_error",
    ("single_pendulum", 0): "malformed_components",
    ("slider_crank_rigid_bodies", 0): "wrong_parameter",
    ("flexible_beam_drilled_part", 1): "no_holes",
}
RIGID = ("single_mass_oscillator", "double_mass_oscillator", "free_fall_mass_point", "flying_mass_point",
         "single_pendulum", "slider_crank_rigid_bodies")
ASSEMBLY = "cantilever_beam"
AGENT_TASKS = ("single_mass_oscillator", "double_mass_oscillator")


def _instances(slugs: tuple[str, ...], seeds: int) -> dict[str, Any]:
    """Task description -> instance, parts of assemblies included (a prompt holds its description)."""
    registry = default_registry()
    out = {}
    for slug in slugs:
        for seed in range(seeds):
            instance = registry.get(slug).instance(seed)
            out[instance.description] = instance
            for _, part in instance.parts or ():
                out[part.description] = part
    return out


def _program(instance: Any, scenario: str | None) -> str:
    program = instance.reference_program
    if scenario == "wrong_mass":
        program = re.sub(r"\nmass1 = ([0-9.]+)\n", lambda m: f"\nmass1 = {float(m.group(1)) * 1.5!r}\n", program)
    elif scenario == "wrong_parameter":  # the first numeric parameter 1.5 times too large
        program = re.sub(r"\n(\w+) = ([0-9.]+)\n", lambda m: f"\n{m.group(1)} = {float(m.group(2)) * 1.5!r}\n",
                         program, count=1)
    elif scenario == "syntax_error":
        program = program.replace("mbs.Assemble()", "mbs.Assemble(")
    elif scenario == "no_holes":
        program = re.sub(r"\nfor x in hole_x:\n    shape = shape - [^\n]*\n", "\n", program)
    return program


def _answer(instance: Any, purpose: str, scenario: str | None) -> dict[str, Any]:
    if purpose == "select":
        if scenario == "malformed_components":
            return chat_reply("I would use a mass point <components> MassPoint")
        return chat_reply(gold_selection(instance.required_components), thinking="The system needs these items.")
    if scenario == "no_code":
        return chat_reply("The mass falls; z(t) = z0 - g t^2 / 2.", thinking="No program is needed.")
    return chat_reply("Here is the program.\n" + gold_code(_program(instance, scenario)),
                      thinking="Let me write the model step by step.", prompt_tokens=900, completion_tokens=700)


async def pipeline_run(out: Path, name: str = "fake") -> Path:
    """Levels 1-3b, two seeds each, some answers broken (see SCENARIOS); returns the run folder."""
    instances = _instances((*RIGID, ASSEMBLY), 2)

    def responder(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        prompt = body["messages"][-1]["content"]
        instance = next(inst for desc, inst in instances.items() if desc in prompt)
        purpose = "select" if "<components>" in prompt else "code"
        return 200, _answer(instance, purpose, SCENARIOS.get((instance.slug, instance.seed))), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="fake-model:7b", backend="ollama", hosts=(server.url,), batch_size=2, think=False)
        settings = RunSettings(llm=llm, levels=("1", "2", "3a", "3b"), only=(*RIGID, ASSEMBLY), variations=2, seed=0,
                               out=out, run_name=name, workers=2, exec_timeout_s=20.0, progress=False)
        await run_benchmark(settings)
    return out / name


async def agent_run(out: Path, name: str = "agent") -> Path:
    """The agent repairs single_mass_oscillator after a simulate call; it answers
    double_mass_oscillator with a wrong mass after a self_check."""
    instances = _instances(AGENT_TASKS, 1)

    def tool_call(tool: str, code: str) -> dict[str, Any]:
        body = chat_reply("Let me test it first.")
        body["message"]["tool_calls"] = [{"function": {"name": tool, "arguments": {"code": code}}}]
        return body

    def responder(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        messages = body["messages"]
        instance = next(inst for desc, inst in instances.items() if desc in messages[0]["content"])
        if "<components>" in messages[0]["content"]:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        tried = any(m["role"] == "tool" for m in messages)
        program = instance.reference_program
        if instance.slug == "single_mass_oscillator":
            if not tried:
                return 200, tool_call("simulate", program.replace("mass=mass)", "mas=mass)")), {}
            return 200, chat_reply("Fixed the keyword.\n" + gold_code(program)), {}
        if not tried:
            return 200, tool_call("self_check", _program(instance, "wrong_mass")), {}
        return 200, chat_reply("The check passed.\n" + gold_code(_program(instance, "wrong_mass"))), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="agent-model:1b", backend="ollama", hosts=(server.url,), batch_size=2)
        settings = RunSettings(llm=llm, only=AGENT_TASKS, variations=1, out=out, run_name=name, progress=False,
                               agent="loop", max_rounds=4, workers=2)
        await run_benchmark(settings)
    return out / name
