"""The preflight: a machine whose sandbox cannot import Exudyn stops ``meceng run`` (and ``meceng
rescore``) before any LLM request, with one message naming the missing library and its package."""

from __future__ import annotations

import asyncio
import os
import sys
from pathlib import Path

import pytest
from fake_ollama import FakeOllama, openai_reply

from meceng.pipeline.preflight import SYSTEM_LIBRARIES, StackCheck, explain, missing_library

LIBGL_ERROR = "libGL.so.1: cannot open shared object file: No such file or directory"


def no_libgl(tmp_path: Path) -> dict[str, str]:
    """The environment of a machine without libGL: an ``exudyn`` package first on PYTHONPATH (which
    the sandbox's children get) that fails to import as Exudyn's compiled module does there."""
    stub = tmp_path / "nolibgl" / "exudyn"
    stub.mkdir(parents=True)
    (stub / "__init__.py").write_text(f"raise ImportError({LIBGL_ERROR!r})\n")
    path = os.pathsep.join(p for p in (str(stub.parent), os.environ.get("PYTHONPATH", "")) if p)
    return {**os.environ, "PYTHONPATH": path, "OPENAI_API_KEY": "sk-test"}


async def meceng(env: dict[str, str], *args: str) -> tuple[int, str]:
    proc = await asyncio.create_subprocess_exec(sys.executable, "-m", "meceng", *args, env=env,
                                                stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.STDOUT)
    output, _ = await asyncio.wait_for(proc.communicate(), timeout=300)
    return proc.returncode or 0, output.decode()


async def test_run_without_libgl_stops_before_any_request(tmp_path: Path) -> None:
    async with FakeOllama(lambda body: (200, openai_reply("never"), {})) as server:
        code, output = await meceng(no_libgl(tmp_path), "run", "--backend", "openai", "--base-url", server.url + "/v1",
                                    "--model", "m", "--levels", "1", "--only", "single_pendulum", "--variations", "1",
                                    "--out", str(tmp_path / "runs"), "--name", "r", "--no-progress")
    assert code == 3, output
    assert server.requests == [], "an LLM request was spent on a stack that cannot grade"
    assert "cannot grade" in output and "libGL.so.1" in output, output
    assert "apt-get install libgl1" in output and "dnf install mesa-libGL" in output, output
    journal = tmp_path / "runs" / "r" / "journal.jsonl"
    assert not journal.exists() or journal.read_text() == ""  # no task record: nothing to resume past
    print(output)


async def test_the_same_run_with_the_stack_passes_the_preflight(tmp_path: Path) -> None:
    """The control: the same command on this machine's real stack reaches the server."""
    env = {**os.environ, "OPENAI_API_KEY": "sk-test"}
    async with FakeOllama(lambda body: (200, openai_reply("no program here"), {})) as server:
        code, output = await meceng(env, "run", "--backend", "openai", "--base-url", server.url + "/v1",
                                    "--model", "m", "--levels", "1", "--only", "single_pendulum", "--variations", "1",
                                    "--out", str(tmp_path / "runs"), "--name", "r", "--no-progress")
    assert code == 0, output
    assert len(server.requests) >= 1 and "cannot grade" not in output


@pytest.mark.parametrize(("text", "debian", "rhel"), [
    (LIBGL_ERROR, "libgl1", "mesa-libGL"),
    ("harness setup failed: Exudyn could not import its compiled module: libGLU.so.1: cannot open", "libglu1-mesa",
     "mesa-libGLU"),
    ("ImportError: libXrender.so.1: cannot open shared object file", "libxrender1", "libXrender"),
    ("OSError: libxcb.so.1: cannot open shared object file", "libxcb1", "libxcb"),
])
def test_the_missing_library_is_named_with_its_packages(text: str, debian: str, rhel: str) -> None:
    said = missing_library(text)
    assert said is not None and f"apt-get install {debian}" in said and f"dnf install {rhel}" in said


def test_an_unknown_library_still_is_named_and_no_library_is_invented() -> None:
    assert "libfoo.so.3" in (missing_library("libfoo.so.3: cannot open shared object file") or "")
    assert missing_library("ZeroDivisionError: division by zero") is None
    message = explain([StackCheck("ground truth rigid (x@0)", False, "timeout after 60 s")], ("rigid",))
    assert "meceng doctor" in message and "missing system library" not in message
    assert all(name.startswith("lib") and ".so" in name for name in SYSTEM_LIBRARIES)


async def test_a_sweep_without_libgl_stops_before_any_run_asks_its_server(tmp_path: Path,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    """Once per sweep, before any run: the sweep raises, no run folder gets a record, no request."""
    from meceng.llm.types import LLMSettings
    from meceng.pipeline import RunSettings
    from meceng.pipeline.preflight import StackUnusable
    from meceng.sweeps.farm import SweepJob, run_sweep

    monkeypatch.setenv("PYTHONPATH", no_libgl(tmp_path)["PYTHONPATH"])  # what the sandbox's children get
    async with FakeOllama(lambda body: (200, openai_reply("never"), {})) as server:
        jobs = [SweepJob(name, name, RunSettings(llm=LLMSettings(model=name, backend="ollama", hosts=(server.url,)),
                                                 only=("single_pendulum",), variations=1, out=tmp_path,
                                                 run_name=name, workers=1, progress=False), 1)
                for name in ("m1", "m2")]
        with pytest.raises(StackUnusable, match=r"libGL\.so\.1.*libgl1"):
            await run_sweep(jobs, workers=1, display=False)
    assert server.requests == [] and not (tmp_path / "m1").exists()
