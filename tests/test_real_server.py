"""MecEng against a real OpenAI-compatible server: llama.cpp's (llama-cpp-python's
``llama_cpp.server``) in its own process on 127.0.0.1, serving a tiny random llama the tests write
(``llama_server.py``). Its answers are ``#`` over and over, so every graded task must be the
model's failure, and an answer limit the server ignored would show in every answer.

What the fakes never did and this server does: it reads only ``max_tokens`` (not
``max_completion_tokens``), refuses a prompt over its context with 400 ``context_length_exceeded``,
answers one request at a time (the others wait in its queue), reports a forced tool call cut by
the limit as ``finish_reason: tool_calls`` with arguments that are not JSON, and counts a prompt in
its own tokens (one per byte here).

Skipped without the ``servers`` extra; ``.ci/run`` installs it and sets MECENG_REAL_SERVERS=required,
so there a missing extra fails instead of skipping.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest
from llama_server import SERVED_NAME, LlamaServer, servers_missing, write_tiny_llama
from records import normalized

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.llm.backend_openai import OpenAIBackend
from meceng.llm.messages import assistant_message, tool_message, user_messages
from meceng.llm.scheduler import Endpoint
from meceng.llm.types import ChatRequest, ChatResponse, ContextExceeded, LLMSettings, ToolCall
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.alternatives import ALTERNATIVES
from meceng.tasks.registry import default_registry

MISSING = servers_missing()
if MISSING is not None:
    if os.environ.get("MECENG_REAL_SERVERS") == "required":
        raise RuntimeError(MISSING)
    pytest.skip(MISSING, allow_module_level=True)

pytestmark = pytest.mark.servers

LIMIT = 16
CONTEXT = 8192
SLUGS = ("single_mass_oscillator", "single_pendulum", "free_fall_mass_point")
MODEL_FAILURES = ("choose_components", "finished_assemble")


@pytest.fixture(scope="module")
def model(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_tiny_llama(tmp_path_factory.mktemp("model") / "tiny.gguf")


@pytest.fixture(scope="module")
def server(model: Path) -> Iterator[LlamaServer]:
    with LlamaServer(model, n_ctx=CONTEXT) as running:
        yield running


@pytest.fixture(scope="module")
def small_server(model: Path, tmp_path_factory: pytest.TempPathFactory) -> Iterator[LlamaServer]:
    """A context smaller than every MecEng prompt (~5,600 byte tokens)."""
    with LlamaServer(model, n_ctx=1024, log=tmp_path_factory.mktemp("small") / "server.log") as running:
        yield running


def llm(url: str, **changes: Any) -> LLMSettings:
    return LLMSettings(**{"model": SERVED_NAME, "backend": "openai", "hosts": (url,), "num_predict": LIMIT,
                          "num_ctx": CONTEXT, "batch_size": 4, "timeout_s": 120.0, "backoff_s": 0.2, **changes})


class WatchedBackend(OpenAIBackend):
    """The real OpenAI backend, counting what it sends: requests, and how many are in flight at
    once. With ``force_tool`` the first request of an agent conversation must call that tool
    (``tool_choice``): a random model would never call one by itself."""

    def __init__(self, settings: LLMSettings, force_tool: str | None = None) -> None:
        super().__init__(settings)
        self.force_tool = force_tool
        self.sent = 0
        self.in_flight = self.max_in_flight = 0

    def request_body(self, host: str, request: ChatRequest) -> dict[str, Any]:
        body = super().request_body(host, request)
        if self.force_tool and request.tools and len(request.messages) == 1:
            body["tool_choice"] = {"type": "function", "function": {"name": self.force_tool}}
        return body

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        self.sent += 1
        self.in_flight += 1
        self.max_in_flight = max(self.max_in_flight, self.in_flight)
        try:
            return await super()._send(endpoint, request)
        finally:
            self.in_flight -= 1


def answers(task: dict[str, Any]) -> list[dict[str, Any]]:
    """The metadata of every model answer a record holds (selection, program, agent rounds)."""
    metas = [task[step]["meta"] for step in ("selection", "generation") if task.get(step, {}).get("meta", {}).get(
        "done_reason") is not None]
    turns = (task.get("agent") or {}).get("transcript") or []
    return metas + [t["meta"] for t in turns if t.get("role") == "assistant"]


async def test_the_answer_limit_reaches_the_server(server: LlamaServer, small_server: LlamaServer) -> None:
    backend = OpenAIBackend(llm(server.url))
    response = await backend.chat(ChatRequest(user_messages("Write a pendulum."), "code", "t@0"))
    await backend.aclose()
    assert response.completion_tokens == LIMIT and response.truncated and set(response.content) == {"#"}
    # why the backend sends max_tokens too: this server ignores max_completion_tokens alone (the
    # answer ran on to the end of its context)
    alone = httpx.post(f"{small_server.url}/chat/completions", timeout=120, json={
        "model": SERVED_NAME, "messages": [{"role": "user", "content": "hi"}], "max_completion_tokens": LIMIT,
        "temperature": 0.0})
    assert alone.status_code == 200 and alone.json()["usage"]["completion_tokens"] > 10 * LIMIT


async def test_a_prompt_over_the_servers_context_is_refused_once_with_its_numbers(
        small_server: LlamaServer, tmp_path: Path) -> None:
    backend = WatchedBackend(llm(small_server.url, num_ctx=1024))
    with pytest.raises(ContextExceeded) as refused:
        await backend.chat(ChatRequest(user_messages("x" * 2000), "select", "t@0"))
    assert refused.value.context == 1024 and refused.value.prompt_tokens and refused.value.prompt_tokens > 2000
    settings = RunSettings(llm=backend.settings, only=SLUGS[:2], variations=1, out=tmp_path, run_name="small",
                           progress=False, workers=1)
    run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
    assert backend.sent == 1 + 2  # one request per task: refused for good, not retried
    assert run["summary"]["context_exceeded"] == 2 and run["summary"]["counted"] == 0
    for task in run["tasks"]:
        assert task["context_exceeded"]["context"] == 1024 and task["context_exceeded"]["prompt_tokens"] > 5000
        assert "does not fit the server's context" in task["infrastructure_error"]


async def test_a_pipeline_run_grades_every_task_as_the_models_failure(server: LlamaServer, tmp_path: Path) -> None:
    backend = WatchedBackend(llm(server.url))
    settings = RunSettings(llm=backend.settings, only=SLUGS, variations=2, out=tmp_path, run_name="pipeline",
                           progress=False, workers=2)
    run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
    tasks = run["tasks"]
    assert len(tasks) == 6 and run["summary"]["infrastructure_failures"] == 0
    assert all(t["overall"] is False and t["first_failure"] in MODEL_FAILURES for t in tasks)
    metas = [m for t in tasks for m in answers(t)]
    assert len(metas) == 12 and all(m["completion_tokens"] == LIMIT and m["truncated"] for m in metas)
    assert all(t["selection"]["meta"]["prompt_tokens"] > 5000 for t in tasks)  # the server's own count
    assert backend.max_in_flight >= 2  # several requests wait in the server's queue at once


async def test_an_agent_run_calls_tools_through_the_servers_chat_template(server: LlamaServer,
                                                                          tmp_path: Path) -> None:
    backend = WatchedBackend(llm(server.url), force_tool="simulate")
    settings = RunSettings(llm=backend.settings, only=SLUGS, variations=1, out=tmp_path, run_name="agent",
                           progress=False, workers=2, agent="loop", max_rounds=3)
    run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
    tasks = run["tasks"]
    assert len(tasks) == 3 and run["summary"]["infrastructure_failures"] == 0
    for task in tasks:
        assert task["overall"] is False and task["first_failure"] in MODEL_FAILURES
        assert task["agent"]["tool_calls"] == {"simulate": 1} and task["agent"]["rounds"] == 2
        call, result = task["agent"]["transcript"][1], task["agent"]["transcript"][2]
        assert call["tool_calls"][0]["id"] and call["meta"]["truncated"]  # cut by the limit mid-arguments
        assert result["role"] == "tool" and "not valid JSON" in result["content"]
        assert all(m["completion_tokens"] <= LIMIT for m in answers(task))


async def test_a_compare_call_is_answered_recorded_and_its_answer_read_by_the_server(server: LlamaServer,
                                                                                        tmp_path: Path) -> None:
    """The tiny model, made to call ``compare``, cuts its arguments at the limit: the call is
    answered (not valid JSON) and recorded like every tool call. Then a conversation that carries a
    real compare (the ground truth against itself built another way) and its answer: the server's
    tool handling and template take both, and it answers."""
    backend = WatchedBackend(llm(server.url), force_tool="compare")
    settings = RunSettings(llm=backend.settings, only=SLUGS[:1], variations=1, out=tmp_path, run_name="compare",
                           progress=False, workers=1, agent="loop", max_rounds=2)
    run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
    (task,) = run["tasks"]
    assert task["agent"]["tool_calls"] == {"compare": 1} and run["summary"]["infrastructure_failures"] == 0
    call, result = task["agent"]["transcript"][1], task["agent"]["transcript"][2]
    assert call["tool_calls"][0]["name"] == "compare" and call["meta"]["truncated"]
    assert result["role"] == "tool" and result["name"] == "compare" and "not valid JSON" in result["content"]

    instance = default_registry().get(SLUGS[0]).instance(0)
    other = next(a for a in ALTERNATIVES if a.slug == SLUGS[0]).program(instance)
    toolbox = Toolbox(instance, rigid_catalog())
    arguments = {"code_a": instance.reference_program, "code_b": other}
    answer = (await toolbox.call("compare", arguments)).text
    assert answer.startswith("compare: A and B move alike")
    compare_call = ToolCall("compare", arguments, "call_1")
    messages = (*user_messages("Is my program right?"),
                assistant_message(ChatResponse("", tool_calls=(compare_call,))), tool_message(compare_call, answer))
    reply = await backend.chat(ChatRequest(messages, "code", instance.key, tools=toolbox.schemas))
    await backend.aclose()
    assert reply.completion_tokens > 0 and reply.prompt_tokens > len(answer)  # one token a byte: the answer was read


async def test_a_consensus_run_of_noise_is_every_sample_a_group_of_its_own(server: LlamaServer,
                                                                           tmp_path: Path) -> None:
    """``--agent consensus`` on the real server: three samples per task at distinct seeds, each the
    model's failure and none like another (no program, no motion), so every group is one sample
    and the confidence 1/3."""
    backend = WatchedBackend(llm(server.url, temperature=0.7))
    settings = RunSettings(llm=backend.settings, only=SLUGS[:1], variations=1, out=tmp_path, run_name="consensus",
                           progress=False, workers=2, agent="consensus", samples=3)
    run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
    assert backend.sent == 3 * 2 and run["summary"]["infrastructure_failures"] == 0
    for task in run["tasks"]:
        block = task["consensus"]
        assert task["overall"] is False and task["first_failure"] in MODEL_FAILURES
        assert block["groups"] == [[0], [1], [2]] and block["confidence"] == pytest.approx(1 / 3, abs=1e-4)
        assert [s["seed"] for s in block["samples"]] == [42, 43, 44]
        assert all(s["lost"] is None and s["overall"] is False and s["ran"] is False for s in block["samples"])


@pytest.mark.slow
async def test_a_hung_server_ends_the_run_in_bounded_time_with_the_tasks_lost(model: Path, tmp_path: Path) -> None:
    """The server stopped (SIGSTOP): connections are accepted, nothing is answered. The first
    requests wait out their timeout; the rest are refused unsent, so the run ends with every task
    lost after a couple of timeouts instead of one per request and attempt."""
    with LlamaServer(model, n_ctx=CONTEXT, log=tmp_path / "server.log") as hung:
        hung.freeze()
        backend = WatchedBackend(llm(hung.url, timeout_s=3.0, max_attempts=3, batch_size=2))
        settings = RunSettings(llm=backend.settings, only=SLUGS, variations=2, out=tmp_path, run_name="hung",
                               progress=False, workers=1)
        try:
            run = json.loads((await run_benchmark(settings, backend=backend)).read_text())
        finally:
            hung.freeze(False)
    assert run["summary"]["infrastructure_failures"] == 6 and run["summary"]["counted"] == 0
    assert backend.sent <= 2 * 2 + 1  # of 6 selections x 3 attempts = 18


def meceng_run(out: Path, name: str, url: str) -> subprocess.Popen[str]:
    """``meceng run`` against the server as a user types it: six level 1-2 tasks, a 16-token limit."""
    args = ["--backend", "openai", "--base-url", url, "--model", SERVED_NAME, "--num-predict", str(LIMIT),
            "--num-ctx", str(CONTEXT), "--llm-timeout", "120", "--only", ",".join(SLUGS), "--variations", "2",
            "--out", str(out), "--name", name, "--no-progress"]
    return subprocess.Popen([sys.executable, "-m", "meceng", "run", *args],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def comparable(run_json: Path) -> dict[str, Any]:
    run = json.loads(run_json.read_text())
    return normalized({"tasks": run["tasks"], "summary": {k: v for k, v in run["summary"].items() if k != "timing"}})


@pytest.mark.slow
def test_a_server_killed_mid_run_loses_tasks_that_resume_finishes_as_an_undisturbed_run(
        model: Path, tmp_path: Path) -> None:
    with LlamaServer(model, n_ctx=CONTEXT, log=tmp_path / "server.log") as server:
        straight = meceng_run(tmp_path, "straight", server.url)
        output, _ = straight.communicate(timeout=600)
        assert straight.returncode == 0, output
        expected = comparable(tmp_path / "straight" / "run.json")

        killed = meceng_run(tmp_path, "killed", server.url)
        journal = tmp_path / "killed" / "journal.jsonl"
        deadline = time.monotonic() + 300
        while (not journal.exists() or journal.read_bytes().count(b"\n") < 1) and time.monotonic() < deadline:
            time.sleep(0.05)
        server.kill()
        output, _ = killed.communicate(timeout=600)  # ends on its own: the tasks in flight and after are lost
        assert killed.returncode == 0, output
        lost = json.loads((tmp_path / "killed" / "run.json").read_text())["summary"]["infrastructure_failures"]
        assert 0 < lost < 6, output
        assert "lost to the server" in output and "--resume" in output

        server.start()  # restarted on the same port, as a user would
        resumed = subprocess.run([sys.executable, "-m", "meceng", "run", "--resume", str(tmp_path / "killed"),
                                  "--no-progress"], capture_output=True, text=True, timeout=600)
        assert resumed.returncode == 0, resumed.stdout + resumed.stderr
    assert comparable(tmp_path / "killed" / "run.json") == expected
    run = json.loads((tmp_path / "killed" / "run.json").read_text())
    assert run["resumed_tasks"] == 6 - lost and run["summary"]["infrastructure_failures"] == 0

