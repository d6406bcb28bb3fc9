"""The agent's ``compare`` tool and the agreement of two programs behind it (no ground truth): the
symmetric comparison on made-up motions, then programs: the same system built another way
(``tasks/alternatives.py``) agrees, a changed mass, length or gravity sign parts and the answer
says which body and when, a program that fails is named with its error, and the tool through the
three APIs' fakes, the agent's note and the viewer."""

from __future__ import annotations

import asyncio
import json
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fake_anthropic import FakeAnthropic, anthropic_reply
from fake_ollama import FakeOllama, chat_reply, openai_reply
from test_api_backends import SENTINEL, gold_answer, instances, prompt_of
from test_behaviour import T, body, circle, motion

from meceng.agents.loop import agent_prompt
from meceng.agents.prompts import code_prompt
from meceng.agents.steps import generation_prompt
from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.eval.agreement import compare_motions
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.alternatives import ALTERNATIVES
from meceng.tasks.registry import default_registry
from meceng.viewer.site import build_site


def alternative(alt_id: str) -> tuple[Any, str, str]:
    """(instance, its ground truth, the same system built another way)."""
    alt = next(a for a in ALTERNATIVES if a.id == alt_id)
    instance = default_registry().get(alt.slug).instance(1)
    return instance, instance.reference_program, alt.program(instance)


async def compare(instance: Any, code_a: str, code_b: str) -> str:
    return (await Toolbox(instance, rigid_catalog()).call("compare", {"code_a": code_a, "code_b": code_b})).text


# ----------------------------------------------------------------------------- the agreement, made-up motions


def test_the_agreement_is_symmetric_and_a_program_that_blows_up_does_not_loosen_it() -> None:
    a = motion(body(0, 1.0, None, circle(1.0)), body(1, 2.0, None, circle(1.0, np.pi)))
    b = motion(body(7, 2.0, None, circle(1.0, np.pi)), body(3, 1.0, None, circle(1.0)))  # other order and numbers
    same = compare_motions(a, b)
    assert same.agree is True and same.pairs == ((0, 3), (1, 7))
    late = circle(1.0)
    late[T > 1.5] += np.array([0.0, 0.05, 0.0])
    parted = motion(body(7, 2.0, None, circle(1.0, np.pi)), body(3, 1.0, None, late))
    one, other = compare_motions(a, parted), compare_motions(parted, a)
    assert one.agree is False and other.agree is False
    assert one.verdict.first_divergence.time == other.verdict.first_divergence.time
    assert abs(one.verdict.first_divergence.time - 1.5) <= 0.021
    assert one.verdict.first_divergence.body == 0 and one.verdict.first_divergence.candidate_body == 3
    # the same parting, then the program flies off to 1e6 m: its scale must not widen the tolerance
    # (with the larger of the two scales the parting at 1.5 s would be found only at 1.8 s)
    wild = late.copy()
    wild[T > 1.8] *= 1e6
    blown = compare_motions(a, motion(body(7, 2.0, None, circle(1.0, np.pi)), body(3, 1.0, None, wild)))
    assert blown.agree is False and abs(blown.verdict.first_divergence.time - 1.5) <= 0.021
    assert compare_motions(a, None).agree is None and "B" in compare_motions(a, None).detail
    nothing = {**b, "t": T[:0], "states": b["states"][:0]}  # a recorder that gave up before its first sample
    assert compare_motions(nothing, a).agree is None and "of A" in compare_motions(nothing, a).detail
    # a record that stops early agrees with nothing, whatever it did until then
    short = compare_motions(a, {**b, "t": T[:50], "states": b["states"][:50]})
    assert short.agree is False and short.ends == (2.0, float(T[49])) and short.verdict.passed


# ----------------------------------------------------------------------------- the tool, on programs


@pytest.mark.parametrize("alt_id", ["double_pendulum_rigid_bodies/links created in the other order",
                                    "flying_rigid_body/local axes permuted, rotated back"])
async def test_the_same_system_built_another_way_compares_as_alike(alt_id: str) -> None:
    instance, truth, other = alternative(alt_id)
    text = await compare(instance, truth, other)
    assert text.startswith("compare: A and B move alike up to t = "), text
    pairs = re.findall(r"^  A's (#\d+) \w+.* ↔ B's (#\d+) \w+", text, re.M)
    assert pairs and len(pairs) == len(re.findall(r"^  A's #", text, re.M))
    assert " differ\n" not in text and "unmatched" not in text and "largest deviation: " in text


CHANGES = [
    # (task, text in the program, its replacement, A's body that must be named)
    ("single_mass_oscillator", "mass = 0.885\n", "mass = 0.885 * 1.05\n", "#1 MassPoint"),
    ("single_pendulum", "length = 1.15\n", "length = 1.2\n", "#1 MassPoint"),
    ("single_pendulum", "gravity=[0, -gravity, 0]", "gravity=[0, gravity, 0]", "#1 MassPoint"),
]


@pytest.mark.parametrize(("slug", "old", "new", "named"), CHANGES, ids=["mass", "length", "gravity sign"])
async def test_a_changed_program_parts_and_the_answer_says_which_body_and_when(slug: str, old: str, new: str,
                                                                              named: str) -> None:
    instance = default_registry().get(slug).instance(0)
    truth = instance.reference_program
    assert old in truth
    text = await compare(instance, truth, truth.replace(old, new))
    head = text.splitlines()[0]
    when = re.match(r"compare: A and B part at t = ([\d.e-]+) s: .* of A's (#\d+ \w+) and B's #\d+ \w+: "
                    r"[\d.e+-]+ m(/s)? apart, tolerance", head)
    assert when is not None, text
    assert when.group(2) == named and 0.0 <= float(when.group(1)) <= instance.sim.end_time
    assert text.splitlines()[1].startswith(f"  then: A's {named} at (")
    assert "both run again with twice the steps" in text  # the step-error check ran, and it stood


async def test_a_program_that_fails_is_named_with_its_error() -> None:
    instance, truth, other = alternative("free_fall_mass_point/gravity as a user-function force")
    broken = truth.replace("mass=mass,", "mas=mass,")  # a keyword Exudyn does not know: before the solve
    text = await compare(instance, truth, broken)
    assert text.splitlines()[0] == "compare: not compared: program B did not run to its solve"
    assert re.match(r"program B: stage: \w+; error: .*TypeError", text.splitlines()[1]), text
    # a user function that raises half-way: compared while both ran, and the failure said
    half = 0.5 * instance.sim.end_time
    stops = other.replace("lambda mbs, t, load: [0, 0, -mass * gravity]",
                          f"lambda mbs, t, load: [0, 0, -mass * gravity] if t < {half!r} else [0, 0, 1 / 0]")
    text = await compare(instance, stops, truth)
    head = text.splitlines()[0]
    assert re.match(r"compare: A and B differ: A's motion ends at t = 0\.4\d* s, B's at t = 1 s; up to t = 0\.4\d* s "
                    r"they move alike", head), text
    assert "program A: stage: solver_started; error: " in text and "ZeroDivisionError" in text


def test_the_agent_note_offers_compare_and_the_paper_prompt_stays_as_it_was() -> None:
    instance = default_registry().get("single_pendulum").instance(0)
    names = instance.required_components
    plain = generation_prompt(instance, rigid_catalog(), names, "MBS1")
    assert plain == code_prompt("MBS1", instance.description, rigid_catalog().context(names))
    assert "compare" not in plain
    note = agent_prompt(instance, rigid_catalog(), names, "MBS1")
    assert note.startswith(plain) and "`compare(code_a, code_b)`" in note and "independent way" in note


# ----------------------------------------------------------------------------- the three APIs' fakes


SLUG = "single_mass_oscillator"


def compare_script(known: dict[str, Any], backend_name: str) -> Any:
    """A model that first compares its program with the same system built another way, then
    answers with its program."""
    def answer(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        purpose, gold = gold_answer(known, body)
        instance = next(inst for desc, inst in known.items() if desc in prompt_of(body))
        other = next(a for a in ALTERNATIVES if a.slug == SLUG).program(instance)
        arguments = {"code_a": instance.reference_program, "code_b": other}
        asked = purpose == "code" and len(body["messages"]) == 1
        if backend_name == "anthropic":
            if asked:
                return 200, anthropic_reply(tool_uses=({"id": "toolu_01", "name": "compare", "input": arguments},),
                                            stop_reason="tool_use"), {}
            return 200, anthropic_reply(gold), {}
        reply = openai_reply(gold) if backend_name == "openai" else chat_reply(gold)
        if asked:
            message = reply["choices"][0]["message"] if backend_name == "openai" else reply["message"]
            call: dict[str, Any] = {"function": {"name": "compare", "arguments": arguments}}
            if backend_name == "openai":
                call = {"id": "call_1", "type": "function",
                        "function": {"name": "compare", "arguments": json.dumps(arguments)}}
            message["content"], message["tool_calls"] = "", [call]
        return 200, reply, {}
    return answer


def tool_answer(backend_name: str, body: dict[str, Any]) -> str:
    """The tool's answer in the request after the call, where each API carries it."""
    last = body["messages"][-1]
    if backend_name == "anthropic":
        (result,) = last["content"]
        assert result["type"] == "tool_result" and result["tool_use_id"] == "toolu_01"
        content = result["content"]
        return content if isinstance(content, str) else "".join(b.get("text", "") for b in content)
    assert last["role"] == "tool"
    assert last.get("tool_call_id") == "call_1" if backend_name == "openai" else last.get("tool_name") == "compare"
    return str(last["content"])


async def test_compare_through_the_three_apis_is_answered_recorded_and_shown(tmp_path: Path,
                                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    known = instances((SLUG,))
    monkeypatch.setenv("ANTHROPIC_API_KEY", SENTINEL)
    monkeypatch.setenv("OPENAI_API_KEY", SENTINEL)
    async with (FakeAnthropic(compare_script(known, "anthropic"), key=SENTINEL) as claude,
                FakeOllama(compare_script(known, "openai")) as gpt,
                FakeOllama(compare_script(known, "ollama")) as local):
        servers = {"anthropic": claude, "openai": gpt, "ollama": local}
        urls = {"anthropic": claude.url, "openai": gpt.url + "/v1", "ollama": local.url}
        await asyncio.gather(*(run_benchmark(RunSettings(
            llm=LLMSettings(model="claude-x", backend=name, hosts=(urls[name],), backoff_s=0.01), only=(SLUG,),
            variations=1, out=tmp_path, run_name=name, progress=False, agent="loop", max_rounds=3))
            for name in servers))
        for name in servers:
            offered = servers[name].requests[-1]["tools"]
            assert "compare" in json.dumps(offered)
            answer = tool_answer(name, servers[name].requests[-1])
            assert answer.startswith("compare: A and B move alike up to t = 2 s"), answer
            task = json.loads((tmp_path / name / "run.json").read_text())["tasks"][0]
            assert task["overall"] is True and task["agent"]["tool_calls"] == {"compare": 1}
            call, result = task["agent"]["transcript"][1], task["agent"]["transcript"][2]
            assert call["tool_calls"][0]["name"] == "compare" and set(call["tool_calls"][0]["arguments"]) == {
                "code_a", "code_b"}
            assert result == {"role": "tool", "name": "compare", "content": answer}
    build_site([tmp_path / "ollama"], tmp_path / "site", workers=1)
    page = next((tmp_path / "site" / "tasks").rglob("*.html")).read_text()
    assert "calls <b>compare</b>" in page and "program A (" in page and "program B (" in page
    assert "tool result: compare" in page and "move alike up to t = 2 s" in page
