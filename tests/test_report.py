"""A small grid (2 fake models x 2 temperatures x 2 code prompts) against a fake Ollama server,
then `meceng report`: the numbers in report.md / report.json match the run records."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

from fake_ollama import FakeOllama, chat_reply

from meceng.agents.prompts import gold_code, gold_selection
from meceng.eval.rates import wilson
from meceng.llm.types import LLMSettings
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
    spec = tmp_path / "models.toml"
    spec.write_text('[[models]]\nname = "strong:1b"\nprice_prompt = 3.0\nprice_completion = 15.0\n')
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "report", str(tmp_path / "runs"), "--out", str(out),
                           "--models", str(spec)], capture_output=True, text=True, timeout=300)
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
    # tokens per model: a task is a selection (100 prompt, 50 completion) and a code answer (100, 300)
    tokens = {r["model"]: r for r in report["tokens"]}
    assert tokens["strong:1b"]["tasks"] == 16 and tokens["strong:1b"]["prompt"] == 3200
    assert tokens["strong:1b"]["completion"] == 5600 and tokens["strong:1b"]["reasoning"] == 0
    assert abs(tokens["strong:1b"]["cost"] - (3200 * 3.0 + 5600 * 15.0) / 1e6) < 1e-12
    assert tokens["weak:1b"]["cost"] is None and "| strong:1b | 16 | 3,200 | 5,600 | 0 | 0.09 |" in markdown
    one_run = json.loads(next((tmp_path / "runs").glob("*/run.json")).read_text())
    assert one_run["summary"]["tokens"]["totals"] == {"prompt": 800, "completion": 1400, "reasoning": 0}
    assert "50.0 [15–85]" in markdown  # 2 of 4 with its Wilson interval


def test_level3_tables_count_parts_and_assemblies_apart(tmp_path) -> None:
    import json as _json

    from meceng.eval.rates import load_runs
    from meceng.eval.tables import flexible_table, flexible_timing_table

    def part(ok: bool, origin: str) -> dict:
        return {"level": "3a", "slug": "p", "seed": 0, "origin": origin, "overall": ok, "first_failure": None,
                "stages": [{"name": "choose_part_components", "passed": True},
                           {"name": "mesh_match", "passed": ok}],
                "timing": {"llm_s": 60.0, "evaluation_s": 30.0}, "tokens": {"completion": 500},
                "generation": {"meta": {"context_used": 1000}}}

    def assembly(started: bool, ok: bool) -> dict:
        return {"level": "3b", "slug": "a", "seed": 0, "overall": ok, "first_failure": None,
                "stages": [{"name": "parts_overall", "passed": started}, {"name": "mbs_started", "passed": started},
                           {"name": "choose_components", "passed": started}],
                "timing": {"llm_s": 60.0 if started else 0.0, "evaluation_s": 6.0, "mbs_evaluation_s": 6.0},
                "tokens": {"completion": 1000 if started else 0}}

    tasks = [part(True, "a@0"), part(True, "a@0"), assembly(True, True), part(False, "a@1"), assembly(False, False)]
    run_dir = tmp_path / "run"
    run_dir.mkdir()
    (run_dir / "run.json").write_text(_json.dumps({"settings": {"llm": {"model": "m", "temperature": 0, "think": False,
                                                                       "batch_size": 8},
                                                               "prompt": {"select_template": "CI1",
                                                                          "code_template": "MBS1"}},
                                                  "summary": {}, "tasks": tasks}))
    runs = load_runs([run_dir])
    row = flexible_table(runs)[0]
    assert (row["parts"], row["assemblies"]) == (3, 2)
    assert row["parts overall"].passed == 2 and row["MBS started"].passed == 1 and row["overall"].passed == 1
    timing = flexible_timing_table(runs)[0]
    assert timing["parts_eval_min"] == 1.5 and timing["mbs_eval_min"] == 0.2 and timing["batch_size"] == 8
    assert timing["generated_tokens_k"] == 2.5 and timing["context_p95"] == 1000


def test_rigid_tables_count_levels_1_and_2_only(tmp_path) -> None:
    """Tables 4 and 5 and Figures 8-10 are about levels 1-2: a part has no component-selection
    stage of that name and must not count as a failed selection; a flexible-only run has no such
    sections at all."""
    from meceng.eval.rates import load_runs
    from meceng.eval.tables import component_series, error_category_table, series, thinking_table
    from meceng.report import build_report

    rigid = {"level": "1", "slug": "r", "seed": 0, "overall": True, "first_failure": None,
             "stages": [{"name": "choose_components", "passed": True}], "error_categories": []}
    part = {"level": "3a", "slug": "p", "seed": 0, "origin": "a@0", "overall": False, "first_failure": "mesh_match",
            "stages": [{"name": "choose_part_components", "passed": True}, {"name": "mesh_match", "passed": False}]}
    settings = {"llm": {"model": "m", "temperature": 0, "think": False},
                "prompt": {"select_template": "CI1", "code_template": "MBS1"}}
    for name, tasks in (("mixed", [rigid, part, part]), ("flexible", [part])):
        (tmp_path / name).mkdir()
        (tmp_path / name / "run.json").write_text(json.dumps({"settings": settings, "summary": {}, "tasks": tasks}))
    mixed = load_runs([tmp_path / "mixed"])
    assert component_series(mixed)["m"]["CI1"].n == 1 and component_series(mixed)["m"]["CI1"].passed == 1
    assert series(mixed, "temperature")["m"]["0"].n == 1 and thinking_table(mixed)[0]["n"] == 1
    assert error_category_table(mixed)[0]["n"] == 1
    flexible = load_runs([tmp_path / "flexible"])
    assert thinking_table(flexible) == [] and component_series(flexible) == {} and error_category_table(flexible) == []
    build_report([tmp_path / "flexible"], tmp_path / "report")
    text = (tmp_path / "report" / "report.md").read_text()
    assert "Table 6" in text and "Table 4" not in text and "Fig. 9" not in text


def test_wilson_interval_holds_the_rate_at_the_ends() -> None:
    from meceng.eval.rates import Rate

    for n in range(1, 60):  # n = 3, 6, 7 at 0 % and 10, 13 at 100 % round past the rate
        for passed in (0, n):
            rate = Rate(passed, n)
            low, high = rate.interval
            assert low <= rate.value <= high
            assert min(rate.error_bar) >= 0.0
    assert Rate(0, 0).error_bar == (0.0, 0.0)


async def _one_sided_run(tmp_path: Path, name: str, responder, only: tuple[str, ...], variations: int) -> Path:
    async with FakeOllama(responder) as server:
        llm = LLMSettings(model=name, backend="ollama", hosts=(server.url,), max_attempts=1)
        settings = RunSettings(llm=llm, only=only, variations=variations, out=tmp_path / "runs", run_name=name,
                               progress=False)
        return await run_benchmark(settings)


async def test_report_on_perfect_failed_and_infrastructure_only_runs(tmp_path: Path) -> None:
    """The first thing a user reports on is a perfect gold run: rates of 100 % (and 0 %, and runs
    where nothing was graded) must give a report, not a matplotlib error."""
    from meceng.report import build_report

    # n = 10 at 100 % and n = 6 at 0 % are sizes where the interval's end rounds past the rate
    gold = RunSettings(only=("single_mass_oscillator",), variations=10, out=tmp_path / "runs", run_name="gold",
                       progress=False)
    perfect = await run_benchmark(gold)
    single = await run_benchmark(replace(gold, variations=1, run_name="single"))  # n = 1
    failed = await _one_sided_run(tmp_path, "failing:1b", lambda body: (200, chat_reply("no idea"), {}),
                                  SLUGS, 3)
    broken = await _one_sided_run(tmp_path, "absent:1b", lambda body: (404, {"error": "model not found"}, {}),
                                  SLUGS, 1)
    assert {t["overall"] for t in json.loads(perfect.read_text())["tasks"]} == {True}
    assert {t["overall"] for t in json.loads(failed.read_text())["tasks"]} == {False}
    assert {t["first_failure"] for t in json.loads(broken.read_text())["tasks"]} == {"infrastructure"}

    for runs in ([perfect.parent], [single.parent], [failed.parent], [broken.parent],
                 [perfect.parent, failed.parent, broken.parent]):
        out = tmp_path / ("report-" + "-".join(r.name for r in runs))
        written = build_report(runs, out)
        assert (out / "report.html").stat().st_size > 0 and (out / "report.md").stat().st_size > 0
        assert (out / "stages.png").stat().st_size > 0
        assert all(Path(p).exists() for p in written.values())
    markdown = (tmp_path / "report-gold" / "report.md").read_text()
    assert "100.0 [" in markdown
