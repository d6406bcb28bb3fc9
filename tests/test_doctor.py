"""``meceng doctor`` against the fake servers: the stack lines (a sandbox without libGL fails with the
library and its package), the server lines (reachable, the model served, its context)."""

from __future__ import annotations

import asyncio
import os
import sys
from pathlib import Path

import pytest
from fake_anthropic import FakeAnthropic
from fake_ollama import FakeOllama, openai_reply
from test_preflight import no_libgl

from meceng.llm.probe import probe
from meceng.llm.types import LLMSettings


async def doctor(env: dict[str, str], *args: str) -> tuple[int, str]:
    proc = await asyncio.create_subprocess_exec(sys.executable, "-m", "meceng", "doctor", "--levels", "1", *args,
                                                env={**env, "COLUMNS": "200"}, stdout=asyncio.subprocess.PIPE,
                                                stderr=asyncio.subprocess.STDOUT)
    output, _ = await asyncio.wait_for(proc.communicate(), timeout=300)
    return proc.returncode or 0, output.decode()


async def test_doctor_passes_on_this_machine_with_a_served_model() -> None:
    async with FakeOllama(lambda body: (200, openai_reply("x"), {}), models=("qwen3",), context=32768) as server:
        code, output = await doctor(dict(os.environ), "--backend", "ollama", "--host", server.url, "--model", "qwen3",
                                    "--num-ctx", "16384")
    assert code == 0, output
    assert "ground truth rigid" in output and "import exudyn" in output and "FAILED" not in output
    assert "qwen3 served" in output and "16,384" in output and "32,768" in output
    assert server.requests == []  # listing routes only: nothing asked of the model


async def test_doctor_shows_the_missing_library_and_a_model_not_served(tmp_path: Path) -> None:
    async with FakeOllama(lambda body: (200, openai_reply("x"), {}), models=("llama-3",)) as server:
        code, output = await doctor(no_libgl(tmp_path), "--backend", "openai", "--host", server.url + "/v1",
                                    "--model", "qwen3")
    assert code == 1, output
    assert "libGL.so.1" in output and "libgl1" in output and "mesa-libGL" in output
    assert "qwen3 not served" in output and "llama-3" in output


async def test_probe_reads_each_apis_listing(monkeypatch: pytest.MonkeyPatch) -> None:
    async with FakeOllama(lambda body: (200, {}, {}), models=("m",), context=4096) as server:
        served, = await probe(LLMSettings(model="m", backend="openai", hosts=(server.url + "/v1",)))
    assert served.ok and served.context == 4096 and "max_model_len" in served.detail
    async with FakeAnthropic(lambda body: (200, {}, {}), models=("claude-x",)) as api:
        monkeypatch.delenv("FAKE_ANTHROPIC_KEY_35", raising=False)
        offered, = await probe(LLMSettings(model="claude-x", backend="anthropic", hosts=(api.url,),
                                           api_key_env="FAKE_ANTHROPIC_KEY_35"))
        assert not offered.ok and "API key" in offered.detail  # no key in that variable
        monkeypatch.setenv("FAKE_ANTHROPIC_KEY_35", api.key)
        offered, = await probe(LLMSettings(model="claude-x", backend="anthropic", hosts=(api.url,),
                                           api_key_env="FAKE_ANTHROPIC_KEY_35"))
        missing, = await probe(LLMSettings(model="claude-nope", backend="anthropic", hosts=(api.url,),
                                           api_key_env="FAKE_ANTHROPIC_KEY_35"))
    assert offered.ok and "claude-x offered" in offered.detail
    assert missing.reachable and not missing.served
    down, = await probe(LLMSettings(model="m", backend="ollama", hosts=("http://127.0.0.1:9",)))
    assert not down.reachable
