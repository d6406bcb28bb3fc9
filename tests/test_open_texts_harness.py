"""Open texts through the harness (issue 36): the ``--texts`` flag, the record's field, grading by
behaviour, the prompts an open-text task gets, the sweep's texts axis and the report's side-by-side
table. Written for any set of task models that have an open text (one today, 50 once merged); the
gold programs at four seeds are in tests/test_gold.py."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any, ClassVar

import pytest

from meceng.agents.prompts import CODE_TEMPLATES, OPEN_TEXT_NEUTRAL
from meceng.cli import main
from meceng.eval.aggregate import stage_rates
from meceng.eval.chain import BEHAVIOUR_STAGE, StageResult, Tolerances, Verdict, by_behaviour
from meceng.eval.rates import load_runs
from meceng.eval.tables import texts_table
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, instance_prompts, run_benchmark
from meceng.pipeline.evaluation import Evaluator
from meceng.pipeline.records import task_record
from meceng.report import build_report
from meceng.sweeps.spec import load_spec, study_points
from meceng.tasks.alternatives import alternatives_of
from meceng.tasks.base import TaskModel
from meceng.tasks.registry import TaskRegistry, default_registry
from meceng.tools.execution import ExecutionLimits

ROOT = Path(__file__).resolve().parents[1]
PENDULUM = "single_pendulum_rigid_body"  # the first model with an open text


def open_models() -> list[TaskModel]:
    return [m for m in default_registry().select(("1", "2")) if isinstance(m, TaskModel) and m.open_description]


def without_open_text() -> TaskModel:
    """A level-1/2 model without an open text: a real one while some lack it, else a throwaway copy."""
    model = next((m for m in default_registry().select(("1", "2")) if isinstance(m, TaskModel)
                  and not m.open_description), None)
    if model is None:
        base = default_registry().get(PENDULUM)
        model = replace(base, id=9001, name="throwaway without open text", open_description="")
    return model


# --- the flag and what it selects ---------------------------------------------------------------

def test_tasks_show_and_prompt_take_the_open_text(capsys: pytest.CaptureFixture[str]) -> None:
    model = default_registry().get(PENDULUM)
    assert main(["tasks", "show", PENDULUM, "--seed", "2", "--texts", "open", "--json"]) == 0
    shown = json.loads(capsys.readouterr().out)
    assert shown["texts"] == "open"
    assert shown["description"] == model.describe(model.sample_params(2), "open")
    assert main(["tasks", "show", PENDULUM, "--seed", "2", "--json"]) == 0
    assert "texts" not in json.loads(capsys.readouterr().out)  # the paper's text, as before
    assert main(["tasks", "prompt", PENDULUM, "--texts", "open", "--json"]) == 0
    prompts = json.loads(capsys.readouterr().out)
    assert all(model.describe(model.sample_params(0), "open") in p["text"] for p in prompts)


def test_a_task_without_an_open_text_is_a_clear_error(capsys: pytest.CaptureFixture[str]) -> None:
    part = default_registry().select(("3a",))[0]
    with pytest.raises(SystemExit) as stopped:
        main(["tasks", "show", part.slug, "--texts", "open"])
    assert stopped.value.code == 2 and "no open text (a level-3 task)" in capsys.readouterr().err


async def test_run_refuses_levels_and_named_models_without_open_texts(tmp_path: Path) -> None:
    gold = LLMSettings(model="gold", backend="gold")
    with pytest.raises(ValueError, match="level 3a has no open texts"):
        await run_benchmark(RunSettings(llm=gold, levels=("1", "3a"), texts="open", out=tmp_path, progress=False))
    lacking = without_open_text()
    registry = TaskRegistry((default_registry().get(PENDULUM), lacking))
    with pytest.raises(ValueError, match=f"no open text yet for {lacking.slug}"):
        await run_benchmark(RunSettings(llm=gold, only=(lacking.slug,), texts="open", out=tmp_path, progress=False),
                            registry=registry)
    assert list(tmp_path.iterdir()) == []  # refused before any folder was made


def test_with_texts_keeps_the_models_that_have_one_and_names_the_rest() -> None:
    pendulum, lacking = default_registry().get(PENDULUM), without_open_text()
    registry = TaskRegistry((pendulum, lacking))
    models = registry.select(("1", "2"))
    assert registry.with_texts(models, "paper", ("1", "2")) == (models, [])
    assert registry.with_texts(models, "open", ("1", "2")) == ([pendulum], [lacking.slug])
    instances = registry.instances([pendulum], seed=5, variations=2, texts="open")
    assert [(i.key, i.texts) for i in instances] == [(f"{PENDULUM}@5", "open"), (f"{PENDULUM}@6", "open")]
    assert instances[0].description == pendulum.describe(pendulum.sample_params(5), "open")


def test_run_settings_say_their_texts_and_a_resume_keeps_them(tmp_path: Path) -> None:
    settings = RunSettings(texts="open", levels=("1",))
    data = json.loads(json.dumps(settings.to_json()))
    assert data["pipeline"]["texts"] == "open"
    assert RunSettings.from_json(data, out=tmp_path, run_name="r").texts == "open"
    del data["pipeline"]["texts"]  # a run folder from before issue 36
    assert RunSettings.from_json(data, out=tmp_path, run_name="r").texts == "paper"


def test_cli_run_takes_texts() -> None:
    from meceng.cli import build_parser
    from meceng.cli.arguments import llm_settings, run_settings

    args = build_parser().parse_args(["run", "--texts", "open", "--only", PENDULUM])
    assert run_settings(args, llm_settings(args)).texts == "open"
    args = build_parser().parse_args(["run"])
    assert run_settings(args, llm_settings(args)).texts == "paper"
    with pytest.raises(SystemExit):
        build_parser().parse_args(["run", "--texts", "engineer"])


# --- grading by behaviour -----------------------------------------------------------------------

def _paper_verdict(behaviour_passed: bool | None, components: bool = True) -> Verdict:
    stages = (StageResult("choose_components", components, "chosen"),
              StageResult("finished_assemble", True, "mbs.Assemble() finished"),
              StageResult("topology_match", False, "graphs differ"),
              StageResult("graph_content_match", None, "not evaluated: topology differs"),
              StageResult("solver_success", True, "simulation finished"),
              StageResult("solution_match", False, "solutions differ"))
    return Verdict(stages, error_categories=("kinematics/marker",), solution_norm=3.0,
                   behaviour={"passed": behaviour_passed, "detail": "motions compared"})


def test_by_behaviour_counts_behaviour_and_not_the_writing() -> None:
    paper = _paper_verdict(True, components=False)
    assert not paper.overall and paper.first_failure == "choose_components"
    graded = by_behaviour(paper)
    assert graded.overall and graded.first_failure is None and graded.graded_by == "behaviour"
    not_required = {s.name for s in graded.stages if not s.required}
    assert not_required == {"choose_components", "topology_match", "graph_content_match", "solution_match"}
    assert graded.stage("choose_components").passed is False  # kept as it was, not counted
    assert all(s.passed is None and s.detail.startswith("not required")
               for s in graded.stages if s.name in not_required - {"choose_components"})
    assert graded.stages[-1] == StageResult(BEHAVIOUR_STAGE, True, "motions compared")
    assert graded.error_categories == () and graded.differences == ()
    data = graded.to_json()
    assert data["graded_by"] == "behaviour" and {"name": "topology_match", "passed": None,
                                                  "detail": graded.stage("topology_match").detail,
                                                  "required": False} in data["stages"]
    failed = by_behaviour(_paper_verdict(False))
    assert not failed.overall and failed.first_failure == BEHAVIOUR_STAGE
    unknown = by_behaviour(_paper_verdict(None))  # no ground-truth motion: not the model's failure
    assert unknown.first_failure == "infrastructure"


def test_a_paper_verdict_is_unchanged() -> None:
    paper = _paper_verdict(True)
    assert "graded_by" not in paper.to_json() and all("required" not in s for s in paper.to_json()["stages"])
    assert not paper.overall and paper.first_failure == "topology_match"


def test_rates_leave_out_what_a_record_does_not_require() -> None:
    def record(verdict: Verdict) -> dict[str, Any]:
        return {"level": "1", **verdict.to_json()}

    paper = [record(_paper_verdict(True)), record(replace(_paper_verdict(True), stages=tuple(
        replace(s, passed=True) for s in _paper_verdict(True).stages)))]
    before = stage_rates(paper)
    assert before["rates"]["topology_match"] == 0.5 and before["rates"]["overall"] == 0.5
    mixed = stage_rates([*paper, record(by_behaviour(_paper_verdict(True)))])
    assert mixed["rates"]["topology_match"] == 0.5  # over the two records that require it
    assert mixed["rates"]["overall"] == 2 / 3
    only_open = stage_rates([record(by_behaviour(_paper_verdict(True))), record(by_behaviour(_paper_verdict(False)))])
    assert only_open["rates"]["solution_match"] is None and only_open["rates"]["overall"] == 0.5
    assert only_open["rates"][BEHAVIOUR_STAGE] == 0.5 and only_open["rates"]["solver_success"] == 1.0


async def test_a_program_written_another_way_passes_an_open_text_and_fails_the_paper() -> None:
    """tasks/alternatives.py: the pendulum with its reference point at the hinge moves as the
    ground truth does; the paper's grader fails it (graph content), the open text passes it."""
    model = default_registry().get(PENDULUM)
    alternative = alternatives_of(PENDULUM)[0]
    paper, open_ = model.instance(0), model.instance(0, texts="open")
    program = alternative.program(paper)
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=60), Tolerances())
    paper_verdict = (await evaluator.evaluate(paper, program, paper.required_components, None))[0]
    open_verdict, candidate, reference = await evaluator.evaluate(open_, program, open_.required_components, None)
    assert not paper_verdict.overall and paper_verdict.behaviour["passed"]
    assert open_verdict.overall and open_verdict.graded_by == "behaviour"
    record = task_record(open_, _Selection(), _Generation(), open_verdict, candidate, reference,
                         {"llm_s": 0.0, "evaluation_s": 0.0, "total_s": 0.0}, {})
    assert record["texts"] == "open" and record["overall"] and record["graded_by"] == "behaviour"
    # a program that moves otherwise fails the open text too: gravity of another planet
    wrong = program.replace(f"gravity = {paper.params['gravity']!r}", "gravity = 3.71")
    assert wrong != program
    assert not (await evaluator.evaluate(open_, wrong, None, None))[0].overall


class _Selection:
    infrastructure_error = None
    meta: ClassVar[dict[str, Any]] = {}

    def to_json(self) -> dict[str, Any]:
        return {}


class _Generation(_Selection):
    pass


# --- prompts ------------------------------------------------------------------------------------

DICTATING = ("in exactly the order given", "the ground first", "in the order stated in the description",
             "adding items in the order given", "the order the description names them")


@pytest.mark.parametrize("agent", ["pipeline", "loop"])
@pytest.mark.parametrize("template", list(CODE_TEMPLATES))
def test_open_text_prompts_dictate_no_order(template: str, agent: str) -> None:
    for model in open_models():
        prompts = instance_prompts(model.instance(0, texts="open"), RunSettings(code_template=template, agent=agent))
        said = [phrase for p in prompts for phrase in DICTATING if phrase in " ".join(p.text.split())]
        assert said == [], f"{model.slug}: {said}"
        paper = instance_prompts(model.instance(0), RunSettings(code_template=template, agent=agent))
        code = paper[-1].text
        rules = ("Return the whole program in a single", "do not start a renderer", "Do not write files",
                 "one ```python code block", "Give the complete program in a single ```python block")
        assert [r for r in rules if r in code] == [r for r in rules if r in prompts[-1].text]


def test_every_neutral_rule_changes_a_paper_prompt() -> None:
    """The neutral versions are live: each pattern matches a paper prompt (so the test above can fail)."""
    import re

    model = default_registry().get(PENDULUM)
    texts = [p.text for template in CODE_TEMPLATES
             for p in instance_prompts(model.instance(0), RunSettings(code_template=template))]
    for pattern, _ in OPEN_TEXT_NEUTRAL:
        assert any(re.search(pattern, text) for text in texts), pattern


# --- sweeps and the report ----------------------------------------------------------------------

def test_texts_are_a_sweep_axis(tmp_path: Path) -> None:
    spec = tmp_path / "texts.toml"
    spec.write_text(f'[[models]]\nname = "gold"\nbackend = "gold"\n[[studies]]\nname = "t"\nonly = ["{PENDULUM}"]\n'
                    'texts = ["paper", "open"]\nvariations = 2\n')
    points = study_points(load_spec(spec).studies[0])
    assert [(p.texts, p.name.endswith("_texts-open")) for p in points] == [("paper", False), ("open", True)]
    spec.write_text('[[models]]\nname = "gold"\n[[studies]]\nname = "t"\nlevels = ["3b"]\ntexts = ["open"]\n')
    with pytest.raises(ValueError, match=r"study t: texts = 'open'.*3b"):
        load_spec(spec)
    texts = load_spec(ROOT / "sweeps" / "texts.toml").studies[0]
    main_points = {p.name for p in study_points(load_spec(ROOT / "sweeps" / "paper.toml").studies[0])}
    paper_side = [p for p in study_points(texts) if p.texts == "paper"]
    assert len(paper_side) == len(texts.models) == len([p for p in study_points(texts) if p.texts == "open"])
    assert {p.name for p in paper_side} <= main_points  # the main study's runs, not run twice


def _run(folder: Path, model: str, texts: str, results: list[tuple[bool, bool]]) -> None:
    """A run.json with records that pass the paper's verdict / behaviour as given."""
    tasks = []
    for k, (paper, behaviour) in enumerate(results):
        verdict = _paper_verdict(behaviour)
        if paper:
            verdict = replace(verdict, stages=tuple(replace(s, passed=True) for s in verdict.stages))
        if texts == "open":
            verdict = by_behaviour(verdict)
        tasks.append({"slug": PENDULUM, "seed": k, "level": "1", "texts": texts, **verdict.to_json()})
    settings = RunSettings(llm=LLMSettings(model=model), texts=texts).to_json()
    folder.mkdir(parents=True)
    (folder / "run.json").write_text(json.dumps({"settings": settings, "summary": {}, "tasks": tasks}))


def test_report_puts_paper_and_open_rates_side_by_side(tmp_path: Path) -> None:
    _run(tmp_path / "runs" / "a-paper", "m", "paper", [(True, True), (False, True), (False, False), (False, False)])
    _run(tmp_path / "runs" / "a-open", "m", "open", [(False, True), (False, True), (False, True), (False, False)])
    _run(tmp_path / "runs" / "b-paper", "n", "paper", [(True, True)])
    runs = load_runs([tmp_path / "runs"])
    rows = {r["model"]: r for r in texts_table(runs)}
    assert (rows["m"]["paper"].passed, rows["m"]["paper"].n) == (1, 4)
    assert (rows["m"]["paper_behaviour"].passed, rows["m"]["open"].passed, rows["m"]["open"].n) == (2, 3, 4)
    assert rows["m"]["points"] == pytest.approx(25.0)
    assert rows["n"]["open"].n == 0 and rows["n"]["points"] is None
    assert texts_table([r for r in runs if r.texts == "paper"]) == []  # no open run: no table
    build_report([tmp_path / "runs"], tmp_path / "report")
    markdown = (tmp_path / "report" / "report.md").read_text()
    section = markdown.split("## Paper and open texts side by side", 1)[1].split("\n## ", 1)[0]
    assert "| m T=0 think=False CI1/MBS1 | 25.0 " in section and "| +25.0 |" in section
    table2 = markdown.split("## Success per stage", 1)[1].split("\n## ", 1)[0]
    assert "texts=open" in table2  # the open run's own row, never pooled with the paper run


def test_paper_and_open_ground_truths_share_a_reference_store_entry() -> None:
    """The ground truth is one program whatever text describes it: only its header comment differs,
    and the store's key leaves that out; another seed is another entry."""
    from meceng.pipeline.store import reference_key

    model = default_registry().get(PENDULUM)
    paper, open_ = model.instance(1), model.instance(1, texts="open")
    assert paper.reference_program != open_.reference_program
    limits = ExecutionLimits()
    key = reference_key(paper.reference_program, paper.sim.block(), limits)
    assert key == reference_key(open_.reference_program, open_.sim.block(), limits)
    assert key != reference_key(model.instance(2).reference_program, paper.sim.block(), limits)
