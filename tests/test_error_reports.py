"""An error inside ``mbs.Assemble()`` is reported at the program's own line — number, source line,
Exudyn's message — with no harness frame and no path of this machine: in ``meceng evaluate
--json``, in a run's record and in the agent's ``simulate`` tool."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

INSTANCE = default_registry().get("single_mass_oscillator").instance(1)
BAD_MARKER = "mbs.AddMarker(MarkerNodePosition(nodeNumber=99))"


def broken_program() -> tuple[str, int]:
    """The reference with a marker on a node that does not exist, added just before Assemble."""
    lines = INSTANCE.reference_program.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("mbs.Assemble()"))
    lines.insert(at, BAD_MARKER)
    return "\n".join(lines) + "\n", at + 2  # the Assemble call, 1-based, after the insertion


def assert_at_program_line(error: str, line: int) -> None:
    assert error.startswith(f"line {line} (mbs.Assemble()): ModelError: "), error
    assert "invalid (global) node number 99" in error
    for leak in ("runner.py", "/meceng/", "/tmp/", "/work/", "site-packages", "Python file"):
        assert leak not in error, error


def test_evaluate_json_names_the_programs_line(tmp_path: Path) -> None:
    program, line = broken_program()
    (tmp_path / "bad.py").write_text(program)
    proc = subprocess.run([sys.executable, "-m", "meceng", "evaluate", "single_mass_oscillator", "--seed", "1",
                           "--code", str(tmp_path / "bad.py"), "--json"], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 1, proc.stderr
    data = json.loads(proc.stdout)
    assert data["execution"]["error_line"] == line
    assert_at_program_line(data["execution"]["error"], line)
    stage = next(s for s in data["stages"] if s["name"] == "finished_assemble")
    assert stage["passed"] is False
    assert_at_program_line(stage["detail"], line)


async def test_run_record_names_the_programs_line(tmp_path: Path) -> None:
    program, line = broken_program()

    def responder(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        prompt = body["messages"][-1]["content"]
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(INSTANCE.required_components)), {}
        return 200, chat_reply(gold_code(program)), {}

    async with FakeOllama(responder) as server:
        llm = LLMSettings(model="m", backend="ollama", hosts=(server.url,))
        settings = RunSettings(llm=llm, only=("single_mass_oscillator",), variations=1, seed=1, out=tmp_path,
                               run_name="r", progress=False, workers=1)
        run = json.loads((await run_benchmark(settings)).read_text())
    record = run["tasks"][0]
    assert record["first_failure"] == "finished_assemble"
    assert record["execution"]["error_line"] == line
    assert_at_program_line(record["execution"]["error"], line)
    assert str(tmp_path) not in json.dumps(record["execution"])


async def test_simulate_tool_names_the_programs_line() -> None:
    program, line = broken_program()
    text = (await Toolbox(INSTANCE, rigid_catalog()).call("simulate", {"code": program})).text
    assert_at_program_line(text.splitlines()[0].partition("; error: ")[2], line)
