"""The report's figures: bar, line, difficulty and release plots, drawn headless (Agg) to PNG."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from meceng.eval.rates import Rate


def save_figure(fig: Any, ax: Any, path: Path) -> None:
    """A legend where something was drawn (a run with nothing graded draws nothing), then the PNG."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)

def bar_plot(path: Path, groups: dict[str, dict[str, Rate]], title: str, ylabel: str) -> None:
    """Grouped bars with Wilson error bars: one group per model, one bar per key."""
    keys = list(dict.fromkeys(k for d in groups.values() for k in d))  # first-seen order
    fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(groups) * max(1, len(keys))), 4))
    width = 0.8 / max(1, len(keys))
    for j, key in enumerate(keys):
        xs, ys, low, high = [], [], [], []
        for i, model in enumerate(groups):
            rate = groups[model].get(key)
            if rate is None or rate.value is None:
                continue
            down, up = rate.error_bar
            xs.append(i + j * width)
            ys.append(100 * rate.value)
            low.append(100 * down)
            high.append(100 * up)
        ax.bar(xs, ys, width, yerr=[low, high], capsize=3, label=key)
    ax.set_xticks([i + width * (len(keys) - 1) / 2 for i in range(len(groups))], list(groups), rotation=20)
    ax.set_ylim(0, 105)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    save_figure(fig, ax, path)

def line_plot(path: Path, groups: dict[str, dict[str, Rate]], title: str, xlabel: str) -> None:
    fig, ax = plt.subplots(figsize=(6, 4))
    for model, rates in groups.items():
        known = {k: r for k, r in rates.items() if r.value is not None}
        if not known:
            continue
        xs = [float(k) for k in known]
        ys = [100 * r.value for r in known.values() if r.value is not None]
        bars = [r.error_bar for r in known.values()]
        ax.errorbar(xs, ys, yerr=[[100 * d for d, _ in bars], [100 * u for _, u in bars]],
                    marker="o", capsize=3, label=model)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("overall success (%)")
    ax.set_ylim(0, 105)
    ax.set_title(title)
    save_figure(fig, ax, path)

def difficulty_plot(path: Path, rows: list[dict[str, Any]]) -> None:
    fig, ax = plt.subplots(figsize=(7, max(3, 0.25 * len(rows))))
    ax.barh([r["slug"] for r in rows][::-1], [100 * r["difficulty"] for r in rows][::-1])
    ax.set_xlabel("difficulty = 1 - mean overall success (%)")
    ax.set_xlim(0, 100)
    ax.set_title("Difficulty per task model")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)

def release_plot(path: Path, points: list[tuple[str, str, float | None, float]]) -> None:
    import datetime as dt

    fig, ax = plt.subplots(figsize=(7, 4))
    for model, release, size, rate in points:
        when = dt.date.fromisoformat(release)
        ax.scatter([when], [100 * rate], s=20 + 3 * (size or 10))
        ax.annotate(model, (when, 100 * rate), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.set_ylabel("overall success (%)")
    ax.set_ylim(0, 105)
    ax.set_title("Overall success vs release date (marker size: parameters)")
    fig.autofmt_xdate()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
