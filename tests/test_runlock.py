"""One process per run folder: a live holder keeps the folder, a dead one's lock is taken over."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from dataclasses import asdict, replace
from pathlib import Path

import pytest

from meceng.pipeline.lock import LOCK_NAME, Holder, RunBusy, RunLock


def write_lock(folder: Path, holder: Holder, age_s: float = 0.0) -> Path:
    path = folder / LOCK_NAME
    path.write_text(json.dumps(asdict(holder)))
    stamp = time.time() - age_s
    os.utime(path, (stamp, stamp))
    return path


def dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_a_live_holder_keeps_the_folder(tmp_path: Path) -> None:
    first = RunLock(tmp_path)
    first.acquire()
    with pytest.raises(RunBusy, match=str(os.getpid())):
        RunLock(tmp_path).acquire()
    first.release()
    second = RunLock(tmp_path)
    second.acquire()  # released: free again
    assert json.loads((tmp_path / LOCK_NAME).read_text())["token"] == second.holder.token


def test_the_lock_of_a_dead_process_is_taken_over(tmp_path: Path) -> None:
    write_lock(tmp_path, replace(Holder.me(), pid=dead_pid(), token="dead"))
    lock = RunLock(tmp_path)
    lock.acquire()
    assert json.loads((tmp_path / LOCK_NAME).read_text())["token"] == lock.holder.token
    assert sorted(p.name for p in tmp_path.iterdir()) == [LOCK_NAME]  # nothing left aside


def test_a_reused_pid_is_not_the_holder(tmp_path: Path) -> None:
    write_lock(tmp_path, replace(Holder.me(), start="1", token="before-reboot-or-reuse"))
    RunLock(tmp_path).acquire()


def test_another_hosts_lock_is_stale_only_without_heartbeat(tmp_path: Path) -> None:
    other = replace(Holder.me(), host="node-elsewhere", token="other")
    write_lock(tmp_path, other, age_s=10)
    with pytest.raises(RunBusy, match="node-elsewhere"):
        RunLock(tmp_path, stale_after_s=60).acquire()
    write_lock(tmp_path, other, age_s=120)
    RunLock(tmp_path, stale_after_s=60).acquire()


def test_a_second_run_on_a_held_folder_is_refused_by_the_cli(tmp_path: Path) -> None:
    (tmp_path / "r").mkdir()
    holder = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        write_lock(tmp_path / "r", replace(Holder.me(), pid=holder.pid,
                                           start=Path(f"/proc/{holder.pid}/stat").read_text().rsplit(")", 1)[1]
                                           .split()[19], token="live"))
        proc = subprocess.run([sys.executable, "-m", "meceng.cli", "run", "--model", "gold", "--only", "3",
                               "--variations", "1", "--out", str(tmp_path), "--name", "r", "--no-progress"],
                              capture_output=True, text=True, timeout=300)
    finally:
        holder.kill()
        holder.wait()
    assert proc.returncode != 0 and "being run by" in proc.stderr
    assert not (tmp_path / "r" / "journal.jsonl").exists()
