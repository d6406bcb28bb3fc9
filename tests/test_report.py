"""A small grid (2 fake models x 2 temperatures x 2 code prompts) against a fake Ollama server,
then `meceng report`: the numbers in report.md / report.json match the run records."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.llm import LLMSettings
from meceng.agents.prompts import gold_code, gold_selection
from meceng.eval.report import wilson
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry

SLUGS = ("single_mass_oscillator", "double_mass_oscillator")


def test_wilson_interval() -> None:
    low, high = wilson(8, 10)
    assert 0.49 < low < 0.50 and 0.94 < high < 0.95
    assert wilson(0, 0) == (0.0, 1.0)


async def test_report_numbers_match_run_records(tmp_path: Path) -> None:
    registry = default_registry()
    instances = {registry.get(s).instance(k).description: registry.get(s).instance(k) for s in SLUGS for k in (0, 1)}

    def responder(body):
        prompt = body["messages"][-1]["content"]
        instance = next(inst for desc, inst in instances.items() if desc in prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components)), {}
        program = instance.reference_program
        if body["model"] == "weak:1b" and instance.slug == "double_mass_oscillator":
            program = re.sub(r"\nmass2 = ([0-9.]+)\n", lambda m: f"\nmass2 = {float(m.group(1)) * 2!r}\n", program)
        return 200, chat_reply(gold_code(program), completion_tokens=300), {}

    async with FakeOllama(responder) as server:
        for model in ("strong:1b", "weak:1b"):
            for temperature in (0.0, 0.7):
                for code_template in ("MBS1", "MBS3"):
                    llm = LLMSettings(model=model, backend="ollama", hosts=(server.url,), temperature=temperature)
                    settings = RunSettings(llm=llm, only=SLUGS, variations=2, out=tmp_path / "runs",
                                           run_name=f"{model}-{temperature}-{code_template}".replace(":", "-"),
                                           code_template=code_template, progress=False)
                    await run_benchmark(settings)

    out = tmp_path / "report"
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "report", str(tmp_path / "runs"), "--out", str(out)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    for name in ("report.html", "report.md", "stages.png", "temperature.png", "code_templates.png", "difficulty.png"):
        assert (out / name).stat().st_size > 0
    assert "data:image/png;base64," in (out / "report.html").read_text()

    report = json.loads((out / "report.json").read_text())
    records = {}
    for run_json in (tmp_path / "runs").glob("*/run.json"):
        run = json.loads(run_json.read_text())
        records[run["settings"]["llm"]["model"], run["settings"]["llm"]["temperature"],
                run["settings"]["prompt"]["code_template"]] = run["tasks"]
    assert len(report["stages"]) == 8
    for row in report["stages"]:
        model, rest = row["run"].split(" T=")
        temperature = float(rest.split(" ")[0])
        code_template = rest.split("/")[-1]
        tasks = records[model, temperature, code_template]
        assert row["overall"]["n"] == len(tasks) == 4
        assert row["overall"]["passed"] == sum(t["overall"] for t in tasks)
        expected = 4 if model == "strong:1b" else 2
        assert row["overall"]["passed"] == expected
    # sorted as in the paper: best first
    assert [r["overall"]["passed"] for r in report["stages"]] == sorted(
        (r["overall"]["passed"] for r in report["stages"]), reverse=True)
    weak = next(r for r in report["error_categories"] if r["model"] == "weak:1b")
    assert weak["counts"]["inertia and mass"] == 8 and weak["n"] == 16
    hardest = report["difficulty"][0]
    assert hardest["slug"] == "double_mass_oscillator" and hardest["overall"]["passed"] == 8
    markdown = (out / "report.md").read_text()
    assert "| weak:1b T=0.7 think=False CI1/MBS3 | 4 |" in markdown
    assert "50.0 [15–85]" in markdown  # 2 of 4 with its Wilson interval
