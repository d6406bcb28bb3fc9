"""The run folder: journal.jsonl as tasks finish, programs/, parts/, settings.json and run.json.

Everything a run writes goes through here, so the folder's layout is described in one place
(docs/running.md, "A run's folder") and read back by ``--resume``, ``rescore``, ``report`` and ``view``.
"""

from __future__ import annotations

import contextvars
import datetime as dt
import json
import logging
import os
import platform
import re
import secrets
import threading
from pathlib import Path
from typing import Any

import structlog

from meceng.eval.aggregate import summarize
from meceng.jsonl import read_jsonl
from meceng.tasks.base import TaskInstance, program_header


def record_key(record: dict[str, Any]) -> str:
    """The key of the instance a record belongs to (a part drawn for an assembly names it)."""
    own = f"{record['slug']}@{record['seed']}" + (f"~{record['repair']['id']}" if record.get("repair") else "")
    return f"{record['origin']}/{own}" if record.get("origin") else own


def safe_name(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", text).strip("-") or "run"


def write_atomic(path: Path, text: str) -> None:
    """Write ``path`` whole or not at all. The temporary file's name is the writer's own: two
    writers of one path (grading-pool processes writing the reference file of one instance for two
    of its repair drafts) must not rename each other's half-written file."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp")
    try:
        tmp.write_text(text)
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)


def versions() -> dict[str, str]:
    """Package versions from their metadata (importing NGSolve here would cost a third of a second)."""
    from importlib.metadata import PackageNotFoundError, version

    out = {"python": platform.python_version(), "platform": platform.platform()}
    for package in ("meceng", "exudyn", "ngsolve", "netgen-mesher", "numpy", "scipy", "networkx", "aiohttp",
                    "pymeshlab"):
        try:
            out[package] = version(package)
        except PackageNotFoundError:
            out[package] = "not installed"
    return out


def gpu_telemetry() -> list[dict[str, str]]:
    """nvidia-smi readings where a GPU exists; empty elsewhere."""
    import shutil
    import subprocess

    if shutil.which("nvidia-smi") is None:
        return []
    try:
        out = subprocess.run(
            ["nvidia-smi", "--query-gpu=name,memory.total,memory.used,utilization.gpu,driver_version",
             "--format=csv,noheader"], capture_output=True, text=True, timeout=10, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return []
    keys = ("name", "memory_total", "memory_used", "utilization", "driver")
    return [dict(zip(keys, (p.strip() for p in line.split(",")), strict=False)) for line in out.splitlines()]


def save_programs(run_dir: Path, instance: TaskInstance, code: str | None) -> dict[str, str]:
    """Both programs of a task as files with a header (the description wrapped: ~4 ms a task, so
    the flow runs this in the grading pool). Returns their paths relative to ``run_dir``."""
    folder = run_dir / "programs" / instance.slug
    folder.mkdir(parents=True, exist_ok=True)
    stem = f"seed{instance.seed}" + (f"_for_{safe_name(instance.origin)}" if instance.origin else "")
    if instance.draft is not None:  # a repair task: each draft of the instance has its own answer
        stem += f"_draft_{safe_name(instance.draft.id)}"
    reference = folder / f"{stem}_reference.py"
    write_atomic(reference, instance.reference_program)
    files = {"reference": str(reference.relative_to(run_dir))}
    if code is not None:
        generated = folder / f"{stem}_generated.py"
        header = program_header(f"generated program: {instance.task_id} {instance.name}, seed {instance.seed}",
                                instance.description)
        write_atomic(generated, f"{header}\n{code}")
        files["generated"] = str(generated.relative_to(run_dir))
    return files


class RunWriter:
    """The run directory: journal.jsonl as tasks finish, programs/, and run.json at the end."""

    def __init__(self, run_dir: Path) -> None:
        self.run_dir = run_dir
        (run_dir / "programs").mkdir(parents=True, exist_ok=True)
        self.journal_path = run_dir / "journal.jsonl"
        self.finished = read_jsonl(self.journal_path)  # also cuts a line half-written by a kill
        self._journal = open(self.journal_path, "a", encoding="utf-8")  # noqa: SIM115 - kept open for the run
        self._lock = threading.Lock()

    def part_path(self, instance: TaskInstance) -> Path:
        """Where a passing part's reduced FEM model is kept (for its assembly)."""
        folder = self.run_dir / "parts"
        folder.mkdir(parents=True, exist_ok=True)
        return folder / f"{safe_name(instance.key.replace('/', '--'))}.npz"

    def append(self, record: dict[str, Any]) -> None:
        """One line per finished task, on disk before this returns (safe from threads)."""
        line = json.dumps(record, default=str) + "\n"
        with self._lock:
            self._journal.write(line)
            self._journal.flush()
            os.fsync(self._journal.fileno())

    def finish(self, settings_json: dict[str, Any], records: list[dict[str, Any]], started: float, wall: float,
               extra: dict[str, Any] | None = None) -> Path:
        """Write run.json: the summary of ``records`` and, in their order, each one's full record as
        the journal holds it. ``records`` may be slim (see ``slim_record``): the full ones are copied
        line by line from the journal rather than held in memory for the whole run."""
        self._journal.close()
        head = {
            **(extra or {}),
            "settings": settings_json,
            "versions": versions(),
            "gpu": gpu_telemetry(),
            "started": dt.datetime.fromtimestamp(started, dt.UTC).isoformat(),
            "wall_time_s": wall,
            "summary": summarize(records),
        }
        lines = self._journal_lines({record_key(r) for r in records})
        path = self.run_dir / "run.json"
        tmp = path.with_name(path.name + ".tmp")
        with tmp.open("w", encoding="utf-8") as out:
            out.write(json.dumps(head, indent=1, default=str)[:-2] + ',\n "tasks": [\n')
            out.write(",\n".join(lines[record_key(r)] for r in records))
            out.write("\n ]\n}\n")
        os.replace(tmp, path)
        return path

    def _journal_lines(self, keys: set[str]) -> dict[str, str]:
        """The last journal line of each key (a task done again after a resume wins)."""
        latest: dict[str, str] = {}
        with self.journal_path.open(encoding="utf-8") as journal:
            for line in journal:
                line = line.rstrip("\n")
                try:
                    key = record_key(json.loads(line))
                except (ValueError, KeyError):
                    continue
                if key in keys:
                    latest[key] = line
        return latest


#: what the summary reads of an execution (eval/limits.py): how it ended and how long it took
_EXECUTION_SUMMARY_KEYS = ("stage", "error_kind", "cpu_s", "wall_s", "wall_time")
#: what the summary reads of an agent's block; the transcript and programs stay in the journal
_AGENT_SUMMARY_KEYS = ("first_overall", "first_failure", "rounds", "tool_calls", "completion_tokens",
                       "prompt_tokens", "stop_reason")


def slim_record(record: dict[str, Any]) -> dict[str, Any]:
    """What a run keeps in memory of a finished task: enough for the summary and the record's key;
    prompts, answers, programs, executions and transcripts are in the journal already."""
    slim = {k: v for k, v in record.items() if k not in (
        "description", "params", "selection", "generation", "execution", "reference_execution", "differences",
        "agent", "traceback", "part")}
    for step in ("selection", "generation"):
        if step in record:
            slim[step] = {"meta": {k: v for k, v in record[step].get("meta", {}).items() if k != "thinking"}}
    if "agent" in record:
        slim["agent"] = {k: record["agent"].get(k) for k in _AGENT_SUMMARY_KEYS}
    for key in ("execution", "reference_execution"):  # the summary counts the runs that reached a limit
        if isinstance(record.get(key), dict):
            slim[key] = {k: record[key].get(k) for k in _EXECUTION_SUMMARY_KEYS if k in record[key]}
    if "consensus" in record:  # the groups and every sample's verdicts, without programs and words
        block = record["consensus"]
        slim["consensus"] = {**{k: v for k, v in block.items() if k not in ("samples", "agreements")},
                             "samples": [{k: v for k, v in s.items() if k not in ("code", "behaviour_detail")}
                                         for s in block.get("samples", [])]}
    return slim


_RUN_LOG: contextvars.ContextVar[Path | None] = contextvars.ContextVar("meceng_run_log", default=None)


class _ThisRun(logging.Filter):
    """Lets through only the events of one run: runs of a sweep share the process and the logger,
    and each task (and thread) a run starts inherits the run's context."""

    def __init__(self, path: Path) -> None:
        super().__init__()
        self.path = path

    def filter(self, record: logging.LogRecord) -> bool:
        return _RUN_LOG.get() == self.path


def attach_run_log(path: Path) -> logging.Handler:
    """JSON lines of this run's log events into the run folder, for as long as the run lasts.
    Called from the run's own task, so that events of concurrent runs go to their own folders."""
    _RUN_LOG.set(path)
    handler = logging.FileHandler(path)
    handler.addFilter(_ThisRun(path))
    handler.setFormatter(structlog.stdlib.ProcessorFormatter(
        processor=structlog.processors.JSONRenderer(),
        foreign_pre_chain=[structlog.processors.add_log_level, structlog.processors.TimeStamper(fmt="iso")]))
    logger = logging.getLogger("meceng")
    logger.addHandler(handler)
    if logger.level == logging.NOTSET or logger.level > logging.INFO:
        logger.setLevel(logging.INFO)
    return handler
