"""A gold sweep killed with SIGKILL at three points and resumed ends with the same run.json as an
uninterrupted one; no finished task is redone and no LLM call is repeated."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
from records import normalized

ONLY = "1,2,3,4,9,11,12,19,23,29,35,43"


def start(out: Path, name: str, resume: bool = False) -> subprocess.Popen[str]:
    args = ["--resume", str(out / name)] if resume else [
        "--model", "gold", "--only", ONLY, "--variations", "2", "--seed", "5", "--out", str(out), "--name", name]
    return subprocess.Popen([sys.executable, "-m", "meceng.cli", "run", *args, "--no-progress"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def journal_lines(path: Path) -> int:
    return path.read_bytes().count(b"\n") if path.exists() else 0


def comparable(run_json: Path) -> dict[str, Any]:
    run = json.loads(run_json.read_text())
    return normalized({"tasks": run["tasks"], "summary": {k: v for k, v in run["summary"].items() if k != "timing"}})


def test_killed_runs_resume_to_the_same_result(tmp_path: Path) -> None:
    reference = start(tmp_path, "straight")
    assert reference.wait(timeout=600) == 0, reference.stderr.read() if reference.stderr else ""
    expected = comparable(tmp_path / "straight" / "run.json")
    total = len(expected["tasks"])

    journal = tmp_path / "killed" / "journal.jsonl"
    for kill_after in (1, total // 2, total - 1):
        proc = start(tmp_path, "killed", resume=journal.exists())
        deadline = time.monotonic() + 300
        while journal_lines(journal) < kill_after and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.02)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    done_before = journal_lines(journal)
    assert done_before < total or not (tmp_path / "killed" / "run.json").exists()

    final = start(tmp_path, "killed", resume=True)
    assert final.wait(timeout=600) == 0, final.stderr.read() if final.stderr else ""
    run = json.loads((tmp_path / "killed" / "run.json").read_text())
    assert comparable(tmp_path / "killed" / "run.json") == expected
    # every task ran once: the journal holds one line per task, the cache one line per LLM call
    assert journal_lines(journal) == total
    assert journal_lines(tmp_path / "killed" / "responses.jsonl") == 2 * total
    assert run["resumed_tasks"] == done_before
    # the viewer's traces of the tasks done before each kill are still there, one file per record
    traces = sorted(p.name for p in (tmp_path / "killed" / "traces").iterdir())
    assert traces == sorted(Path(t["files"]["traces"]).name for t in run["tasks"]) and len(traces) == total


def test_existing_run_folder_is_not_overwritten(tmp_path: Path) -> None:
    first = start(tmp_path, "once")
    assert first.wait(timeout=600) == 0
    again = start(tmp_path, "once")
    assert again.wait(timeout=600) == 2
    assert "--resume" in (again.stderr.read() if again.stderr else "")


def gold_run(out: Path) -> Path:
    """A gold run of tasks 3 and 11 in ``out / "r"``, made through the command line; its run.json."""
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "run", "--model", "gold", "--only", "3,11",
                           "--variations", "1", "--out", str(out), "--name", "r", "--no-progress"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return out / "r" / "run.json"


def test_rescore_regrades_saved_programs_without_llm(tmp_path: Path) -> None:
    run_json = gold_run(tmp_path)
    run = json.loads(run_json.read_text())
    traces = tmp_path / "r" / run["tasks"][0]["files"]["traces"]
    with np.load(traces) as data:
        assert "cand_t" in data.files and "ref_t" in data.files
    # tamper with a saved program's record: the rescore must grade the code it finds
    record = run["tasks"][0]
    record["generation"]["code"] = record["generation"]["code"].replace("mbs.Assemble()", "raise ValueError('x')")
    for task in run["tasks"]:  # a run made before the behaviour verdict: rescore adds it
        task.pop("behaviour", None)
    run_json.write_text(json.dumps(run))
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "rescore", str(tmp_path / "r")],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    after = json.loads(run_json.read_text())
    assert after["tasks"][0]["overall"] is False and after["tasks"][0]["first_failure"] == "finished_assemble"
    assert after["tasks"][1]["overall"] is True
    assert [t["behaviour"]["passed"] for t in after["tasks"]] == [False, True]
    assert after["summary"]["behaviour"]["graded"] == 2
    assert all(t["evaluator"] for t in after["tasks"]) and "rescored" in after
    assert (tmp_path / "r" / "responses.jsonl").read_text().count("\n") == 4  # no new LLM call
    assert (tmp_path / "r" / "run.previous.json").exists()
    # the plots follow the new grading: the tampered program left no trajectory, the ground truth did
    with np.load(tmp_path / "r" / after["tasks"][0]["files"]["traces"]) as data:
        assert "cand_t" not in data.files and "ref_t" in data.files


def test_rescore_options_give_the_same_verdicts_and_fill_the_store(tmp_path: Path) -> None:
    """Cold interpreters and the fork server grade alike; a store given to rescore is filled with
    the ground truths and used by the next rescore; a wrong option is refused with exit 2."""
    run_json = gold_run(tmp_path)
    run = json.loads(run_json.read_text())
    record = run["tasks"][0]
    record["generation"]["code"] = record["generation"]["code"].replace("mbs.Assemble()", "raise ValueError('x')")
    run_json.write_text(json.dumps(run))
    store = tmp_path / "references"
    verdicts = []
    stored = ["--reference-store", str(store)]
    for options in (["--executor", "subprocess", "--workers", "1"], stored, stored):
        proc = subprocess.run([sys.executable, "-m", "meceng.cli", "rescore", str(tmp_path / "r"), *options],
                              capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr
        tasks = json.loads(run_json.read_text())["tasks"]
        verdicts.append([(t["slug"], t["overall"], t["first_failure"]) for t in tasks])
    assert verdicts[0] == verdicts[1] == verdicts[2]
    assert verdicts[0][0][1] is False and verdicts[0][1][1] is True
    # per task one ground truth and its run with twice the steps (the behaviour verdict's), made once
    assert len(list(store.glob("*/*.pkl"))) == 4
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "rescore", str(tmp_path / "r"), "--executor", "cold"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2 and "--executor" in proc.stderr
    proc = subprocess.run([sys.executable, "-m", "meceng.cli", "rescore", str(tmp_path / "no-such-run")],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2 and "no-such-run does not exist" in proc.stderr
