"""The viewer's pictures, drawn at build time with matplotlib (Agg) from a record's traces file:
program vs ground truth over time for the coordinates that differ most, and the program's part
beside the ground-truth part from the same views.

Drawn only for records that need them (a numerical-solution mismatch, a part), so a site of
20 000 mostly passing records is written in seconds, not in hours.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator

from meceng.eval.solution import resample
from meceng.inspect.snapshot import shaded_surface
from meceng.pipeline.traces import ranked_coordinates

PLOTTED_COORDINATES = 6
VIEWS = ((25.0, -60.0, "oblique"), (90.0, -90.0, "top (z)"), (0.0, -90.0, "front (y)"))


def _differing(traces: dict[str, Any], count: int) -> list[int]:
    """Positions (in the traces' coordinate list) worth a panel: those where the program leaves
    the ground truth, most first; the first two when none does (a shorter or exploding run)."""
    if "cand_q" not in traces or traces["cand_q"].shape[1] != traces["ref_q"].shape[1]:
        return list(range(min(2, traces["ref_q"].shape[1])))
    order = ranked_coordinates(traces["cand_t"], traces["cand_q"], traces["ref_t"], traces["ref_q"], count)
    end = min(float(traces["cand_t"].max()), float(traces["ref_t"].max()))
    grid = np.linspace(0.0, end, 50)
    scale = float(np.nanmax(np.abs(traces["ref_q"]))) or 1.0
    shown = [int(k) for k in order if not np.allclose(
        resample(traces["cand_t"], traces["cand_q"][:, [k]], grid),
        resample(traces["ref_t"], traces["ref_q"][:, [k]], grid), rtol=0.0, atol=1e-9 * scale)]
    return shown or list(range(min(2, traces["ref_q"].shape[1])))


#: (rows, cols) -> a figure with its axes and their two lines, made once per process and redrawn:
#: a new figure per plot cost ~3x as much (0.65 s against 0.23 s on a loaded 2-core machine)
_FIGURES: dict[tuple[int, int], tuple[Any, list[Any], list[tuple[Any, Any]]]] = {}


def _figure(rows: int, cols: int) -> tuple[Any, list[Any], list[tuple[Any, Any]]]:
    if (rows, cols) not in _FIGURES:
        fig, grid = plt.subplots(rows, cols, figsize=(5.2 * cols, 2.2 * rows), squeeze=False)
        axes = list(grid.flat)
        lines = []
        for n, ax in enumerate(axes):
            truth, = ax.plot([], [], color="#1f5fbf", lw=1.6, label="ground truth")
            program, = ax.plot([], [], color="#d62728", lw=1.3, ls="--", label="program")
            lines.append((truth, program))
            ax.xaxis.set_major_locator(MaxNLocator(5))
            ax.yaxis.set_major_locator(MaxNLocator(4))
            ax.tick_params(labelsize=7)
            if n == 0:
                ax.legend(fontsize=7, loc="best")
            if n // cols == rows - 1:
                ax.set_xlabel("time (s)", fontsize=8)
        # fixed margins: tight_layout measures every tick label and took most of a plot's time
        fig.subplots_adjust(left=0.09 if cols == 2 else 0.13, right=0.98, bottom=0.5 / (2.2 * rows) + 0.04,
                            top=1 - 0.3 / (2.2 * rows), wspace=0.25, hspace=0.45)
        _FIGURES[(rows, cols)] = (fig, axes, lines)
    return _FIGURES[(rows, cols)]


def trajectory_plot(traces: dict[str, Any], path: Path, count: int = PLOTTED_COORDINATES,
                    mark: float | None = None) -> bool:
    """Program (dashed) vs ground truth (solid) over time, one panel per coordinate, the ones
    that differ most first; ``mark``: a vertical line where the behaviour verdict saw the motions
    part. False when the traces hold no trajectory."""
    if "ref_q" not in traces or traces["ref_q"].shape[1] == 0:
        return False
    picked = _differing(traces, count)
    cols = 2 if len(picked) > 1 else 1
    fig, axes, lines = _figure((len(picked) + cols - 1) // cols, cols)
    for n, (ax, (truth, program)) in enumerate(zip(axes, lines, strict=True)):
        ax.set_visible(n < len(picked))
        if n >= len(picked):
            continue
        k = picked[n]
        truth.set_data(traces["ref_t"], traces["ref_q"][:, k])
        has_program = "cand_q" in traces and k < traces["cand_q"].shape[1]
        program.set_visible(has_program)
        program.set_data((traces["cand_t"], traces["cand_q"][:, k]) if has_program else ([], []))
        ax.relim(visible_only=True)
        ax.autoscale_view()
        ax.set_title(f"coordinate q[{int(traces['coordinates'][k])}]", fontsize=9, pad=3)
    marks = [ax.axvline(mark, color="tab:red", linewidth=0.8, linestyle=":") for ax in axes[:len(picked)]] \
        if mark is not None else []
    fig.savefig(path, dpi=80)
    for line in marks:  # the figure is reused for the next record
        line.remove()
    return True


def part_plot(traces: dict[str, Any], path: Path) -> bool:
    """The program's part (top row) and the ground-truth part (bottom row) from the same views,
    on the same axes limits, so a wrong size or a missing hole shows. False without surfaces."""
    meshes = [(label, traces.get(f"{p}_vertices"), traces.get(f"{p}_triangles"), colour)
              for label, p, colour in (("program", "cand", (0.85, 0.35, 0.25)), ("ground truth", "ref",
                                                                                  (0.3, 0.5, 0.85)))]
    present = [m for m in meshes if m[1] is not None and m[2] is not None and len(m[2])]
    if not present:
        return False
    everything = np.concatenate([m[1] for m in present])
    low, high = everything.min(axis=0), everything.max(axis=0)
    extent = np.maximum(high - low, 0.02 * float(np.max(high - low)) or 1.0)  # a flat part stays visible
    margin = 0.04 * extent
    fig = plt.figure(figsize=(4.2 * len(VIEWS), 3.2 * len(meshes)))
    for row, (label, vertices, triangles, colour) in enumerate(meshes):
        for col, (elev, azim, name) in enumerate(VIEWS):
            ax = fig.add_subplot(len(meshes), len(VIEWS), row * len(VIEWS) + col + 1, projection="3d")
            ax.set_axis_off()
            if vertices is None or triangles is None or not len(triangles):
                ax.set_title(f"{label}: no surface", fontsize=9)
                continue
            ax.add_collection3d(shaded_surface(np.asarray(vertices, float), np.asarray(triangles), colour))
            for k, axis in enumerate("xyz"):  # the same limits in every panel: sizes compare
                getattr(ax, f"set_{axis}lim")(low[k] - margin[k], high[k] + margin[k])
            ax.set_box_aspect(tuple(extent + 2 * margin))
            ax.view_init(elev=elev, azim=azim)
            ax.set_title(f"{label}, {name}", fontsize=9)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.93, wspace=0.02, hspace=0.12)
    fig.savefig(path, dpi=72)
    plt.close(fig)
    return True
