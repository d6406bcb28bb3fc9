"""``--agent consensus`` across models (``--consensus-models``, a sweep study's ``consensus =
"across"``): sample k is written by model k mod M, the record names each sample's model, samples of
different models that move alike form one group, and a sweep study makes one run, not M."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from fake_ollama import FakeOllama, chat_reply

from meceng.eval.calibration import per_model
from meceng.eval.rates import Rate, run_model
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark

RIGHT, WRONG = "scripted:p=1", "scripted-same:p=0"  # always the ground truth; always the task's first draft


def scripted(model: str) -> LLMSettings:
    return LLMSettings(model=model, backend="scripted", temperature=0.7)


def across(tmp_path: Path, name: str, models: tuple[LLMSettings, ...], **changes: Any) -> RunSettings:
    given: dict[str, Any] = {"only": ("single_mass_oscillator", "single_pendulum"), "agent": "consensus", **changes}
    return RunSettings(llm=models[0], consensus_models=models, samples=3, variations=1, out=tmp_path, run_name=name,
                       progress=False, workers=2, **given)


async def test_samples_alternate_between_models_and_a_group_may_hold_both(tmp_path: Path) -> None:
    path = await run_benchmark(across(tmp_path, "two", (scripted(RIGHT), scripted(WRONG))))
    run = json.loads(path.read_text())
    tasks = {t["slug"]: t for t in run["tasks"]}
    for task in tasks.values():
        block = task["consensus"]
        assert block["models"] == [RIGHT, WRONG]
        # k mod 2: samples 0 and 2 by the right model, sample 1 by the wrong one, each with its own answer
        assert [s["model"] for s in block["samples"]] == [RIGHT, WRONG, RIGHT]
        assert [s["endpoint"] == "scripted: reference" for s in block["samples"]] == [True, False, True]
        assert [s["overall"] for s in block["samples"]] == [True, False, True]
        assert block["samples"][block["chosen"]]["model"] == RIGHT and task["overall"] is True
    # an oscillator with the wrong mass swings at another frequency: the models part, 2 against 1
    assert tasks["single_mass_oscillator"]["consensus"]["groups"] == [[0, 2], [1]]
    # a pendulum of another mass swings alike (the period does not depend on the mass): the wrong
    # model's program joins the right model's group, agreement between different models counts
    pendulum = tasks["single_pendulum"]["consensus"]
    assert "mass" in pendulum["samples"][1]["endpoint"], pendulum["samples"][1]["endpoint"]
    assert pendulum["groups"] == [[0, 1, 2]] and pendulum["confidence"] == 1.0
    settings = json.loads((tmp_path / "two" / "settings.json").read_text())
    assert [m["model"] for m in settings["pipeline"]["consensus_models"]] == [RIGHT, WRONG]
    assert RunSettings.from_json(settings, tmp_path, "two").sample_models == (scripted(RIGHT), scripted(WRONG))
    assert run_model(settings) == f"{RIGHT}+{WRONG}"  # the report's and viewer's name: never pooled with RIGHT's runs
    # the report: each model's samples one at a time, and the answers it wrote
    rows = {r["model"]: r for r in per_model(run["tasks"])}
    assert rows[RIGHT]["paper"] == Rate(4, 4) and rows[WRONG]["paper"] == Rate(0, 2)
    assert rows[RIGHT]["answers"] == Rate(2, 2) and rows[WRONG]["answers"] == Rate(0, 2)


async def test_through_a_server_each_sample_is_asked_of_its_model(tmp_path: Path) -> None:
    """Two model names on one fake Ollama: the server sees each sample's requests under the model
    k mod M names, with the sample's seed; the model that writes the faulty program is outvoted."""
    from test_consensus_apis import SLUG, answers

    select, right, wrong = answers()
    asked: list[tuple[str, int]] = []

    def ollama(body: dict[str, Any]) -> tuple[int, Any, dict[str, str]]:
        prompt = body["messages"][0]["content"]
        if "<components>" in prompt:
            return 200, chat_reply(select), {}
        asked.append((body["model"], body["options"]["seed"]))
        return 200, chat_reply(right if body["model"] == "good" else wrong), {}

    async with FakeOllama(ollama) as lama:
        models = tuple(LLMSettings(model=m, backend="ollama", hosts=(lama.url,), temperature=0.7)
                       for m in ("good", "bad"))
        path = await run_benchmark(across(tmp_path, "served", models, only=(SLUG,), preflight=False))
    record = json.loads(path.read_text())["tasks"][0]
    block = record["consensus"]
    assert sorted(asked) == [("bad", 43), ("good", 42), ("good", 44)]
    assert [s["model"] for s in block["samples"]] == ["good", "bad", "good"]
    assert block["groups"] == [[0, 2], [1]] and record["overall"] is True


def test_several_models_are_a_consensus_run_only(tmp_path: Path) -> None:
    import asyncio

    with pytest.raises(ValueError, match="--agent consensus"):
        asyncio.run(run_benchmark(across(tmp_path, "no", (scripted(RIGHT), scripted(WRONG)), agent="pipeline")))
    assert not (tmp_path / "no").exists()


def test_a_sweep_study_across_models_is_one_run(tmp_path: Path) -> None:
    from meceng.sweeps.spec import load_spec, study_points

    spec = tmp_path / "across.toml"
    spec.write_text('[[models]]\nname = "qwen3:8b"\n[[models]]\nname = "gpt-oss:20b"\nthink_off = "low"\n'
                    '[[studies]]\nname = "across"\nagent = "consensus"\nconsensus = "across"\nsamples = 4\n'
                    '[[studies]]\nname = "each"\nagent = "consensus"\nsamples = 4\n')
    across_study, each = load_spec(spec).studies
    points = study_points(across_study)
    assert len(points) == 1 and len(study_points(each)) == 2
    point = points[0]
    assert point.name.startswith("qwen3-8b-and-gpt-oss-20b_T0.7_") and point.name.endswith("_consensus-across-k4")
    # each model with its own settings: gpt-oss's thinking off is reasoning "low"
    assert [(m.model, m.think) for m in point.llms()] == [("qwen3:8b", False), ("gpt-oss:20b", "low")]
    assert {p.name for p in study_points(each)}.isdisjoint({point.name})
    for bad, why in (('agent = "pipeline"\nconsensus = "across"', "needs agent"),
                     ('agent = "consensus"\nconsensus = "both"', "choose each or across")):
        spec.write_text(f'[[models]]\nname = "a"\n[[models]]\nname = "b"\n[[studies]]\nname = "s"\n{bad}\n')
        with pytest.raises(ValueError, match=why):
            load_spec(spec)


def test_the_viewer_names_each_samples_model() -> None:
    from meceng.viewer.pages import task_page

    samples = [{"index": k, "model": model, "seed": 42 + k, "lost": None, "group": 0, "code": "x = 1\n",
                "endpoint": "e", "ran": True, "overall": True, "first_failure": None, "behaviour_passed": True}
               for k, model in enumerate(("qwen3:8b", "gpt-oss:20b"))]
    block = {"k": 2, "counted": 2, "chosen": 0, "confidence": 1.0, "groups": [[0, 1]], "agreements": [],
             "models": ["qwen3:8b", "gpt-oss:20b"], "samples": samples}
    page = task_page({"slug": "s", "seed": 0, "overall": True, "consensus": block}, run_label="r", root="../",
                     program=None, reference=None, file_links={}, images={}, neighbours=(None, None))
    section = page.split("id='consensus'")[1]
    assert "<th>model</th>" in section and "<td>gpt-oss:20b</td>" in section
    assert "sample k written by model k mod 2" in section


def test_the_command_line_gives_every_model_the_runs_settings_and_a_resume_its_new_server(tmp_path: Path) -> None:
    from meceng.cli import build_parser
    from meceng.cli.arguments import llm_settings, resumed_settings, run_settings

    parser = build_parser()
    args = parser.parse_args(["run", "--agent", "consensus", "--consensus-models", "a:1b, b:2b", "--host",
                              "http://127.0.0.1:1", "--think", "on", "--out", str(tmp_path), "--name", "r"])
    settings = run_settings(args, llm_settings(args))
    assert [(m.model, m.backend, m.hosts, m.think, m.temperature) for m in settings.sample_models] == [
        (name, "ollama", ("http://127.0.0.1:1",), True, 0.7) for name in ("a:1b", "b:2b")]
    assert settings.llm == settings.consensus_models[0]
    (tmp_path / "r").mkdir()
    (tmp_path / "r" / "settings.json").write_text(json.dumps(settings.to_json()))
    moved = resumed_settings(parser.parse_args(["run", "--resume", str(tmp_path / "r"), "--host", "http://127.0.0.1:2"]))
    assert [m.hosts for m in moved.sample_models] == [("http://127.0.0.1:2",)] * 2
    with pytest.raises(SystemExit):  # one model is not a run across models
        parser.parse_args(["run", "--agent", "consensus", "--consensus-models", "a:1b"])


def test_same_fault_models_may_each_repeat_a_fault_of_their_own() -> None:
    from meceng.llm.backend_scripted import ScriptedBackend, ScriptedDraft, parse_scripted

    drafts = {"t@0": (ScriptedDraft("a", "A", "x = 1"), ScriptedDraft("b", "B", "x = 2"))}
    wrong = {d: {ScriptedBackend(f"scripted-same:p=0:d={d}", 42, drafts).answer("t@0", k, "gold")[1]
                 for k in range(20)} for d in (0, 1, 2)}
    assert wrong == {0: {"draft a [A]"}, 1: {"draft b [B]"}, 2: {"draft a [A]"}}  # d mod the task's drafts
    assert parse_scripted("scripted-same:p=0.5") == parse_scripted("scripted-same:p=0.5:d=0")
    with pytest.raises(ValueError, match="scripted-same:p=P"):
        parse_scripted("scripted:p=0.5:d=1")  # a model whose faults are drawn at random has no one fault
