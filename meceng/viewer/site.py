"""``meceng view``: a static site over one or more runs, readable from ``file://`` with no server
and nothing fetched from the internet.

Layout of ``out``: ``index.html`` (the table of every record; its script and style under
``static/``, its data in ``data.js``) and ``tasks/r<run>/<key>.html`` (a page per record, with
its PNGs beside it). Pages are written by forked workers, each over a share of the records (the
runs are read once, before the fork); plots are drawn only where a page needs one, and a plot an
earlier build drew from the same traces file is kept (matplotlib costs 0.1-0.3 s a plot).
"""

from __future__ import annotations

import functools
import multiprocessing
import os
import shutil
import time
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from meceng.logs import get_logger
from meceng.pipeline.traces import load_traces, traces_path
from meceng.viewer.data import ViewRun, data_script, find_runs, index_data, load_run, page_path, run_labels
from meceng.viewer.pages import task_page

log = get_logger(__name__)

STATIC_FILES = ("index.html", "viewer.css", "viewer.js")

#: the runs of the build under way; set before the workers fork, so they inherit it unpickled
_RUNS: list[ViewRun] = []
_LABELS: list[str] = []


@dataclass(frozen=True)
class SiteStats:
    records: int
    pages: int
    plots: int
    seconds: float
    index: Path

    def to_json(self) -> dict[str, Any]:
        return {"records": self.records, "pages": self.pages, "plots": self.plots, "seconds": round(self.seconds, 2),
                "index": str(self.index)}


def needs_trajectory_plot(record: dict[str, Any]) -> bool:
    return any(s["name"] == "solution_match" and s.get("passed") is False for s in record.get("stages", []))


def needs_part_plot(record: dict[str, Any]) -> bool:
    return str(record.get("level")) == "3a" and bool(record.get("stages"))


def _read(path: Path) -> str | None:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None


def _programs(run: ViewRun, record: dict[str, Any]) -> tuple[str | None, str | None]:
    """The extracted program (the record's code, else its saved file without the header) and
    the reference program as the run saved it."""
    files = record.get("files") or {}
    program = (record.get("generation") or {}).get("code")
    if program is None and files.get("generated"):
        program = _read(run.path / files["generated"])
    reference = _read(run.path / files["reference"]) if files.get("reference") else None
    return program, reference


def write_page(run_index: int, position: int, out: Path) -> int:
    """Write one record's page and its plots; returns the number of plots drawn."""
    from meceng.pipeline.rundir import record_key
    from meceng.viewer.plots import part_plot, trajectory_plot
    from meceng.viewer.systems import system_pictures

    run = _RUNS[run_index]
    record = run.tasks[position]
    target = out / page_path(run_index, record)
    folder = target.parent
    images: dict[str, str] = {}
    plots = 0
    want_trajectory, want_part = needs_trajectory_plot(record), needs_part_plot(record)
    source = traces_path(run.path, record_key(record))
    if (want_trajectory or want_part) and source.exists():
        traces: dict[str, Any] | None = None
        parted = ((record.get("behaviour") or {}).get("first_divergence") or {}).get("time")

        def trajectory(data: dict[str, Any], png: Path) -> bool:
            return trajectory_plot(data, png, mark=parted)

        for kind, wanted, draw in (("trajectory", want_trajectory, trajectory), ("part", want_part, part_plot)):
            png = folder / f"{target.stem}.{kind[:4]}.png"
            if not wanted:
                continue
            if png.exists() and png.stat().st_mtime >= source.stat().st_mtime:  # drawn by an earlier build
                images[kind] = png.name
                continue
            traces = traces if traces is not None else load_traces(run.path, record_key(record))
            if traces is not None and draw(traces, png):
                images[kind] = png.name
                plots += 1
    system = None
    if source.exists() and str(record.get("level")) != "3a":  # every rigid and assembly record: SVG is cheap
        traces = load_traces(run.path, record_key(record))
        if traces is not None and "scenes" in traces:
            system = system_pictures(traces["scenes"])
    program, reference = _programs(run, record)
    links = {name: os.path.relpath(_resolved(run.path) / rel, _resolved(folder))
             for name, rel in (record.get("files") or {}).items()}
    neighbours = tuple(Path(page_path(run_index, run.tasks[p])).name if 0 <= p < len(run.tasks) else None
                       for p in (position - 1, position + 1))
    html = task_page(record, run_label=_LABELS[run_index], root="../../", program=program, reference=reference,
                     file_links=links, images=images, neighbours=neighbours,  # type: ignore[arg-type]
                     system=system)
    target.write_text(html, encoding="utf-8")
    return plots


@functools.lru_cache(maxsize=64)
def _resolved(path: Path) -> Path:
    return path.resolve()


def _write_share(args: tuple[list[tuple[int, int]], str]) -> int:
    jobs, out = args
    return sum(write_page(run_index, position, Path(out)) for run_index, position in jobs)


def build_site(paths: list[Path], out: Path, workers: int | None = None, pages: bool = True) -> SiteStats:
    """Write the site for the runs in ``paths`` into ``out``; ``pages`` False writes the index only."""
    t0 = time.perf_counter()
    runs = [load_run(folder) for folder in find_runs(paths)]
    out.mkdir(parents=True, exist_ok=True)
    (out / "static").mkdir(exist_ok=True)
    package = resources.files("meceng.viewer") / "static"
    for name in STATIC_FILES:
        target = out / name if name == "index.html" else out / "static" / name
        target.write_bytes((package / name).read_bytes())
    data = index_data(runs)
    (out / "data.js").write_text(data_script(data), encoding="utf-8")
    t_index = time.perf_counter()
    jobs = [(i, p) for i, run in enumerate(runs) for p in range(len(run.tasks))]
    plots = 0
    if pages:
        for i, run in enumerate(runs):
            _prepare_folder(out / "tasks" / f"r{i}", run)
        plots = _write_pages(runs, jobs, out, workers)
        for i, run in enumerate(runs):
            _drop_stale(out / "tasks" / f"r{i}", {Path(page_path(i, r)).stem for r in run.tasks})
    stats = SiteStats(len(data["rows"]), len(jobs) if pages else 0, plots, time.perf_counter() - t0,
                      out / "index.html")
    log.info("viewer_written", **stats.to_json(), index_s=round(t_index - t0, 2), runs=len(runs))
    return stats


def _prepare_folder(folder: Path, run: ViewRun) -> None:
    """A run's page folder, emptied when it held another run's pages (its plots would be reused)."""
    marker = folder / ".run"
    if folder.exists() and (not marker.exists() or marker.read_text() != str(run.path.resolve())):
        shutil.rmtree(folder)
    folder.mkdir(parents=True, exist_ok=True)
    marker.write_text(str(run.path.resolve()))


def _drop_stale(folder: Path, stems: set[str]) -> None:
    """Pages and plots of records no longer in the run (a rescore, a resume) go."""
    for path in folder.iterdir():
        if not path.name.startswith(".") and path.name.split(".", 1)[0] not in stems:
            path.unlink()


def _write_pages(runs: list[ViewRun], jobs: list[tuple[int, int]], out: Path, workers: int | None) -> int:
    """Pages in forked workers (each inherits the loaded runs), or in this process for few records."""
    global _RUNS, _LABELS
    _RUNS, _LABELS = runs, run_labels(runs)
    try:
        count = workers or min(4, os.cpu_count() or 1)
        if count <= 1 or len(jobs) < 200:
            return _write_share((jobs, str(out)))
        # plots are where the time goes: deal records round-robin so plot-heavy runs spread out
        shares = [(jobs[k::count * 4], str(out)) for k in range(count * 4)]
        with multiprocessing.get_context("fork").Pool(count) as pool:
            return sum(pool.imap_unordered(_write_share, shares))
    finally:
        _RUNS, _LABELS = [], []
