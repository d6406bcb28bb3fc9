"""How hard each design task model is, measured: per instance the band of passing designs (as a
fraction of the allowed range) and the verdict of the engineer's closed-form estimate.

    python scripts/design_figures.py                         # every level-4 model, seeds 0-4
    python scripts/design_figures.py cradle_restitution_rise --seeds 10
    python scripts/design_figures.py --write                 # keep them in tasks/design/figures.json
    python scripts/design_figures.py --markdown              # the kept figures as docs/design.md's table

The figures are what ``meceng tasks show`` and docs/design.md show; each takes ~10-60 s a model
(one reference run per design tried, in this process).
"""

from __future__ import annotations

import argparse
import fcntl
import json
import statistics
import time
from pathlib import Path

from meceng.tasks.design_check import band_fraction, check_estimate
from meceng.tasks.registry import default_registry

FIGURES = Path(__file__).resolve().parents[1] / "meceng" / "tasks" / "design" / "figures.json"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("slugs", nargs="*", help="design task models (default: all of level 4)")
    parser.add_argument("--seeds", type=int, default=5, help="instances per model: seeds 0..N-1")
    parser.add_argument("--write", action="store_true", help=f"merge the figures into {FIGURES.name}")
    parser.add_argument("--markdown", action="store_true", help=f"print {FIGURES.name} as a table, run nothing")
    args = parser.parse_args()
    registry = default_registry()
    models = [registry.get(s) for s in args.slugs] if args.slugs else registry.select(levels=["4"])
    if args.markdown:
        print(markdown(models, json.loads(FIGURES.read_text()) if FIGURES.exists() else {}))
        return 0
    figures: dict = {}
    for model in models:
        t0 = time.perf_counter()
        bands, estimates = [], []
        for seed in range(args.seeds):
            instance = model.instance(seed)
            band = band_fraction(instance.design)
            estimate = check_estimate(instance)
            bands.append(band)
            estimates.append(estimate)
            print(f"{model.slug} seed {seed}: target {instance.design.target:g} gold {instance.design.gold} | "
                  f"band {100 * band:.2f} % of the range | estimate {estimate.design} -> {estimate.value:.5g} "
                  f"({estimate.error_in_tolerances:.1f} tolerances, {'passes' if estimate.passed else 'fails'})",
                  flush=True)
        figures[model.slug] = {
            "seeds": args.seeds,
            "band_percent": {"min": round(100 * min(bands), 2), "median": round(100 * statistics.median(bands), 2),
                             "max": round(100 * max(bands), 2)},
            "estimate": {"passed": sum(e.passed for e in estimates), "of": len(estimates),
                         "median_error_in_tolerances": round(statistics.median(
                             min(e.error_in_tolerances, 1e6) for e in estimates), 2)},
        }
        print(f"== {model.slug}: {json.dumps(figures[model.slug])} ({time.perf_counter() - t0:.0f} s)", flush=True)
    if args.write:
        with open(FIGURES.with_suffix(".lock"), "w") as lock:  # several scripts may write at once
            fcntl.flock(lock, fcntl.LOCK_EX)
            kept = json.loads(FIGURES.read_text()) if FIGURES.exists() else {}
            kept.update(figures)
            FIGURES.write_text(json.dumps(dict(sorted(kept.items())), indent=1) + "\n")
        print(f"written: {FIGURES}")
    return 0


def markdown(models: list, figures: dict) -> str:
    rows = ["| id | design task | system | open value(s) | quantity | band (% of the range) | estimate passes |",
            "|---:|---|---|---|---|---|---|"]
    for model in models:
        fig = figures.get(model.slug)
        band = (f"{fig['band_percent']['median']} ({fig['band_percent']['min']}–{fig['band_percent']['max']})"
                if fig else "not measured")
        passes = (f"{fig['estimate']['passed']}/{fig['estimate']['of']} "
                  f"({fig['estimate']['median_error_in_tolerances']} tol. off)" if fig else "–")
        values = ", ".join(f"{v.name} [{v.low:g}, {v.high:g}] {v.unit}".rstrip() for v in model.variables)
        rows.append(f"| {model.id} | `{model.slug}` | `{model.system.slug}` | {values} | {model.spec.kind} | "
                    f"{band} | {passes} |")
    return "\n".join(rows)


if __name__ == "__main__":
    raise SystemExit(main())
