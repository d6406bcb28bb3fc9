"""The hosted-API backends against fake servers on 127.0.0.1 that speak the real wire formats:
Anthropic's Messages API (through the official SDK) and OpenAI's chat completions with the API's
default settings. Runs through the command line as a user starts them, the agent loop with native
tool calls, retries, truncation, and no API key in any file a run writes."""

from __future__ import annotations

import asyncio
import base64
import json
import os
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest
from fake_anthropic import FakeAnthropic, anthropic_error, anthropic_problem, anthropic_reply
from fake_ollama import FakeOllama, chat_reply, ollama_problem, openai_problem, openai_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.llm.backend_anthropic import AnthropicBackend, thinking_budget
from meceng.llm.backend_ollama import OllamaBackend
from meceng.llm.backend_openai import OpenAIBackend
from meceng.llm.messages import assistant_message, tool_message, user_messages
from meceng.llm.types import ChatRequest, ChatResponse, LLMError, LLMSettings, ToolCall
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

SENTINEL = "sk-SENTINEL-7f3a9c21e4b8"


def instances(slugs: tuple[str, ...], seeds: int = 1) -> dict[str, Any]:
    """Description -> instance, an assembly's parts included (a prompt holds its description)."""
    out = {}
    for slug in slugs:
        for seed in range(seeds):
            instance = default_registry().get(slug).instance(seed)
            out[instance.description] = instance
            for _, part in instance.parts or ():
                out[part.description] = part
    return out


def prompt_of(body: dict[str, Any]) -> str:
    content = body["messages"][0]["content"]
    return content if isinstance(content, str) else json.dumps(content)


def gold_answer(known: dict[str, Any], body: dict[str, Any]) -> tuple[str, Any]:
    prompt = prompt_of(body)
    instance = next(inst for desc, inst in known.items() if desc in prompt)
    if "<components>" in prompt:
        return "select", gold_selection(instance.required_components)
    return "code", gold_code(instance.reference_program)


def anthropic_settings(url: str, **changes: Any) -> LLMSettings:
    return LLMSettings(**{"model": "claude-x", "backend": "anthropic", "hosts": (url,), "api_defaults": True,
                          "backoff_s": 0.01, **changes})


async def test_anthropic_request_retries_and_answer(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-ant-test")
    script = [anthropic_error(529, "overloaded_error", "Overloaded"),
              (*anthropic_error(429, "rate_limit_error", "rate limited")[:2], {"retry-after": "0"}),
              (200, anthropic_reply("<components>MassPoint</components>", stop_reason="max_tokens",
                                    input_tokens=300, output_tokens=40), {})]
    async with FakeAnthropic(lambda body: script.pop(0)) as server:
        settings = anthropic_settings(server.url, num_predict=777)
        backend = AnthropicBackend(settings, api_key="sk-ant-test")
        response = await backend.chat(ChatRequest(user_messages("choose"), "select", "t@0"))
        await backend.aclose()
    assert response.attempts == 3 and response.content == "<components>MassPoint</components>"
    assert response.truncated and response.prompt_tokens == 300 and response.completion_tokens == 40
    body, headers = server.requests[-1], server.headers[-1]
    assert body["max_tokens"] == 777 and body["model"] == "claude-x" and body["thinking"] == {"type": "disabled"}
    assert "temperature" not in body and "seed" not in body and "top_p" not in body
    assert headers["anthropic-version"] and "sk-ant-test" in (headers.get("x-api-key", "")
                                                             + headers.get("authorization", ""))


@pytest.mark.parametrize(("status", "kind"), [(400, "invalid_request_error"), (404, "not_found_error")])
async def test_anthropic_permanent_errors_are_not_retried(status: int, kind: str) -> None:
    async with FakeAnthropic(lambda body: anthropic_error(status, kind, "model: claude-nope")) as server:
        backend = AnthropicBackend(anthropic_settings(server.url), api_key="sk-ant-test")
        with pytest.raises(LLMError) as caught:
            await backend.chat(ChatRequest(user_messages("x"), "code", "t@0"))
        await backend.aclose()
    assert len(server.requests) == 1 and not caught.value.transient and caught.value.status == status
    assert kind in str(caught.value) and "claude-nope" in str(caught.value)


async def test_anthropic_wrong_key_is_an_infrastructure_error_not_retried() -> None:
    async with FakeAnthropic(lambda body: (200, anthropic_reply("never"), {})) as server:
        backend = AnthropicBackend(anthropic_settings(server.url), api_key="sk-ant-wrong")
        with pytest.raises(LLMError) as caught:
            await backend.chat(ChatRequest(user_messages("x"), "code", "t@0"))
        await backend.aclose()
    assert caught.value.status == 401 and "authentication_error" in str(caught.value)
    assert len(server.requests) == 1


def test_anthropic_without_key_says_which_variable(monkeypatch: pytest.MonkeyPatch) -> None:
    from meceng.llm.factory import make_backend

    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    with pytest.raises(ValueError, match="ANTHROPIC_API_KEY"):
        make_backend(anthropic_settings("http://127.0.0.1:9"))
    monkeypatch.setenv("MY_KEY", "k")
    assert make_backend(anthropic_settings("http://127.0.0.1:9", api_key_env="MY_KEY")).name == "anthropic"


@pytest.mark.parametrize(("think", "num_predict", "max_tokens", "budget"),
                         [(True, 7680, 7680, 5760), ("low", 7680, 7680, 1920), (True, 1000, 2048, 1024)])
def test_thinking_budget_fits_the_answer_limit(think: bool | str, num_predict: int, max_tokens: int,
                                               budget: int) -> None:
    got_max, thinking = thinking_budget(LLMSettings(think=think, num_predict=num_predict))
    assert got_max == max_tokens and thinking == {"type": "enabled", "budget_tokens": budget}
    assert thinking["budget_tokens"] >= 1024 and got_max - thinking["budget_tokens"] >= 1024


async def test_anthropic_agent_loop_with_tool_use_and_thinking(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    """The agent simulates a broken program through a tool_use block, reads the tool_result and
    answers with the repaired one; the signed thinking goes back with the tool-use turn."""
    monkeypatch.setenv("ANTHROPIC_API_KEY", "sk-ant-test")
    known = instances(("single_mass_oscillator",))
    instance = next(iter(known.values()))
    broken = instance.reference_program.replace("mass=mass)", "mas=mass)")

    def responder(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        purpose, answer = gold_answer(known, body)
        if purpose == "select":
            return 200, anthropic_reply(answer), {}
        if len(body["messages"]) == 1:
            return 200, anthropic_reply("Let me test it.", thinking="Test before answering.", thinking_tokens=30,
                                        tool_uses=({"id": "toolu_01", "name": "simulate", "input": {"code": broken}},),
                                        stop_reason="tool_use"), {}
        return 200, anthropic_reply("Fixed.\n" + answer), {}

    async with FakeAnthropic(responder) as server:
        llm = anthropic_settings(server.url, think=True, num_predict=4096)
        settings = RunSettings(llm=llm, only=("single_mass_oscillator",), variations=1, out=tmp_path, run_name="a",
                               progress=False, agent="loop", max_rounds=3, workers=1)
        run = json.loads((await run_benchmark(settings)).read_text())
    task = run["tasks"][0]
    assert task["overall"] is True and task["agent"]["tool_calls"] == {"simulate": 1}
    assert task["agent"]["first_overall"] is False  # the first program was the broken one
    second = server.requests[-1]
    assert second["tools"][0]["input_schema"]["type"] == "object"
    assert second["thinking"] == {"type": "enabled", "budget_tokens": 3072}
    turn, results = second["messages"][1], second["messages"][2]
    assert [b["type"] for b in turn["content"]] == ["thinking", "text", "tool_use"]
    assert turn["content"][0]["signature"] and turn["content"][2]["id"] == "toolu_01"
    assert results["role"] == "user" and results["content"][0]["type"] == "tool_result"
    assert results["content"][0]["tool_use_id"] == "toolu_01"
    assert "mas" in results["content"][0]["content"]  # the simulator's error about the wrong keyword
    meta = task["agent"]["transcript"][1]["meta"]
    assert meta["reasoning_tokens"] == 30 and meta["thinking_chars"] > 0


async def test_openai_api_defaults_and_reasoning_tokens(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from meceng.llm.factory import make_backend

    monkeypatch.setenv("OPENAI_API_KEY", "sk-openai-test")
    known = instances(("single_pendulum",))

    def responder(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        if "temperature" in body:  # as OpenAI's reasoning models answer
            return 400, {"error": {"message": "Unsupported value: 'temperature'", "type": "invalid_request_error",
                                   "param": "temperature", "code": "unsupported_value"}}, {}
        reply = openai_reply(gold_answer(known, body)[1], completion_tokens=500)
        reply["usage"]["completion_tokens_details"] = {"reasoning_tokens": 320}
        return 200, reply, {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="gpt-x", backend="openai", hosts=(server.url + "/v1",), api_defaults=True)
        settings = RunSettings(llm=llm, only=("single_pendulum",), variations=1, out=tmp_path, run_name="o",
                               progress=False)
        run = json.loads((await run_benchmark(settings, backend=make_backend(llm))).read_text())
    task = run["tasks"][0]
    assert task["overall"] is True and task["generation"]["meta"]["reasoning_tokens"] == 320
    assert task["tokens"]["reasoning"] == 640 and run["summary"]["tokens"]["totals"]["reasoning"] == 640
    assert all("temperature" not in b and "seed" not in b for b in server.requests)
    assert all(h["authorization"] == "Bearer sk-openai-test" for h in server.headers)


# ----------------------------------------------------------------------------- pictures in tool answers


def tiny_png() -> bytes:
    """A real 1x1 grey PNG: signature, IHDR, IDAT, IEND."""
    import struct
    import zlib

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(b"\x00\x80")) + chunk(b"IEND", b""))


PNG = base64.b64encode(tiny_png()).decode()
SNAPSHOT = ToolCall("snapshot", {"code": "...", "t": 0.0}, id="call_1")
SIMULATE = ToolCall("simulate", {"code": "..."}, id="call_2")
VIEWS = "front, top, side and isometric views at t = 0"


def conversation(*, pictures: bool) -> tuple[dict[str, Any], ...]:
    """The agent's messages after a turn that called snapshot and simulate; with ``pictures`` the
    snapshot's answer carries a PNG, as the loop writes it for a vision model."""
    turn = assistant_message(ChatResponse(content="Let me look at it.", tool_calls=(SNAPSHOT, SIMULATE)))
    return (*user_messages("Model the rotor."), turn,
            tool_message(SNAPSHOT, VIEWS, images=(PNG,) if pictures else ()),
            tool_message(SIMULATE, '{"stage": "solved"}'))


def decodes_to_the_png(data: str) -> bool:
    return base64.b64decode(data, validate=True) == tiny_png()


def openai_answer(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
    return 200, openai_reply("done"), {}


def ollama_answer(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
    return 200, chat_reply("done"), {}


async def sent_messages(backend_name: str, messages: tuple[dict[str, Any], ...]) -> list[dict[str, Any]]:
    """The ``messages`` (Anthropic: with ``system``) a backend sent for this conversation; the fake
    answers 400 to anything the real API refuses, which fails the call."""
    fake, answer = {"anthropic": (FakeAnthropic, lambda body: (200, anthropic_reply("done"), {})),
                    "openai": (FakeOllama, openai_answer), "ollama": (FakeOllama, ollama_answer)}[backend_name]
    async with fake(answer) as server:
        if backend_name == "anthropic":
            backend: Any = AnthropicBackend(anthropic_settings(server.url), api_key="sk-ant-test")
        elif backend_name == "openai":
            backend = OpenAIBackend(LLMSettings(model="gpt-x", backend="openai", hosts=(server.url + "/v1",)))
        else:
            backend = OllamaBackend(LLMSettings(model="qwen3-vl", backend="ollama", hosts=(server.url,)))
        response = await backend.chat(ChatRequest(messages, "code", "t@0"))
        await backend.aclose()
    assert response.content == "done" and len(server.requests) == 1
    return server.requests[0]["messages"]


async def test_anthropic_picture_is_an_image_block_of_its_tool_result() -> None:
    sent = await sent_messages("anthropic", conversation(pictures=True))
    assert [m["role"] for m in sent] == ["user", "assistant", "user"]
    snapshot, simulate = sent[2]["content"]
    assert snapshot["type"] == "tool_result" and snapshot["tool_use_id"] == "call_1"
    text, image = snapshot["content"]
    assert text == {"type": "text", "text": VIEWS}
    assert image["type"] == "image" and image["source"]["type"] == "base64"
    assert image["source"]["media_type"] == "image/png" and decodes_to_the_png(image["source"]["data"])
    assert simulate == {"type": "tool_result", "tool_use_id": "call_2", "content": '{"stage": "solved"}'}


async def test_openai_picture_follows_the_turns_tool_answers_as_an_image_url_part() -> None:
    sent = await sent_messages("openai", conversation(pictures=True))
    assert [m["role"] for m in sent] == ["user", "assistant", "tool", "tool", "user"]
    assert [m["tool_call_id"] for m in sent[2:4]] == ["call_1", "call_2"]  # right after the turn that called
    assert sent[2]["content"] == VIEWS  # a tool message: text only
    caption, picture = sent[4]["content"]
    assert caption["type"] == "text" and "snapshot call_1" in caption["text"]
    assert picture["type"] == "image_url"
    prefix, data = picture["image_url"]["url"].split(",", 1)
    assert prefix == "data:image/png;base64" and decodes_to_the_png(data)


async def test_ollama_picture_is_in_the_images_of_a_user_message_after_the_tool_answers() -> None:
    sent = await sent_messages("ollama", conversation(pictures=True))
    assert [m["role"] for m in sent] == ["user", "assistant", "tool", "tool", "user"]
    assert [m["tool_name"] for m in sent[2:4]] == ["snapshot", "simulate"]
    assert not any("images" in m for m in sent[:4])  # a vision template may drop a tool message's images
    assert "snapshot" in sent[4]["content"] and len(sent[4]["images"]) == 1 and decodes_to_the_png(sent[4]["images"][0])


# what each backend sent for the conversation without pictures before pictures existed
WITHOUT_PICTURES = {
    "anthropic": [
        {"role": "user", "content": "Model the rotor."},
        {"role": "assistant", "content": [
            {"type": "text", "text": "Let me look at it."},
            {"type": "tool_use", "id": "call_1", "name": "snapshot", "input": {"code": "...", "t": 0.0}},
            {"type": "tool_use", "id": "call_2", "name": "simulate", "input": {"code": "..."}}]},
        {"role": "user", "content": [
            {"type": "tool_result", "tool_use_id": "call_1", "content": VIEWS},
            {"type": "tool_result", "tool_use_id": "call_2", "content": '{"stage": "solved"}'}]}],
    "openai": [
        {"role": "user", "content": "Model the rotor."},
        {"role": "assistant", "content": "Let me look at it.", "tool_calls": [
            {"id": "call_1", "type": "function", "function": {"name": "snapshot",
                                                              "arguments": '{"code": "...", "t": 0.0}'}},
            {"id": "call_2", "type": "function", "function": {"name": "simulate", "arguments": '{"code": "..."}'}}]},
        {"role": "tool", "tool_call_id": "call_1", "content": VIEWS},
        {"role": "tool", "tool_call_id": "call_2", "content": '{"stage": "solved"}'}],
    "ollama": [
        {"role": "user", "content": "Model the rotor."},
        {"role": "assistant", "content": "Let me look at it.", "tool_calls": [
            {"function": {"name": "snapshot", "arguments": {"code": "...", "t": 0.0}}},
            {"function": {"name": "simulate", "arguments": {"code": "..."}}}]},
        {"role": "tool", "tool_name": "snapshot", "content": VIEWS},
        {"role": "tool", "tool_name": "simulate", "content": '{"stage": "solved"}'}],
}


def png_size(data: str) -> tuple[int, int]:
    """Width and height from a base64 PNG's IHDR (the fakes have checked its signature)."""
    import struct

    raw = base64.b64decode(data)
    return struct.unpack(">II", raw[16:24])


def snapshot_script(known: dict[str, Any], backend_name: str) -> Any:
    """A vision model's answers: the components, then a ``snapshot`` of the reference program, then
    (once the tool has answered) the reference program."""
    def answer(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        purpose, gold = gold_answer(known, body)
        program = next(inst for desc, inst in known.items() if desc in prompt_of(body)).reference_program
        answered = any(m["role"] == "tool" for m in body["messages"]) or len(body["messages"]) > 1
        if backend_name == "anthropic":
            if purpose == "code" and not answered:
                return 200, anthropic_reply(tool_uses=({"id": "toolu_01", "name": "snapshot",
                                                        "input": {"code": program}},), stop_reason="tool_use"), {}
            return 200, anthropic_reply(gold), {}
        reply = openai_reply(gold) if backend_name == "openai" else chat_reply(gold)
        if purpose == "code" and not answered:
            message = reply["choices"][0]["message"] if backend_name == "openai" else reply["message"]
            call: dict[str, Any] = {"function": {"name": "snapshot", "arguments": {"code": program}}}
            if backend_name == "openai":
                call = {"id": "call_1", "type": "function",
                        "function": {"name": "snapshot", "arguments": json.dumps({"code": program})}}
            message["content"], message["tool_calls"] = "", [call]
        return 200, reply, {}
    return answer


def picture_sent(backend_name: str, body: dict[str, Any]) -> str:
    """The one picture of the request after the snapshot, from where each API carries it."""
    messages = body["messages"]
    if backend_name == "anthropic":
        (result,) = messages[-1]["content"]
        (image,) = [b for b in result["content"] if b["type"] == "image"]
        assert result["tool_use_id"] == "toolu_01" and image["source"]["media_type"] == "image/png"
        return str(image["source"]["data"])
    assert [m["role"] for m in messages[-2:]] == ["tool", "user"]
    if backend_name == "openai":
        (url,) = [part["image_url"]["url"] for part in messages[-1]["content"] if part["type"] == "image_url"]
        assert url.startswith("data:image/png;base64,")
        return str(url.removeprefix("data:image/png;base64,"))
    (image,) = messages[-1]["images"]
    return str(image)


async def test_cli_vision_run_sends_the_snapshot_to_all_three_apis(tmp_path: Path) -> None:
    """``meceng run --agent loop --vision`` as a user starts it: the model asks for a snapshot and
    the tool's PNG reaches the fake Anthropic, OpenAI and Ollama servers in each one's form (which
    the fakes check as the real APIs do)."""
    held_out = "four_bar_mechanism_rigid_bodies"  # three bodies, none of the inspector's own test tasks
    known = instances((held_out,))
    async with (FakeAnthropic(snapshot_script(known, "anthropic"), key=SENTINEL) as claude,
                FakeOllama(snapshot_script(known, "openai")) as gpt,
                FakeOllama(snapshot_script(known, "ollama")) as local):
        ran = await asyncio.gather(*(
            cli_run(tmp_path, name, name, url, "--agent", "loop", "--vision", only=held_out)
            for name, url in (("anthropic", claude.url), ("openai", gpt.url + "/v1"), ("ollama", local.url))))
    for (code, output), (name, server) in zip(ran, (("anthropic", claude), ("openai", gpt), ("ollama", local)),
                                              strict=True):
        assert code == 0, output
        run = json.loads((tmp_path / name / "run.json").read_text())
        task = run["tasks"][0]
        assert run["settings"]["llm"]["vision"] is True and task["overall"] is True, output
        assert task["agent"]["tool_calls"] == {"snapshot": 1}
        width, height = png_size(picture_sent(name, server.requests[-1]))
        assert width >= 200 and height >= 200  # the drawing, not a placeholder


@pytest.mark.parametrize("backend_name", ["anthropic", "openai", "ollama"])
async def test_a_conversation_without_pictures_is_sent_as_before(backend_name: str) -> None:
    sent = await sent_messages(backend_name, conversation(pictures=False))
    assert json.dumps(sent) == json.dumps(WITHOUT_PICTURES[backend_name])


@pytest.mark.parametrize(("check", "messages", "said"), [
    # the picture inside the tool message, as Chat Completions does not take it
    (openai_problem, [{"role": "assistant", "content": "", "tool_calls": [{"id": "c1"}]},
                      {"role": "tool", "tool_call_id": "c1", "content": [
                          {"type": "image_url", "image_url": {"url": f"data:image/png;base64,{PNG}"}}]}],
     "not supported here"),
    # a user message between the answers of one turn
    (openai_problem, [{"role": "assistant", "content": "", "tool_calls": [{"id": "c1"}, {"id": "c2"}]},
                      {"role": "tool", "tool_call_id": "c1", "content": "a"}, {"role": "user", "content": "pic"},
                      {"role": "tool", "tool_call_id": "c2", "content": "b"}], "did not have response messages"),
    (openai_problem, [{"role": "user", "content": [{"type": "image_url", "image_url": {"url": PNG}}]}],
     "data URL"),
    (openai_problem, [{"role": "user", "content": [
        {"type": "image_url", "image_url": {"url": f"data:image/jpeg;base64,{PNG}"}}]}], "not image/jpeg"),
    (anthropic_problem, [{"role": "assistant", "content": [{"type": "tool_use", "id": "t1"}]},
                         {"role": "user", "content": [{"type": "tool_result", "tool_use_id": "t1", "content": [
                             {"type": "image", "source": {"type": "base64", "media_type": "image/png",
                                                          "data": "bm90IGEgcGljdHVyZQ=="}}]}]}],
     "not image/png"),
    (anthropic_problem, [{"role": "assistant", "content": [{"type": "tool_use", "id": "t1"}]},
                         {"role": "user", "content": [{"type": "tool_result", "tool_use_id": "t1", "content": [
                             {"type": "text", "text": ""}]}]}], "non-empty"),
    (anthropic_problem, [{"role": "assistant", "content": [{"type": "tool_use", "id": "t1"}]},
                         {"role": "user", "content": "the picture"}], "without `tool_result`"),
    (ollama_problem, [{"role": "user", "content": "pic", "images": ["not base64!"]}], "base64"),
])
def test_the_fakes_refuse_what_the_apis_refuse(check: Any, messages: list[dict[str, Any]], said: str) -> None:
    problem = check({"messages": messages})
    assert problem is not None and said in problem


async def cli_run(tmp_path: Path, name: str, backend: str, url: str, *extra: str,
                  levels: str = "1,2", only: str = "single_mass_oscillator,single_pendulum") -> tuple[int, str]:
    env = {**os.environ, "OPENAI_API_KEY": SENTINEL, "ANTHROPIC_API_KEY": SENTINEL}
    proc = await asyncio.create_subprocess_exec(
        sys.executable, "-m", "meceng", "run", "--backend", backend, "--base-url", url, "--model", "claude-x",
        "--levels", levels, "--only", only, "--variations", "1", "--out", str(tmp_path), "--name", name,
        "--no-progress", *extra, env=env, stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.STDOUT)
    output, _ = await asyncio.wait_for(proc.communicate(), timeout=600)
    return proc.returncode or 0, output.decode()


def assert_no_key_in(folder: Path, output: str) -> None:
    files = [p for p in folder.rglob("*") if p.is_file()]
    assert len(files) > 5 and SENTINEL not in output
    leaking = [str(p) for p in files if SENTINEL.encode() in p.read_bytes()]
    assert leaking == []


@pytest.mark.parametrize("agent", ["pipeline", "loop"])
async def test_cli_runs_on_both_apis_grade_like_ollama_and_keep_no_key(tmp_path: Path, agent: str) -> None:
    """``meceng run --backend anthropic|openai --base-url ...`` as a user starts it, with a sentinel
    key in the environment: graded 100 % with right answers, and the key is in no file of the run."""
    known = instances(("single_mass_oscillator", "single_pendulum"))

    def answer_anthropic(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        return 200, anthropic_reply(gold_answer(known, body)[1]), {}

    def answer_openai(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        if "temperature" in body:
            return 400, {"error": {"message": "Unsupported value: 'temperature'", "type": "invalid_request_error"}}, {}
        return 200, openai_reply(gold_answer(known, body)[1]), {}

    async with FakeAnthropic(answer_anthropic, key=SENTINEL) as claude, FakeOllama(answer_openai) as gpt:
        ran = await asyncio.gather(
            cli_run(tmp_path, "claude", "anthropic", claude.url, "--agent", agent),
            cli_run(tmp_path, "gpt", "openai", gpt.url + "/v1", "--api-defaults", "--agent", agent))
    for (code, output), name in zip(ran, ("claude", "gpt"), strict=True):
        assert code == 0, output
        run = json.loads((tmp_path / name / "run.json").read_text())
        assert run["summary"]["counted"] == 2 and run["summary"]["rates"]["overall"] == 1.0, output
        assert run["settings"]["llm"]["api_defaults"] is True
        assert_no_key_in(tmp_path / name, output)
    assert all(h["authorization"] == f"Bearer {SENTINEL}" for h in gpt.headers)


async def test_cli_level3_runs_on_both_apis(tmp_path: Path) -> None:
    """A part and the assembly that loads it, through both APIs: graded like the Ollama path."""
    known = instances(("cantilever_beam",))

    def answer_anthropic(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        return 200, anthropic_reply(gold_answer(known, body)[1]), {}

    def answer_openai(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        return 200, openai_reply(gold_answer(known, body)[1]), {}

    async with FakeAnthropic(answer_anthropic, key=SENTINEL) as claude, FakeOllama(answer_openai) as gpt:
        ran = await asyncio.gather(
            cli_run(tmp_path, "claude", "anthropic", claude.url, levels="3b", only="cantilever_beam"),
            cli_run(tmp_path, "gpt", "openai", gpt.url + "/v1", "--api-defaults", levels="3b",
                    only="cantilever_beam"))
    for (code, output), name in zip(ran, ("claude", "gpt"), strict=True):
        assert code == 0, output
        run = json.loads((tmp_path / name / "run.json").read_text())
        levels = run["summary"]["levels"]
        assert levels["3a"]["rates"]["overall"] == 1.0 and levels["3b"]["rates"]["overall"] == 1.0, output
        assert_no_key_in(tmp_path / name, output)


def test_cli_without_key_says_so_and_writes_nothing(tmp_path: Path) -> None:
    import subprocess

    env = {k: v for k, v in os.environ.items() if k not in ("ANTHROPIC_API_KEY", "OPENAI_API_KEY")}
    proc = subprocess.run([sys.executable, "-m", "meceng", "run", "--backend", "anthropic", "--model", "claude-x",
                           "--only", "3", "--variations", "1", "--out", str(tmp_path / "runs"), "--no-progress"],
                          capture_output=True, text=True, timeout=120, env=env)
    assert proc.returncode == 2 and "ANTHROPIC_API_KEY" in proc.stderr
    assert not (tmp_path / "runs").exists()


@pytest.mark.parametrize(("host", "fields"), [
    ("https://api.openai.com/v1", {"max_completion_tokens"}),
    ("https://myres.openai.azure.com/openai/v1", {"max_completion_tokens"}),
    ("http://127.0.0.1:8000/v1", {"max_tokens", "max_completion_tokens"}),
])
def test_answer_limit_fields_per_server(host: str, fields: set[str]) -> None:
    from meceng.llm.backend_openai import answer_limit_fields

    sent = answer_limit_fields(host, 2048)
    assert set(sent) == fields and set(sent.values()) == {2048}


OVERFLOW_BODIES = [  # (body as each server words it, prompt tokens, context)
    ({"error": {"message": "This model's maximum context length is 4096 tokens. However, you requested 5700 tokens "
                           "(5636 in the messages, 64 in the completion). Please reduce the length of the messages "
                           "or completion.", "type": "invalid_request_error", "code": "context_length_exceeded"}},
     5636, 4096),
    ({"error": {"code": 400, "message": "the request exceeds the available context size, try increasing it",
                "type": "exceed_context_size_error", "n_prompt_tokens": 5000, "n_ctx": 4096}}, 5000, 4096),
    ({"object": "error", "message": "'max_tokens' or 'max_completion_tokens' is too large: 2048. This model's maximum "
                                    "context length is 4096 tokens and your request has 3000 input tokens "
                                    "(2048 > 4096 - 3000).", "type": "BadRequestError", "code": 400}, 3000, 4096),
    ({"object": "error", "message": "Requested token count exceeds the model's maximum context length of 8192 "
                                    "tokens. You requested a total of 9000 tokens: 7000 tokens from the input "
                                    "messages and 2000 tokens for the completion."}, 7000, 8192),
]


@pytest.mark.parametrize(("body", "prompt", "context"), OVERFLOW_BODIES)
def test_context_overflow_is_read_from_each_servers_words(body: dict[str, Any], prompt: int, context: int) -> None:
    from meceng.llm.backend_openai import context_exceeded

    overflow = context_exceeded(400, json.dumps(body), "http://h/v1", 2048)
    assert overflow is not None and not overflow.transient
    assert (overflow.prompt_tokens, overflow.context, overflow.answer_limit) == (prompt, context, 2048)
    assert f"{prompt:,} prompt tokens" in str(overflow) and f"{prompt + 2048:,} tokens" in str(overflow)


def test_other_refusals_are_not_context_overflows() -> None:
    from meceng.llm.backend_openai import context_exceeded

    unsupported = {"error": {"message": "Unsupported value: 'temperature'", "type": "invalid_request_error"}}
    assert context_exceeded(400, json.dumps(unsupported), "h", 64) is None
    assert context_exceeded(500, json.dumps(OVERFLOW_BODIES[0][0]), "h", 64) is None


async def test_prompt_over_the_context_is_said_once_kept_by_resume_and_graded_on_a_named_server(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A 400 context_length_exceeded is asked once, recorded with its numbers and left out of the
    rates; a plain --resume keeps it (the same server would refuse it again), a resume on a server
    the user names (--host) asks again and grades it."""
    from meceng.cli.commands import print_summary
    from meceng.llm.backend_openai import OpenAIBackend

    known = instances(("single_mass_oscillator", "single_pendulum"))
    pendulum_text = next(d for d, i in known.items() if i.slug == "single_pendulum")

    def small_context(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        if pendulum_text in prompt_of(body):
            return 400, OVERFLOW_BODIES[0][0], {}
        return 200, openai_reply(gold_answer(known, body)[1]), {}

    def large_context(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        return 200, openai_reply(gold_answer(known, body)[1]), {}

    only = ("single_mass_oscillator", "single_pendulum")
    async with FakeOllama(small_context) as small:
        llm = LLMSettings(model="m", backend="openai", hosts=(small.url + "/v1",), num_predict=64, backoff_s=0.01)
        settings = RunSettings(llm=llm, only=only, variations=1, out=tmp_path, run_name="ctx", progress=False)
        run_json = await run_benchmark(settings, backend=OpenAIBackend(llm))
        refused = [b for b in small.requests if pendulum_text in prompt_of(b)]
        assert len(refused) == 1  # a permanent refusal: not retried
        resumed = await run_benchmark(replace(settings, resume=True), backend=OpenAIBackend(llm))
        assert len(small.requests) == 3  # the plain resume sent nothing: that server would refuse it again
    run = json.loads(resumed.read_text())
    pendulum = next(t for t in run["tasks"] if t["slug"] == "single_pendulum")
    assert pendulum["first_failure"] == "infrastructure" and pendulum["stages"] == []
    assert pendulum["context_exceeded"] == {"prompt_tokens": 5636, "context": 4096, "answer_limit": 64,
                                            "host": small.url + "/v1"}
    assert "5,636 prompt tokens + 64 answer limit > 4,096 context" in pendulum["infrastructure_error"]
    assert run["summary"]["counted"] == 1 and run["summary"]["rates"]["overall"] == 1.0
    assert run["summary"]["context_exceeded"] == 1
    print_summary(run_json)
    said = capsys.readouterr().out
    assert "did not fit the server's context of 4,096 tokens" in said and "at least 5,700 tokens" in said
    assert "--host URL" in said and "lost to the server" not in said

    async with FakeOllama(large_context) as large:
        llm = replace(llm, hosts=(large.url + "/v1",))
        again = replace(settings, llm=llm, resume=True, retry_overflow=True)
        run = json.loads((await run_benchmark(again, backend=OpenAIBackend(llm))).read_text())
    assert len(large.requests) == 2  # only the pendulum's selection and program
    assert run["summary"]["counted"] == 2 and run["summary"]["rates"]["overall"] == 1.0
    assert run["summary"]["context_exceeded"] == 0


def test_resume_with_host_asks_again_what_did_not_fit(tmp_path: Path) -> None:
    from meceng.cli import build_parser
    from meceng.cli.arguments import resumed_settings

    settings = RunSettings(llm=LLMSettings(model="m", backend="openai", hosts=("http://old:1/v1",)))
    (tmp_path / "r").mkdir()
    (tmp_path / "r" / "settings.json").write_text(json.dumps(settings.to_json()))
    plain = resumed_settings(build_parser().parse_args(["run", "--resume", str(tmp_path / "r")]))
    named = resumed_settings(build_parser().parse_args(["run", "--resume", str(tmp_path / "r"),
                                                        "--host", "http://new:2/v1"]))
    assert plain.retry_overflow is False and plain.llm.hosts == ("http://old:1/v1",)
    assert named.retry_overflow is True and named.llm.hosts == ("http://new:2/v1",)
