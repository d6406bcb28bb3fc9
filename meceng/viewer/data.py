"""The viewer's inputs and its index data: run folders read back, and one compact row per task
record for the index page's table.

The rows go into ``data.js`` as ``window.MECENG_DATA = {...}``: a page opened from ``file://``
may not fetch() a JSON file, but it may load a script. Rows are arrays, not objects, so 20 000
records stay a few MB and parse in tens of milliseconds.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from meceng.eval.chain import BEHAVIOUR_STAGE, RIGID_STAGES
from meceng.eval.parts import PART_STAGES
from meceng.eval.rates import run_model
from meceng.jsonl import read_jsonl
from meceng.pipeline.rundir import record_key
from meceng.pipeline.traces import safe_key

#: every stage name in display order (parts, assembly gates, the rigid chain); a record fills its own
STAGE_ORDER = (*PART_STAGES, "parts_overall", "mbs_started", *RIGID_STAGES, BEHAVIOUR_STAGE)
STAGE_LABELS = {"choose_part_components": "pcomp", "interface_name_match": "iface", "material_match": "mat",
                "mass_match": "mass", "mesh_match": "mesh", "eigenfrequencies_match": "eig",
                "parts_overall": "parts", "mbs_started": "mbs", "choose_components": "comp",
                "finished_assemble": "asm", "topology_match": "topo", "graph_content_match": "graph",
                "solver_success": "solver", "solution_match": "sol", BEHAVIOUR_STAGE: "behav"}
#: the index row's fields, in order (the page script reads them by these names)
ROW_FIELDS = ("run", "level", "slug", "seed", "stages", "failure", "categories", "tokens", "llm_s", "eval_s",
              "href", "status", "origin", "detail", "id", "name", "rounds", "draft")


@dataclass
class ViewRun:
    """One run folder as the viewer reads it: run.json, or the journal of a run still going."""

    path: Path
    settings: dict[str, Any]
    tasks: list[dict[str, Any]]

    @property
    def model(self) -> str:
        return run_model(self.settings)

    @property
    def texts(self) -> str:
        """The run's task texts: "paper" (runs before issue 36 say none) or "open"."""
        return str(self.settings.get("pipeline", {}).get("texts", "paper"))

    @property
    def label(self) -> str:
        llm, prompt = self.settings.get("llm", {}), self.settings.get("prompt", {})
        agent = self.settings.get("pipeline", {}).get("agent", "pipeline")
        return (f"{self.model} T={llm.get('temperature', '?')} think={llm.get('think', '?')} "
                f"{prompt.get('select_template', '?')}/{prompt.get('code_template', '?')}"
                + (f" agent={agent}" if agent != "pipeline" else "")
                + (f" texts={self.texts}" if self.texts != "paper" else ""))


def find_runs(paths: list[Path]) -> list[Path]:
    """Run folders among ``paths``: a run folder, its run.json, or a folder of run folders."""
    found: list[Path] = []
    for path in paths:
        if path.is_file():
            found.append(path.parent)
        elif (path / "run.json").exists() or (path / "journal.jsonl").exists():
            found.append(path)
        elif path.is_dir():
            found += sorted(p.parent for p in path.glob("*/run.json"))
            found += sorted(p.parent for p in path.glob("*/journal.jsonl") if not (p.parent / "run.json").exists())
        else:
            raise FileNotFoundError(f"{path}: no run there")
    if not found:
        raise FileNotFoundError("no run found in " + ", ".join(map(str, paths)))
    return list(dict.fromkeys(found))


def load_run(folder: Path) -> ViewRun:
    """run.json when the run finished; a running or killed run's journal and settings otherwise."""
    if (folder / "run.json").exists():
        data = json.loads((folder / "run.json").read_text())
        return ViewRun(folder, data.get("settings", {}), data.get("tasks", []))
    settings = json.loads((folder / "settings.json").read_text()) if (folder / "settings.json").exists() else {}
    latest: dict[str, dict[str, Any]] = {}
    for record in read_jsonl(folder / "journal.jsonl"):
        latest[record_key(record)] = record  # a task done again after a resume wins
    return ViewRun(folder, settings, list(latest.values()))


def page_path(run_index: int, record: dict[str, Any]) -> str:
    """The record's page, relative to the site's root."""
    return f"tasks/r{run_index}/{safe_key(record_key(record))}.html"


def stage_columns(runs: list[ViewRun]) -> list[str]:
    present = {s["name"] for run in runs for t in run.tasks for s in t.get("stages", [])}
    return [s for s in STAGE_ORDER if s in present] + sorted(present - set(STAGE_ORDER))


def _failure_detail(record: dict[str, Any]) -> str:
    if record.get("first_failure") == "infrastructure":
        return str(record.get("infrastructure_error") or "")[:200]
    failed = next((s for s in record.get("stages", []) if s.get("passed") is False and s.get("required", True)), None)
    return "" if failed is None else str(failed.get("detail", ""))[:200]


def index_row(run_index: int, record: dict[str, Any], columns: dict[str, int]) -> list[Any]:
    """The record as the index table shows it (fields in ``ROW_FIELDS`` order)."""
    codes = ["."] * len(columns)
    for stage in record.get("stages", []):
        if stage["name"] in columns:
            # R: recorded but not required (an open text's writing stages, eval.chain.by_behaviour)
            codes[columns[stage["name"]]] = ("R" if stage.get("required", True) is False
                                             else {True: "P", False: "F"}.get(stage.get("passed"), "N"))
    timing, tokens = record.get("timing", {}), record.get("tokens", {})
    infra = record.get("first_failure") == "infrastructure"
    agent = record.get("agent") or {}
    return [run_index, str(record.get("level", "")), record["slug"], record["seed"], "".join(codes),
            record.get("first_failure") or "", "|".join(record.get("error_categories", [])),
            int(tokens.get("prompt", 0)) + int(tokens.get("completion", 0)),
            round(float(timing.get("llm_s", 0.0)), 2), round(float(timing.get("evaluation_s", 0.0)), 2),
            page_path(run_index, record), 2 if infra else int(bool(record.get("overall"))),
            record.get("origin") or "", _failure_detail(record), record.get("id"), record.get("name", ""),
            agent.get("rounds", -1) if agent else -1, _draft(record)]


def _draft(record: dict[str, Any]) -> str:
    """A repair record's draft as the index names it: its fault and label."""
    repair = record.get("repair")
    return f"{repair['id']} ({repair['label']})" if repair else ""


def run_labels(runs: list[ViewRun]) -> list[str]:
    """Each run's label, with its folder's name where two runs would read the same."""
    labels = [run.label for run in runs]
    return [label if labels.count(label) == 1 else f"{label} ({run.path.name})" for label, run in zip(labels, runs,
                                                                                                        strict=True)]


def index_data(runs: list[ViewRun]) -> dict[str, Any]:
    stages = stage_columns(runs)
    columns = {name: i for i, name in enumerate(stages)}
    return {
        "fields": list(ROW_FIELDS),
        "runs": [{"label": label, "model": run.model, "path": str(run.path), "texts": run.texts}
                 for label, run in zip(run_labels(runs), runs, strict=True)],
        "stages": stages,
        "stage_labels": [STAGE_LABELS.get(s, s[:6]) for s in stages],
        "rows": [index_row(i, record, columns) for i, run in enumerate(runs) for record in run.tasks],
    }


def data_script(data: dict[str, Any]) -> str:
    """``data.js``: the index data as a global (``</`` escaped so no text can end the script)."""
    text = json.dumps(data, separators=(",", ":"), ensure_ascii=False).replace("</", "<\\/")
    return f"window.MECENG_DATA = {text};\n"
