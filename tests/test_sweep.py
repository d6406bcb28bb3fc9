from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from meceng.sweep import GridPoint, ModelSpec, SweepSpec, grid_points, load_spec

ROOT = Path(__file__).resolve().parents[1]


def sweep(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(ROOT / "scripts" / "sweep.py"), *args], capture_output=True,
                          text=True, timeout=600)


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


def test_specs_load_and_token_limits_follow_the_paper() -> None:
    for path in (ROOT / "sweeps").glob("*.toml"):
        assert load_spec(path).models
    paper = load_spec(ROOT / "sweeps" / "paper.toml")
    assert len(grid_points(paper)) == len(paper.models) * 3 * 2 * 6 * 4
    plain = GridPoint(ModelSpec("a"), 0.0, False, "CI1", "MBS1")
    reasoning = GridPoint(ModelSpec("b", reasons_anyway=True), 0.0, False, "CI1", "MBS1")
    thinking = GridPoint(ModelSpec("c"), 0.0, True, "CI1", "MBS1")
    assert plain.token_limits() == (4096, 2048)
    assert reasoning.token_limits() == (6144, 3072)
    assert thinking.token_limits() == (15360, 7680)
    assert plain.token_limits(("3a", "3b")) == (6144, 2048)
    assert plain.llm(levels=("3b",)).num_ctx == 6144
    spec = SweepSpec(models=(ModelSpec("m:1b"),), variations=3)
    assert plain.name(spec) != thinking.name(spec)
