"""What the viewer needs of a graded task that the record does not hold: both trajectories and
both part surfaces, kept small, one ``traces/<key>.npz`` per task record in the run folder.

The run drops its executions once a task is graded (memory at server scale), so the flow calls
:func:`save_traces` right after grading, and ``rescore`` calls it again (it regrades, so the file
follows the record). The file name is derived from the record's key alone, so a viewer finds it
for any record, and an older run without it simply shows no plot.

Size: a trajectory is resampled onto at most 200 time points and at most 24 coordinates (those
where program and ground truth differ most), float32; a surface is decimated by vertex
clustering to at most ~2000 triangles. A level 1-2 task costs ~5-25 kB, a part ~30-60 kB.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from meceng.eval.solution import resample
from meceng.inspect.scene import build_scene
from meceng.inspect.view import build_view
from meceng.logs import get_logger
from meceng.syntax import parsing

from .rundir import safe_name

if TYPE_CHECKING:
    from meceng.tools.execution import Execution

log = get_logger(__name__)

MAX_POINTS = 200
MAX_COORDINATES = 24
MAX_TRIANGLES = 2000
MAX_SCENE_ITEMS = 2000  # a larger system gets no picture (a hostile program's thousands of bodies)


def safe_key(key: str) -> str:
    """A record key (``slug@seed`` or ``origin/slug@seed``) as a file name, as parts/ names them."""
    return safe_name(key.replace("/", "--"))


def traces_path(run_dir: Path, key: str) -> Path:
    return run_dir / "traces" / f"{safe_key(key)}.npz"


def _downsample(times: np.ndarray, q: np.ndarray, points: int = MAX_POINTS) -> tuple[np.ndarray, np.ndarray]:
    """The trajectory on a uniform grid over the times it reached (adaptive steps made regular)."""
    if len(times) <= points:
        return times.astype(np.float32), q.astype(np.float32)
    grid = np.linspace(float(np.min(times)), float(np.max(times)), points)
    return grid.astype(np.float32), resample(times, q, grid).astype(np.float32)


def ranked_coordinates(cand_t: np.ndarray, cand_q: np.ndarray, ref_t: np.ndarray, ref_q: np.ndarray,
                       count: int = MAX_COORDINATES) -> np.ndarray:
    """Indices of the coordinates where program and ground truth differ most (largest first);
    the first ``count`` when the two have different numbers of coordinates."""
    if cand_q.shape[1] != ref_q.shape[1] or len(cand_t) == 0 or len(ref_t) == 0:
        return np.arange(min(count, ref_q.shape[1], cand_q.shape[1]))
    end = min(float(np.max(cand_t)), float(np.max(ref_t)))
    grid = np.linspace(0.0, end, 100)
    with np.errstate(invalid="ignore"):
        gap = np.abs(resample(cand_t, cand_q, grid) - resample(ref_t, ref_q, grid))
        score = np.nan_to_num(np.nanmax(gap, axis=0), nan=np.inf) if len(grid) else np.zeros(ref_q.shape[1])
    return np.argsort(-score, kind="stable")[:count]


def decimate_surface(vertices: np.ndarray, triangles: np.ndarray,
                     max_triangles: int = MAX_TRIANGLES) -> tuple[np.ndarray, np.ndarray]:
    """Vertex clustering: vertices snapped to a grid merge, collapsed triangles go; the grid is
    made coarser until at most ``max_triangles`` remain. Shape stays recognisable for a picture
    (not for a metric: the grading uses the full surfaces)."""
    vertices = np.asarray(vertices, dtype=np.float64)
    triangles = np.asarray(triangles, dtype=np.int64)
    if len(triangles) <= max_triangles or len(vertices) == 0:
        return vertices.astype(np.float32), triangles.astype(np.int32)
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    extent = float(np.max(high - low)) or 1.0
    cells = 64
    while True:
        size = extent / cells
        cell = np.floor((vertices - low) / size).astype(np.int64)
        _, label, inverse = np.unique(cell, axis=0, return_index=True, return_inverse=True)
        inverse = inverse.reshape(-1)
        counts = np.bincount(inverse)
        merged = np.zeros((len(label), 3))
        np.add.at(merged, inverse, vertices)
        merged /= counts[:, None]
        tri = inverse[triangles]
        keep = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])
        tri = np.unique(np.sort(tri[keep], axis=1), axis=0) if keep.any() else tri[keep]
        if len(tri) <= max_triangles or cells <= 4:
            return merged.astype(np.float32), tri.astype(np.int32)
        cells = int(cells * 0.75)


def trace_arrays(candidate: Execution, reference: Execution) -> dict[str, np.ndarray]:
    """The arrays :func:`save_traces` keeps (empty when neither program left anything to show)."""
    arrays: dict[str, np.ndarray] = {}
    have_cand = candidate.times is not None and candidate.trajectory is not None and len(candidate.times) > 0
    have_ref = reference.times is not None and reference.trajectory is not None and len(reference.times) > 0
    if have_ref:
        ref_t, ref_q = np.asarray(reference.times), np.atleast_2d(np.asarray(reference.trajectory))
        if have_cand:
            cand_t, cand_q = np.asarray(candidate.times), np.atleast_2d(np.asarray(candidate.trajectory))
            picked = ranked_coordinates(cand_t, cand_q, ref_t, ref_q)
            arrays["cand_t"], arrays["cand_q"] = _downsample(cand_t, cand_q[:, picked])
        else:
            picked = np.arange(min(MAX_COORDINATES, ref_q.shape[1]))
        arrays["coordinates"] = picked.astype(np.int32)
        arrays["ref_t"], arrays["ref_q"] = _downsample(ref_t, ref_q[:, picked])
        arrays["n_coordinates"] = np.array([ref_q.shape[1], cand_q.shape[1] if have_cand else -1], dtype=np.int32)
    for prefix, run in (("cand", candidate), ("ref", reference)):
        if run.surface is not None:
            arrays[f"{prefix}_vertices"], arrays[f"{prefix}_triangles"] = decimate_surface(*run.surface)
    scenes = {prefix: system_scenes(run) for prefix, run in (("cand", candidate), ("ref", reference))}
    if any(scenes.values()):
        arrays["scenes"] = np.array(json.dumps(scenes))
    return arrays


def system_scenes(run: Execution) -> dict[str, Any] | None:
    """The system at t = 0 and at the end as drawable shapes (the viewer's pictures), or None."""
    if run.items is None or not run.inspection or not run.inspection.get("states"):
        return None
    view = build_view(run.items, run.system, run.inspection)
    if len(view.bodies) + len(view.connectors) > MAX_SCENE_ITEMS:
        return None
    return {"times": [view.times[0], view.times[-1]],
            "shapes": [[shape.to_json() for shape in build_scene(view, t)] for t in (view.times[0], view.times[-1])]}


def save_traces(run_dir: Path, key: str, candidate: Execution, reference: Execution) -> str | None:
    """Keep the viewer's trajectories and part surfaces of one graded task at
    ``traces/<key>.npz``; returns the path relative to ``run_dir`` (for ``record["files"]``), or
    None when there was nothing to keep (a program that never ran, an infrastructure failure).

    Never raises: a viewer file must not cost a graded record."""
    try:
        arrays = trace_arrays(candidate, reference)
        path = traces_path(run_dir, key)
        if not arrays:
            path.unlink(missing_ok=True)  # a rescore that no longer has a trajectory: no stale plot
            return None
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(path.name + ".tmp.npz")
        np.savez_compressed(tmp, **arrays)
        os.replace(tmp, path)
        return str(path.relative_to(run_dir))
    except Exception as exc:
        log.warning("traces_not_saved", key=key, error=f"{type(exc).__name__}: {exc}")
        return None


def load_traces(run_dir: Path, key: str) -> dict[str, Any] | None:
    """The arrays of :func:`save_traces`, or None for a record that has none (older runs)."""
    path = traces_path(run_dir, key)
    if not path.exists():
        return None
    try:
        with parsing(), np.load(path) as data:  # numpy parses each array's header
            return {name: data[name] for name in data.files}
    except (OSError, ValueError) as exc:
        log.warning("traces_unreadable", path=str(path), error=str(exc))
        return None
