from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from meceng.llm.types import LLMSettings
from meceng.sweeps.shard import Shard, split
from meceng.sweeps.spec import GridPoint, ModelSpec, load_spec, plan, point_workload, study_points, unique_points

ROOT = Path(__file__).resolve().parents[1]
PAPER = ROOT / "sweeps" / "paper.toml"


def sweep(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    env = {**{k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}, "COLUMNS": "200", **(env or {})}
    # a wide terminal: one table row per line
    return subprocess.run([sys.executable, str(ROOT / "scripts" / "sweep.py"), *args], capture_output=True,
                          text=True, timeout=600, env=env)


def test_no_server_gives_one_line_hint_and_fails(tmp_path: Path) -> None:
    proc = sweep("--host", "http://127.0.0.1:9", "--out", str(tmp_path))
    assert proc.returncode != 0
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "--model gold" in lines[0] and "127.0.0.1:9" in lines[0]


def test_rerun_of_a_finished_sweep_does_no_work(tmp_path: Path) -> None:
    args = ("--model", "gold", "--only", "3", "--variations", "1", "--out", str(tmp_path), "--no-progress")
    first = sweep(*args)
    assert first.returncode == 0, first.stderr
    (run_json,) = tmp_path.glob("*/run.json")
    stamp = run_json.stat().st_mtime_ns
    second = sweep(*args)
    assert second.returncode == 0 and "skipped" in second.stdout
    assert run_json.stat().st_mtime_ns == stamp
    assert json.loads(second.stdout[second.stdout.index("["):])[0]["skipped"] is True


def test_token_limits_follow_the_paper() -> None:
    plain = GridPoint(ModelSpec("a"), 0.0, False, "CI1", "MBS1")
    reasoning = GridPoint(ModelSpec("b", reasons_anyway=True), 0.0, False, "CI1", "MBS1")
    thinking = GridPoint(ModelSpec("c"), 0.0, True, "CI1", "MBS1")
    assert plain.token_limits() == (4096, 2048)
    assert reasoning.token_limits() == (6144, 3072)
    assert thinking.token_limits() == (15360, 7680)
    flexible = GridPoint(ModelSpec("a"), 0.0, False, "CI1", "MBS1", levels=("3a", "3b"))
    assert flexible.token_limits() == (6144, 2048) and flexible.llm().num_ctx == 6144
    assert plain.name != thinking.name


def test_paper_spec_is_the_papers_design() -> None:
    spec = load_spec(PAPER)
    studies = {s.name: s for s in spec.studies}
    assert list(studies) == ["main", "temperature", "temperature-thinking", "thinking", "ci", "mbs", "level3"]
    assert len(studies["main"].models) == 34  # 32 open-weight and two hosted models (Table 12)
    assert studies["main"].temperatures == (0.0,) and studies["main"].thinks == (False,)
    assert len(studies["temperature"].temperatures) == 13  # 0, 0.05, 0.1 ... 1.0 and the default
    assert len(studies["ci"].select_templates) == 6 and len(studies["mbs"].code_templates) == 4
    hosted = {p.model.name: p for p in study_points(studies["main"]) if p.model.backend != "ollama"}
    assert {p.model.backend for p in hosted.values()} == {"anthropic", "openai"}
    assert all(p.llm().api_defaults and "_Tdefault_" in p.name for p in hosted.values())
    think = {p.model.name: p.think for p in study_points(studies["thinking"])}
    assert think["gpt-oss:20b"] == "medium" and think["gemma4:31b"] is True
    assert {p.think for p in study_points(studies["main"]) if p.model.name.startswith("gpt-oss")} == {"low"}
    # level 3: 12 flexible MBSs x 20 = 240 assemblies needing 440 parts (section 4.2)
    (level3,) = {point_workload(p) for p in study_points(studies["level3"])}
    assert level3 == (240 + 440, 2 * (240 + 440))


def test_shared_grid_points_run_once() -> None:
    planned = plan(load_spec(PAPER))
    names = [run.point.name for run in planned]
    points = unique_points(planned)
    assert len(points) == len(set(names)) < len(names)
    shared = [run for run in planned if run.point.name == "gemma4-31b_T0_think-False_CI1_MBS1_L1-2_v20_s0"]
    assert [(r.study, r.shared_with) for r in shared] == [
        ("main", None), ("temperature", "main"), ("ci", "main"), ("mbs", "main")]


def test_spec_errors_are_named(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('[[models]]\nname = "a"\n[[studies]]\nname = "s"\nmodels = ["b"]\n')
    with pytest.raises(ValueError, match="not in"):
        load_spec(bad)
    bad.write_text('[[models]]\nname = "a"\n[[studies]]\nname = "s"\ngird.temperature = [0]\n')
    with pytest.raises(ValueError, match="gird"):
        load_spec(bad)
    bad.write_text('[[models]]\nname = "a"\nprice = 3\n')
    with pytest.raises(ValueError, match="price"):
        load_spec(bad)


def test_default_sampling_sends_no_temperature_or_seed() -> None:
    assert LLMSettings(temperature=0.3, seed=7).options()["temperature"] == 0.3
    options = LLMSettings(temperature=0.3, seed=7, api_defaults=True).options()
    assert "temperature" not in options and "seed" not in options and options["num_ctx"] == 4096


def test_vision_in_a_model_entry_reaches_the_runs_settings(tmp_path: Path) -> None:
    spec = tmp_path / "vision.toml"
    spec.write_text('[[models]]\nname = "claude-x"\nbackend = "anthropic"\nvision = true\n'
                    '[[models]]\nname = "qwen3:8b"\n')
    (study,) = load_spec(spec).studies
    seeing, blind = study_points(study)
    assert seeing.model.vision and seeing.llm().vision is True and seeing.name.endswith("_vision")
    assert not blind.model.vision and blind.llm().vision is False
    assert blind.name == "qwen3-8b_T0_think-False_CI1_MBS1_L1-2_v20_s0"  # as before the setting existed


def test_sweep_vision_flag_with_model(tmp_path: Path) -> None:
    proc = sweep("--model", "qwen3-vl:8b", "--vision", "--only", "3", "--variations", "1", "--dry-run",
                 "--out", str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    assert "qwen3-vl-8b_T0_think-False_CI1_MBS1_L1-2_v1_s0_only-3_vision" in proc.stdout


def test_dry_run_prints_the_plan_and_starts_nothing(tmp_path: Path) -> None:
    proc = sweep("--spec", str(PAPER), "--dry-run", "--out", str(tmp_path / "runs"))
    assert proc.returncode == 0, proc.stderr
    total = next(line for line in proc.stdout.splitlines() if "total (each run once)" in line)
    cells = [c.strip() for c in total.split("│") if c.strip()]
    assert cells[1:] == ["34", "188", "171", "168,440", "336,880"]
    assert "shared with main" in proc.stdout and not (tmp_path / "runs").exists()
    one = sweep("--spec", str(PAPER), "--dry-run", "--study", "level3", "--out", str(tmp_path / "runs"))
    assert one.returncode == 0 and "level3" in one.stdout and "temperature" not in one.stdout


def test_unknown_study_is_a_usage_error(tmp_path: Path) -> None:
    proc = sweep("--spec", str(PAPER), "--study", "nope", "--dry-run")
    assert proc.returncode == 2 and "no study nope" in proc.stderr and "main" in proc.stderr


def test_two_studies_sharing_a_point_run_it_once(tmp_path: Path) -> None:
    spec = tmp_path / "two.toml"
    spec.write_text(f'out = "{tmp_path / "runs"}"\nvariations = 1\nonly = ["3"]\n'
                    '[[models]]\nname = "gold"\nbackend = "gold"\n'
                    '[[studies]]\nname = "a"\n'
                    '[[studies]]\nname = "b"\ngrid.select_template = ["CI1", "CI2"]\n')
    proc = sweep("--spec", str(spec), "--no-progress")
    assert proc.returncode == 0, proc.stderr
    runs = sorted(p.parent.name for p in (tmp_path / "runs").glob("*/run.json"))
    assert runs == ["gold_T0_think-False_CI1_MBS1_L1-2_v1_s0_only-3", "gold_T0_think-False_CI2_MBS1_L1-2_v1_s0_only-3"]


def test_an_unknown_task_in_only_is_refused(tmp_path: Path) -> None:
    proc = sweep("--model", "gold", "--only", "single_pendulum,no_such_task", "--dry-run", "--out", str(tmp_path))
    assert proc.returncode == 2 and "'no_such_task'" in proc.stderr
    spec = tmp_path / "typo.toml"
    spec.write_text('only = ["newtons_cradel"]\n[[models]]\nname = "gold"\nbackend = "gold"\n')
    with pytest.raises(ValueError, match="did you mean newtons_cradle"):
        load_spec(spec)


def test_shards_of_the_paper_partition_its_runs_balanced_by_requests() -> None:
    points = unique_points(plan(load_spec(PAPER)))
    requests = {p.name: point_workload(p)[1] for p in points}
    for count in (1, 2, 3, 7, 200):
        shards = split(points, count, weight=lambda p: point_workload(p)[1], name=lambda p: p.name)
        names = [p.name for shard in shards for p in shard]
        assert sorted(names) == sorted(requests) and len(names) == len(set(names))
        loads = [sum(requests[p.name] for p in shard) for shard in shards]
        assert max(loads) - min(loads) <= max(requests.values())  # within one run of each other
        assert shards == split(points, count, weight=lambda p: point_workload(p)[1], name=lambda p: p.name)


def test_slurm_array_variables_choose_the_shard_and_dry_run_json_prints_it(tmp_path: Path) -> None:
    assert Shard.from_env({"SLURM_ARRAY_TASK_ID": "3", "SLURM_ARRAY_TASK_COUNT": "3",
                           "SLURM_ARRAY_TASK_MIN": "1"}) == Shard(2, 3)
    assert Shard.from_env({}) is None
    folders = []
    for k in range(3):
        env = {"SLURM_ARRAY_TASK_ID": str(k), "SLURM_ARRAY_TASK_COUNT": "3"}
        proc = sweep("--spec", str(PAPER), "--dry-run", "--json", "--out", str(tmp_path), env=env)
        assert proc.returncode == 0, proc.stderr
        shard = json.loads(proc.stdout)
        assert shard["shard"] == f"{k}/3"
        folders += [run["folder"] for run in shard["runs"]]
        assert all(run["requests"] == 2 * run["tasks"] and run["settings"]["llm"]["model"] == run["model"]
                   for run in shard["runs"])
    whole = json.loads(sweep("--spec", str(PAPER), "--dry-run", "--json", "--out", str(tmp_path)).stdout)
    assert sorted(folders) == sorted(run["folder"] for run in whole["runs"]) and len(folders) == 171
    assert sweep("--spec", str(PAPER), "--dry-run", "--shard", "3/3").returncode == 2


def test_a_scripted_model_in_a_sweep_answers_in_process_like_gold() -> None:
    """``--model scripted:p=0.5`` beside an Ollama model: its point runs on the scripted backend
    (no server to probe), the other on the backend asked (it was sent to Ollama and refused offline)."""
    points = [GridPoint(ModelSpec(name=name, backend="ollama"), 0.0, False, "CI1", "MBS1")
              for name in ("scripted:p=0.5", "scripted-same:p=0.3", "gold", "qwen3:8b")]
    assert [p.llm().backend for p in points] == ["scripted", "scripted", "gold", "ollama"]


def test_the_dry_run_counts_each_agents_requests() -> None:
    """Two requests a task for the paper's pipeline; a consensus of K samples makes 2K (each sample
    selects and writes), across models too; a repair draft one (the draft chose its components),
    up to the agent's rounds with tools; the loop a selection and up to its rounds (issue 44)."""
    from dataclasses import replace

    from meceng.pipeline import RunSettings

    base = GridPoint(ModelSpec(name="qwen3:8b"), 0.0, False, "CI1", "MBS1", levels=("1",), only=("single_pendulum",),
                     variations=3)
    tasks, requests = point_workload(base)
    assert (tasks, requests) == (3, 6)
    consensus = replace(base, agent="consensus", samples=4)
    assert point_workload(consensus) == (3, 2 * 4 * 3)
    across = replace(consensus, members=(consensus, replace(consensus, model=ModelSpec(name="gemma3:4b"))))
    assert point_workload(across) == (3, 2 * 4 * 3)
    rounds = RunSettings().max_rounds
    assert point_workload(replace(base, agent="loop")) == (3, 3 * (1 + rounds))
    repair = replace(base, agent="repair", drafts_per_task=2, repair_tools=False)
    assert point_workload(repair) == (6, 6)  # at most: only the drafts that fail are tasks
    assert point_workload(replace(repair, repair_tools=True)) == (6, 6 * rounds)
