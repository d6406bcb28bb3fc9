"""The harness self-check: the gold backend must score 100 % on every task model."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from meceng.pipeline import evaluate_program
from meceng.tasks.registry import default_registry

ROOT = Path(__file__).resolve().parents[1]


def _sweep(tmp_path: Path, variations: int, levels: str = "1,2") -> dict:
    proc = subprocess.run(
        [sys.executable, str(ROOT / "scripts" / "sweep.py"), "--model", "gold", "--levels", levels,
         "--variations", str(variations), "--seed", "100", "--out", str(tmp_path), "--name", "gold", "--no-progress"],
        capture_output=True, text=True, timeout=3000,
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return json.loads((tmp_path / "gold" / "run.json").read_text())


@pytest.mark.timeout(1200)
def test_gold_sweep_scores_everything(tmp_path: Path) -> None:
    run = _sweep(tmp_path, variations=1)
    models = default_registry().select(["1", "2"])
    assert len(run["tasks"]) == len(models)
    failures = [(t["slug"], t["first_failure"], t.get("infrastructure_error"))
                for t in run["tasks"] if not t["overall"]]
    assert failures == []
    assert run["summary"]["rates"]["overall"] == 1.0
    assert [t["slug"] for t in run["tasks"] if not t["behaviour"]["passed"]] == []  # behaviour: gold 100 % too
    assert run["summary"]["behaviour"]["rate"] == 1.0
    assert set(run) >= {"settings", "versions", "summary", "tasks"}
    record = run["tasks"][0]
    assert set(record) >= {"slug", "level", "seed", "params", "stages", "overall", "first_failure",
                           "error_categories", "timing", "tokens"}
    generated = tmp_path / "gold" / record["files"]["generated"]
    assert generated.read_text().startswith("# MecEng generated program")


@pytest.mark.slow
def test_gold_sweep_twenty_variations(tmp_path: Path) -> None:
    run = _sweep(tmp_path, variations=20)
    assert run["summary"]["rates"]["overall"] == 1.0
    assert max(t["timing"]["total_s"] for t in run["tasks"]) < 20.0


def _perturbed(program: str, name: str, value: object) -> str:
    changed = value * 1.05 if isinstance(value, float) else value + 1
    return program.replace(f"\n{name} = {value!r}\n", f"\n{name} = {changed!r}\n")


@pytest.mark.parametrize("slug", [m.slug for m in default_registry().select(["1", "2"])])
async def test_perturbed_parameter_is_detected(slug: str) -> None:
    """Every physical parameter, perturbed by 5 %, fails at graph content or solution."""
    instance = default_registry().get(slug).instance(11)
    physical = [k for k, v in instance.params.items() if isinstance(v, float) and v != 0.0]
    assert physical, "task has no physical parameter"
    name = physical[0]
    program = _perturbed(instance.reference_program, name, instance.params[name])
    assert program != instance.reference_program
    verdict, _, _ = await evaluate_program(instance, program)
    assert not verdict.overall
    assert verdict.first_failure in ("graph_content_match", "solution_match", "solver_success"), verdict.first_failure


@pytest.mark.slow
@pytest.mark.timeout(3000)
def test_gold_level3_sweep_scores_every_part_and_assembly(tmp_path: Path) -> None:
    """Levels 3a and 3b with the gold backend: every part and every assembly passes every metric."""
    run = _sweep(tmp_path, variations=1, levels="3a,3b")
    failures = [(t["slug"], t.get("origin"), t["first_failure"], t.get("infrastructure_error"))
                for t in run["tasks"] if not t["overall"]]
    assert failures == []
    assemblies = [t for t in run["tasks"] if t["level"] == "3b"]
    assert all(t["behaviour"]["passed"] for t in assemblies)
    standalone = [t for t in run["tasks"] if t["level"] == "3a" and not t.get("origin")]
    assert len(assemblies) == 12 and len(standalone) == 22
    assert all(t["files"].get("part") for t in run["tasks"] if t["level"] == "3a")
