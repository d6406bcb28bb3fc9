"""Numerical solution comparison (paper section 3.1).

First the dimensions (number of coordinates, steps actually simulated), then the Frobenius norm
of the difference of q_total = q_ref + q_disp over all steps. Adaptive step control (contact)
makes step times irregular, so both trajectories are resampled onto the ground truth's nominal
grid t_k = k * h before the norm is taken.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SolutionComparison:
    passed: bool
    detail: str
    norm: float | None = None


def resample(times: np.ndarray, q: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """Linear interpolation of every coordinate onto ``grid``; first row per duplicated time."""
    t_unique, first = np.unique(times, return_index=True)
    q_unique = q[first]
    return np.column_stack([np.interp(grid, t_unique, q_unique[:, j]) for j in range(q.shape[1])])


def compare_solutions(
    times: np.ndarray,
    q: np.ndarray,
    ref_times: np.ndarray,
    ref_q: np.ndarray,
    end_time: float,
    steps: int,
    tolerance: float = 1e-5,
) -> SolutionComparison:
    if q.ndim != 2 or ref_q.ndim != 2 or len(q) == 0:
        return SolutionComparison(False, "no trajectory recorded")
    if q.shape[1] != ref_q.shape[1]:
        return SolutionComparison(
            False, f"number of coordinates differs: {q.shape[1]} vs {ref_q.shape[1]} in the ground truth"
        )
    step = end_time / steps
    reached = float(times.max())
    if reached < end_time - 0.5 * step:
        return SolutionComparison(False, f"simulation ended early at t = {reached:.6g} s of {end_time:g} s")
    if not np.all(np.isfinite(q)):
        return SolutionComparison(False, "solution contains NaN or inf")
    grid = np.linspace(0.0, end_time, steps + 1)
    difference = resample(times, q, grid) - resample(ref_times, ref_q, grid)
    norm = float(np.linalg.norm(difference))
    if norm < tolerance:
        return SolutionComparison(True, f"solutions match (norm {norm:.3g} < {tolerance:g})", norm)
    return SolutionComparison(False, f"solutions differ (norm {norm:.3g} >= {tolerance:g})", norm)
