"""How fast `meceng view` writes a site and how fast its index opens and filters in Chromium.

Synthetic runs are made from a real run folder (its records, programs and traces, reused under
new seeds): ``--records`` records over ``--runs`` runs, a share ``--fail`` of them failing at a
random stage (a solution mismatch gets its trajectory plot, as in a real run). Then the site is
built (timed), the index is opened in headless Chromium with a filter applied as a user does it
(times measured by the page's script), and screenshots are written.

    python scripts/bench_viewer.py --source runs/<gold run with traces> --records 20000 --out /tmp/vbench
"""

from __future__ import annotations

import argparse
import copy
import json
import random
import re
import time
from pathlib import Path
from typing import Any

from meceng.eval.categories import CATEGORIES
from meceng.pipeline.rundir import record_key
from meceng.pipeline.traces import traces_path
from meceng.viewer.browser import load, screenshot
from meceng.viewer.site import build_site


def _fail(record: dict[str, Any], rng: random.Random) -> None:
    """Make a passing record fail at a random stage, as a model's failures look in the record."""
    stages = record["stages"]
    at = rng.choice([i for i, s in enumerate(stages) if s["name"] != "choose_components"] or [0])
    if rng.random() < 0.4:
        at = next((i for i, s in enumerate(stages) if s["name"] == "solution_match"), at)
    name = stages[at]["name"]
    stages[at] = {"name": name, "passed": False, "detail": f"synthetic failure of {name} (norm {rng.random():.3g})"}
    for s in stages[at + 1:]:
        s.update(passed=None, detail="not evaluated")
    record.update(overall=False, first_failure=name)
    if name == "graph_content_match":
        category = rng.choice(CATEGORIES)
        record["error_categories"] = [category]
        record["differences"] = [{"item": "object:MassPoint#1", "key": "physicsMass", "value": 2.0, "expected": 1.0,
                                  "category": category}]
    code = (record.get("generation") or {}).get("code")
    if code:
        record["generation"]["code"] = re.sub(r"= ([0-9]+\.[0-9]+)", lambda m: f"= {float(m.group(1)) * 1.1:.4g}",
                                              code, count=2)


def synthesize(source: Path, out: Path, records: int, runs: int, fail: float, seed: int = 0) -> list[Path]:
    data = json.loads((source / "run.json").read_text())
    base = [t for t in data["tasks"] if t.get("stages")]
    rng = random.Random(seed)
    folders = []
    per_run = records // runs
    for r in range(runs):
        folder = out / "runs" / f"synthetic-{r}"
        folder.mkdir(parents=True, exist_ok=True)
        if not (folder / "programs").exists():
            (folder / "programs").symlink_to((source / "programs").resolve())
        tasks = []
        for k in range(per_run):
            original = base[k % len(base)]
            record = copy.deepcopy(original)
            record["seed"] = original["seed"] + 1000 * (k // len(base))
            if rng.random() < fail:
                _fail(record, rng)
            target = traces_path(folder, record_key(record))
            if not target.exists() and traces_path(source, record_key(original)).exists():
                target.parent.mkdir(exist_ok=True)
                target.symlink_to(traces_path(source, record_key(original)).resolve())
            tasks.append(record)
        settings = copy.deepcopy(data["settings"])
        settings["llm"]["model"] = f"synthetic-model-{r}"
        (folder / "run.json").write_text(json.dumps({"settings": settings, "summary": {}, "tasks": tasks}))
        folders.append(folder)
    return folders


def browser_times(index: Path, repeats: int = 3) -> dict[str, Any]:
    """Load-to-ready and select-plus-search times as the page's script measured them (median)."""
    ready, bench = [], []
    for _ in range(repeats):
        page = load(index.as_uri() + "#bench=pendulum", budget_ms=20000)
        timing = re.search(r'<p id="timing"[^>]*>', page.dom)
        assert timing is not None and not page.console, page.console
        ready.append(float(re.search(r'data-ready-ms="([0-9.]+)"', timing.group(0)).group(1)))  # type: ignore[union-attr]
        bench.append(float(re.search(r'data-bench-ms="([0-9.]+)"', timing.group(0)).group(1)))  # type: ignore[union-attr]
        counts = re.search(r'data-bench-counts="([0-9,]+)"', timing.group(0)).group(1)  # type: ignore[union-attr]
    return {"ready_ms": sorted(ready)[repeats // 2], "select_and_search_ms": sorted(bench)[repeats // 2],
            "rows_after_select_and_search": counts, "all_ready_ms": ready}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source", type=Path, required=True, help="a run folder (with traces/ for plots)")
    parser.add_argument("--records", type=int, default=20000)
    parser.add_argument("--runs", type=int, default=4)
    parser.add_argument("--fail", type=float, default=0.3)
    parser.add_argument("--workers", type=int, default=None)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    folders = synthesize(args.source, args.out, args.records, args.runs, args.fail)
    site = args.out / "site"
    results: dict[str, Any] = {}
    t0 = time.perf_counter()
    stats = build_site(folders, site, workers=args.workers, pages=False)
    results["index_only_s"] = round(time.perf_counter() - t0, 2)
    stats = build_site(folders, site, workers=args.workers)
    results["site"] = stats.to_json()
    t0 = time.perf_counter()
    results["rebuild_s"] = round(build_site(folders, site, workers=args.workers).seconds, 2)
    results["browser"] = browser_times(site / "index.html")
    results["data_js_mb"] = round((site / "data.js").stat().st_size / 1e6, 2)
    shots = args.out / "screenshots"
    shots.mkdir(exist_ok=True)
    screenshot((site / "index.html").as_uri() + "#status=failed", shots / "index_failed.png", (1400, 1100))
    results["screenshots"] = [str(shots / "index_failed.png")]
    print(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
