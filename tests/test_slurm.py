"""A real single-node Slurm (Debian's slurm-wlm and munge, configured here, started by hand: no
systemd on these machines) runs a small gold sweep as a three-task array through
scripts/slurm/sweep-array.sbatch; its run folders equal those of a one-process sweep."""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from records import normalized

ROOT = Path(__file__).resolve().parents[1]
DAEMONS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue")

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(any(shutil.which(d) is None for d in DAEMONS) or os.geteuid() != 0,
                       reason="needs root and Debian's slurm-wlm and munge (apt-get install slurm-wlm munge)"),
]

SPEC = """variations = 1
only = ["3", "11"]
[[models]]
name = "gold"
backend = "gold"
[[studies]]
name = "prompts"
grid.select_template = ["CI1", "CI2", "CI3", "CI4"]
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def slurm_conf(home: Path, host: str) -> str:
    return f"""ClusterName=meceng
SlurmctldHost={host}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={home}/munge.sock
CredType=cred/munge
StateSaveLocation={home}/state
SlurmdSpoolDir={home}/spool
SlurmctldPidFile={home}/slurmctld.pid
SlurmdPidFile={home}/slurmd.pid
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SlurmctldLogFile={home}/slurmctld.log
SlurmdLogFile={home}/slurmd.log
NodeName={host} CPUs={os.cpu_count() or 1} RealMemory=2000 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES
"""


@pytest.fixture
def slurm(tmp_path: Path) -> Iterator[dict[str, str]]:
    home = tmp_path / "slurm"
    for folder in ("state", "spool"):
        (home / folder).mkdir(parents=True)
    key = home / "munge.key"
    key.write_bytes(os.urandom(1024))
    key.chmod(0o400)
    host = socket.gethostname().split(".")[0]
    (home / "slurm.conf").write_text(slurm_conf(home, host))
    env = {**os.environ, "SLURM_CONF": str(home / "slurm.conf")}
    subprocess.run(["munged", "--force", f"--socket={home}/munge.sock", f"--key-file={key}",
                    f"--log-file={home}/munged.log", f"--pid-file={home}/munged.pid",
                    f"--seed-file={home}/munged.seed"], check=True, timeout=30)
    try:
        subprocess.run(["slurmctld", "-c"], env=env, check=True, timeout=30)
        subprocess.run(["slurmd"], env=env, check=True, timeout=30)
        deadline = time.monotonic() + 60
        while "idle" not in subprocess.run(["sinfo", "-h", "-o", "%T"], env=env, capture_output=True,
                                           text=True).stdout and time.monotonic() < deadline:
            time.sleep(0.5)
        yield env
    finally:
        for name in ("slurmd", "slurmctld", "munged"):  # the daemons this test started, by their pid files
            pid_file = home / f"{name}.pid"
            if pid_file.exists():
                with contextlib.suppress(ProcessLookupError, ValueError):
                    os.kill(int(pid_file.read_text().split()[0]), 15)


def comparable(run_json: Path) -> object:
    run = json.loads(run_json.read_text())
    return normalized({"tasks": run["tasks"], "summary": {k: v for k, v in run["summary"].items() if k != "timing"}},
                      ("time", "timing", "duration", "started", "stderr_tail", "endpoint", "wall", "cpu_s"))


def test_a_gold_sweep_as_a_three_task_array_equals_one_process(tmp_path: Path, slurm: dict[str, str]) -> None:
    spec = tmp_path / "gold.toml"
    spec.write_text(SPEC)
    one = subprocess.run([sys.executable, str(ROOT / "scripts" / "sweep.py"), "--spec", str(spec), "--out",
                          str(tmp_path / "one"), "--no-progress"], capture_output=True, text=True, timeout=600)
    assert one.returncode == 0, one.stderr
    env = {**slurm, "SPEC": str(spec), "OUT": str(tmp_path / "array"), "REPO": str(ROOT),
           "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"}
    submitted = subprocess.run(["sbatch", "--parsable", "--array=0-2", "--cpus-per-task=1", "--mem=500M",
                                f"--output={tmp_path}/job-%A_%a.out", str(ROOT / "scripts" / "slurm" /
                                                                         "sweep-array.sbatch")],
                               env=env, capture_output=True, text=True, timeout=60, cwd=tmp_path)
    assert submitted.returncode == 0, submitted.stderr
    job = submitted.stdout.strip().split(";")[0]
    deadline = time.monotonic() + 900
    while subprocess.run(["squeue", "-h", "-j", job], env=slurm, capture_output=True, text=True).stdout.strip():
        assert time.monotonic() < deadline, "the array did not finish in 15 minutes"
        time.sleep(1)
    outputs = sorted(tmp_path.glob(f"job-{job}_*.out"))
    assert len(outputs) == 3, outputs
    expected = sorted(p.parent.name for p in (tmp_path / "one").glob("*/run.json"))
    got = sorted(p.parent.name for p in (tmp_path / "array").glob("*/run.json"))
    logs = "\n".join(p.read_text()[-2000:] for p in outputs)
    assert got == expected and len(expected) == 4, logs
    for name in expected:
        assert comparable(tmp_path / "array" / name / "run.json") == comparable(tmp_path / "one" / name / "run.json")
    # each folder was run by one array task: the shards split the runs, none ran twice
    shards = [json.loads(p.read_text()[p.read_text().index("["):]) for p in outputs]
    ran = sorted(Path(r["run"]).parent.name for shard in shards for r in shard if "skipped" not in r)
    assert ran == expected
