"""``meceng run --agent consensus`` as a user starts it, against the fakes of the three APIs
(Ollama's, an OpenAI-compatible server's, Anthropic's): one sample of three is a program with a
seeded fault, so the run must find two groups, answer with the larger and say 2/3."""

from __future__ import annotations

import asyncio
import json
import os
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from fake_anthropic import FakeAnthropic, anthropic_reply
from fake_ollama import FakeOllama, chat_reply, openai_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.tasks.drafts import candidate_drafts
from meceng.tasks.registry import default_registry

SLUG = "single_pendulum"
KEY = "sk-consensus-test"


def answers() -> tuple[str, str, str]:
    """The selection, the right program and a program whose gravity points up."""
    instance = default_registry().get(SLUG).instance(0)
    faulty = next(d for d in candidate_drafts(instance) if d.id == "gravity-sign")
    right = gold_code(instance.reference_program)
    return gold_selection(instance.required_components), right, gold_code(faulty.program)


async def consensus_run(tmp_path: Path, name: str, backend: str, url: str) -> tuple[int, str]:
    env = {**os.environ, "OPENAI_API_KEY": KEY, "ANTHROPIC_API_KEY": KEY}
    proc = await asyncio.create_subprocess_exec(
        sys.executable, "-m", "meceng", "run", "--agent", "consensus", "--samples", "3", "--backend", backend,
        "--base-url", url, "--model", "m", "--only", SLUG, "--variations", "1", "--out", str(tmp_path),
        "--name", name, "--no-progress", "--workers", "2", env=env, stdout=asyncio.subprocess.PIPE,
        stderr=asyncio.subprocess.STDOUT)
    output, _ = await asyncio.wait_for(proc.communicate(), timeout=300)
    return proc.returncode or 0, output.decode()


async def test_consensus_on_the_three_apis_finds_the_faulty_sample(tmp_path: Path) -> None:
    select, right, wrong = answers()
    code_requests: Counter[str] = Counter()

    def program(api: str, prompt: str, seed: int | None) -> str:
        if "<components>" in prompt:
            return select
        code_requests[api] += 1
        # Ollama and the OpenAI-compatible server get the sample's seed; Anthropic's API takes none,
        # so there the second code request is the faulty one
        faulty = seed == 43 if seed is not None else code_requests[api] == 2
        return wrong if faulty else right

    seen: dict[str, list[tuple[Any, Any]]] = {"ollama": [], "openai": []}

    def ollama(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        options = body["options"]
        seen["ollama"].append((options.get("seed"), options.get("temperature")))
        return 200, chat_reply(program("ollama", body["messages"][0]["content"], options.get("seed"))), {}

    def openai(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        seen["openai"].append((body.get("seed"), body.get("temperature")))
        return 200, openai_reply(program("openai", body["messages"][0]["content"], body.get("seed"))), {}

    def anthropic(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        content = body["messages"][0]["content"]
        text = content if isinstance(content, str) else json.dumps(content)
        return 200, anthropic_reply(program("anthropic", text, None)), {}

    async with FakeOllama(ollama) as lama, FakeOllama(openai) as vllm, FakeAnthropic(anthropic, key=KEY) as claude:
        ran = await asyncio.gather(consensus_run(tmp_path, "ollama", "ollama", lama.url),
                                   consensus_run(tmp_path, "openai", "openai", vllm.url + "/v1"),
                                   consensus_run(tmp_path, "anthropic", "anthropic", claude.url))
    for (code, output), name in zip(ran, ("ollama", "openai", "anthropic"), strict=True):
        assert code == 0, output
        record = json.loads((tmp_path / name / "run.json").read_text())["tasks"][0]
        block = record["consensus"]
        assert [len(g) for g in block["groups"]] == [2, 1] and block["confidence"] == 0.6667, name
        assert record["overall"] is True and record["behaviour"]["passed"] is True, name
        assert "consensus: 100.0% of answers pass against 66.7% of single samples (3)" in output, output
        odd = block["samples"][block["groups"][1][0]]
        assert odd["overall"] is False and odd["behaviour_passed"] is False and "motions part" in (
            odd["behaviour_detail"] or "")
    # distinct seeds per sample (the run's 42 + index), at consensus's default temperature
    for api in ("ollama", "openai"):
        assert sorted(s for s, _ in seen[api]) == [42, 42, 43, 43, 44, 44] and {t for _, t in seen[api]} == {0.7}
    assert code_requests == {"ollama": 3, "openai": 3, "anthropic": 3}
