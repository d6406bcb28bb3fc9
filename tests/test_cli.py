from __future__ import annotations

import json
import os
import subprocess
import sys

from meceng.tasks.registry import default_registry


def meceng(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "meceng.cli", *args], capture_output=True, text=True, timeout=120)


def test_tasks_list_json_by_level() -> None:
    proc = meceng("tasks", "list", "--level", "1", "--json")
    assert proc.returncode == 0
    listed = json.loads(proc.stdout)
    expected = [m for m in default_registry() if m.level == "1"]
    assert [t["slug"] for t in listed] == [m.slug for m in expected]
    assert all(t["level"] == "1" for t in listed)


def test_tasks_show_json_keys_and_determinism() -> None:
    a = json.loads(meceng("tasks", "show", "newtons_cradle", "--seed", "3", "--json").stdout)
    b = json.loads(meceng("tasks", "show", "43", "--seed", "3", "--json").stdout)
    assert a == b
    assert set(a) >= {"id", "slug", "name", "level", "seed", "params", "description", "required_components"}
    assert a["id"] == 43 and a["seed"] == 3


def test_tasks_reference_is_runnable(tmp_path) -> None:
    proc = meceng("tasks", "reference", "single_pendulum", "--seed", "2")
    assert proc.returncode == 0 and "mbs.Assemble()" in proc.stdout
    script = tmp_path / "ref.py"
    script.write_text(proc.stdout)
    run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert list(tmp_path.iterdir()) == [script]  # no solution files written


def test_wrong_arguments_are_clear_errors(tmp_path) -> None:
    proc = meceng("tasks", "show", "no_such_task")
    assert proc.returncode == 2 and "unknown task model" in proc.stderr
    proc = meceng("run", "--levels", "7")
    assert proc.returncode == 2 and "levels" in proc.stderr
    proc = meceng("evaluate", "single_pendulum", "--code", str(tmp_path / "missing.py"))
    assert proc.returncode == 2 and "cannot read" in proc.stderr
    proc = meceng("run", "--variations", "0")
    assert proc.returncode == 2


def test_level3_tasks_show_and_evaluate_an_assembly(tmp_path) -> None:
    part = json.loads(meceng("tasks", "show", "flexible_beam_part", "--seed", "1", "--json").stdout)
    assert part["kind"] == "part" and part["part"]["interfaces"] == ["left", "right"]
    assembly = json.loads(meceng("tasks", "show", "cantilever_beam", "--seed", "1", "--json").stdout)
    assert assembly["kind"] == "assembly" and list(assembly["parts"]) == ["beam"]
    assert "Part Loading Info" in assembly["description"]
    listed = json.loads(meceng("tasks", "list", "--level", "3a", "--json").stdout)
    assert [t["id"] for t in listed] == list(range(51, 73))
    program = tmp_path / "assembly.py"
    program.write_text(meceng("tasks", "reference", "cantilever_beam", "--seed", "1").stdout)
    graded = meceng("evaluate", "cantilever_beam", "--seed", "1", "--code", str(program), "--json")
    assert graded.returncode == 0, graded.stdout + graded.stderr
    assert json.loads(graded.stdout)["overall"] is True


def test_run_summary_names_lost_tasks_and_how_to_finish_them(tmp_path, capsys) -> None:
    from meceng.cli.commands import print_summary

    lost = {"slug": "bearing_block_part", "seed": 0, "first_failure": "infrastructure", "overall": False,
            "infrastructure_error": "ollama error 404: model 'x' not found"}
    summary = {"counted": 1, "infrastructure_failures": 1,
               "levels": {"3a": {"counted": 0, "infrastructure_failures": 1, "rates": {"overall": None}},
                          "1": {"counted": 1, "infrastructure_failures": 0, "rates": {"overall": 1.0}}}}
    (tmp_path / "run.json").write_text(json.dumps({"summary": summary, "tasks": [
        lost, {"slug": "single_pendulum", "seed": 0, "first_failure": None, "overall": True}]}))
    print_summary(tmp_path / "run.json")
    out = capsys.readouterr().out
    assert "level 3a (0): nothing graded  [1 lost to the server]" in out and "level 1 (1): overall: 100.0%" in out
    assert "bearing_block_part seed 0: ollama error 404" in out
    assert f"meceng run --resume {tmp_path}" in out and "1 task lost to the server" in out


def test_run_summary_says_the_behaviour_rate_and_where_it_differs_from_the_paper(tmp_path, capsys) -> None:
    from meceng.cli.commands import print_summary

    behaviour = {"graded": 3, "passed": 2, "rate": 2 / 3, "both_pass": 1, "both_fail": 1, "paper_only": 0,
                 "behaviour_only": 1, "disagreements": []}
    summary = {"counted": 3, "infrastructure_failures": 0, "behaviour": behaviour,
               "levels": {"1": {"counted": 3, "infrastructure_failures": 0, "rates": {"overall": 1 / 3}}}}
    (tmp_path / "run.json").write_text(json.dumps({"summary": summary, "tasks": []}))
    print_summary(tmp_path / "run.json")
    out = capsys.readouterr().out
    assert "behaviour (levels 1, 2, 3b): 2/3 passed (66.7%); the paper's verdict differs on 1" in out


def test_resume_on_another_server(tmp_path) -> None:
    """--resume keeps everything a run measures; --host says where the server is now."""
    from meceng.cli import build_parser
    from meceng.cli.arguments import llm_settings, resumed_settings, run_settings

    parser = build_parser()
    first = parser.parse_args(["run", "--model", "m:1b", "--host", "http://127.0.0.1:1", "--temperature", "0.3",
                               "--out", str(tmp_path), "--name", "r"])
    (tmp_path / "r").mkdir()
    (tmp_path / "r" / "settings.json").write_text(json.dumps(run_settings(first, llm_settings(first)).to_json()))
    same = resumed_settings(parser.parse_args(["run", "--resume", str(tmp_path / "r")]))
    moved = resumed_settings(parser.parse_args(["run", "--resume", str(tmp_path / "r"), "--host", "http://127.0.0.1:2"]))
    assert same.llm.hosts == ("http://127.0.0.1:1",) and moved.llm.hosts == ("http://127.0.0.1:2",)
    assert moved.llm.temperature == 0.3 and moved.llm.model == "m:1b" and moved.resume


def test_vision_is_a_run_setting_that_resume_keeps(tmp_path) -> None:
    """--vision goes into the LLM settings, settings.json and back through --resume; a run folder
    from before the setting existed resumes without it."""
    from meceng.cli import build_parser
    from meceng.cli.arguments import llm_settings, resumed_settings, run_settings

    parser = build_parser()
    assert llm_settings(parser.parse_args(["run", "--model", "m:1b"])).vision is False
    args = parser.parse_args(["run", "--model", "m:1b", "--vision", "--agent", "loop", "--out", str(tmp_path)])
    written = run_settings(args, llm_settings(args)).to_json()
    assert written["llm"]["vision"] is True
    for name, saved in (("seeing", written), ("older", {**written, "llm": {
            k: v for k, v in written["llm"].items() if k != "vision"}})):
        (tmp_path / name).mkdir()
        (tmp_path / name / "settings.json").write_text(json.dumps(saved))
    assert resumed_settings(parser.parse_args(["run", "--resume", str(tmp_path / "seeing")])).llm.vision is True
    assert resumed_settings(parser.parse_args(["run", "--resume", str(tmp_path / "older")])).llm.vision is False


def test_gold_run_with_vision_records_it_and_ignores_it(tmp_path) -> None:
    proc = meceng("run", "--model", "gold", "--vision", "--only", "3", "--variations", "1", "--out", str(tmp_path),
                  "--name", "g", "--no-progress")
    assert proc.returncode == 0, proc.stderr
    run = json.loads((tmp_path / "g" / "run.json").read_text())
    assert run["settings"]["llm"]["vision"] is True and run["summary"]["rates"]["overall"] == 1.0
    assert json.loads((tmp_path / "g" / "settings.json").read_text())["llm"]["vision"] is True


def test_a_temperature_the_api_will_not_get_is_refused(tmp_path) -> None:
    """--temperature with --api-defaults or Anthropic would be dropped silently: a clear error instead."""
    env = {**os.environ, "ANTHROPIC_API_KEY": "k", "OPENAI_API_KEY": "k"}
    for extra, said in ((["--backend", "anthropic"], "takes no sampling parameters"),
                        (["--backend", "openai", "--api-defaults"], "--api-defaults sends no temperature")):
        proc = subprocess.run([sys.executable, "-m", "meceng", "run", "--model", "x", *extra, "--temperature", "0.7",
                               "--only", "1", "--out", str(tmp_path / "runs")], capture_output=True, text=True,
                              timeout=120, env=env)
        assert proc.returncode == 2 and said in proc.stderr and "--temperature 0.7" in proc.stderr
    assert not (tmp_path / "runs").exists()


def test_an_unknown_task_in_only_is_refused_and_nothing_runs(tmp_path) -> None:
    proc = meceng("run", "--model", "gold", "--only", "single_pendulum,single_pendulm", "--out", str(tmp_path))
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert "'single_pendulm'" in proc.stderr and "did you mean single_pendulum" in proc.stderr
    assert list(tmp_path.iterdir()) == []  # no run folder: nothing started
    proc = meceng("run", "--model", "gold", "--only", "999", "--out", str(tmp_path))
    assert proc.returncode == 2 and "'999'" in proc.stderr
    proc = meceng("evaluate", "newtons_cradel", "--code", str(tmp_path / "x.py"))
    assert proc.returncode == 2 and "did you mean newtons_cradle" in proc.stderr
    proc = meceng("tasks", "prompt", "newtons_cradel")
    assert proc.returncode == 2 and "did you mean newtons_cradle" in proc.stderr


def test_registry_refuses_unknown_keys_with_close_matches() -> None:
    import pytest

    from meceng.tasks.registry import UnknownTaskError

    registry = default_registry()
    with pytest.raises(UnknownTaskError) as caught:
        registry.select(["1", "2"], ["single_pendulum", "no_such_task", "doubel_pendulum"])
    assert caught.value.unknown == ["no_such_task", "doubel_pendulum"]
    assert caught.value.suggestions["doubel_pendulum"][0] == "double_pendulum"
    assert [m.slug for m in registry.select(None, ["single_pendulum", "43"])] == ["single_pendulum", "newtons_cradle"]
    assert isinstance(caught.value, ValueError) and isinstance(caught.value, KeyError)


def test_tasks_prompt_prints_what_the_pipeline_sends() -> None:
    from meceng.agents.prompts import code_prompt, select_prompt
    from meceng.catalog.catalogs import rigid_catalog

    instance = default_registry().get("newtons_cradle").instance(2)
    prompts = json.loads(meceng("tasks", "prompt", "newtons_cradle", "--seed", "2", "--select-template", "CI3",
                                "--code-template", "MBS2", "--json").stdout)
    catalog = rigid_catalog()
    assert [(p["stage"], p["template"]) for p in prompts] == [("select", "CI3"), ("code", "MBS2")]
    assert prompts[0]["text"] == select_prompt("CI3", instance.description, catalog.menu())
    assert prompts[1]["text"] == code_prompt("MBS2", instance.description,
                                             catalog.context(instance.required_components))
    loop = json.loads(meceng("tasks", "prompt", "newtons_cradle", "--seed", "2", "--agent", "loop", "--json").stdout)
    assert loop[1]["text"].startswith(code_prompt("MBS1", instance.description,
                                                  catalog.context(instance.required_components)))
    assert "simulate(code)" in loop[1]["text"]
    text = meceng("tasks", "prompt", "newtons_cradle", "--seed", "2", "--select-template", "CI3",
                  "--code-template", "MBS2").stdout
    assert prompts[0]["text"].rstrip("\n") in text and prompts[1]["text"].rstrip("\n") in text


def test_tasks_prompt_of_an_assembly_gives_its_parts_first_with_the_part_template() -> None:
    prompts = json.loads(meceng("tasks", "prompt", "rotor_in_two_bearing_blocks_with_pedestal", "--seed", "1",
                                "--json").stdout)
    kinds = [(p["kind"], p["stage"], p["template"]) for p in prompts]
    # two distinct parts (the block used twice is prompted once), then the assembly
    assert kinds == [("part", "select", "PART1"), ("part", "code", "PART1")] * 2 + [
        ("assembly", "select", "CI1"), ("assembly", "code", "MBS1")]
    assert "### InterfaceJoint" in prompts[-1]["text"] and "Part Loading Info" in prompts[-1]["text"]
