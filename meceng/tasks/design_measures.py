"""Measurements a design spec is written with: read off the recorded coordinates of a reference.

Every function takes the step times and the ODE2 coordinates ``q_ref + q`` per step (rows as the
harness records them) or a signal made from them, and returns one number; ``nan`` when the motion
never shows the quantity (a crank that never completes its turn), which no target meets.
"""

from __future__ import annotations

import numpy as np


def angle_z(q: np.ndarray, first: int) -> np.ndarray:
    """The unwrapped rotation about z of a rigid body whose Euler parameters start at column ``first``."""
    e0, e3 = q[:, first], q[:, first + 3]
    return np.unwrap(2.0 * np.arctan2(e3, e0))


def body_axis(q: np.ndarray, first: int, axis: int) -> np.ndarray:
    """The global direction of a rigid body's local x- (0), y- (1) or z-axis (2) per row (a column of
    its rotation matrix), its Euler parameters starting at column ``first``."""
    e0, e1, e2, e3 = (q[:, first + k] for k in range(4))
    columns = (
        (e0**2 + e1**2 - e2**2 - e3**2, 2 * (e1 * e2 + e0 * e3), 2 * (e1 * e3 - e0 * e2)),
        (2 * (e1 * e2 - e0 * e3), e0**2 - e1**2 + e2**2 - e3**2, 2 * (e2 * e3 + e0 * e1)),
        (2 * (e1 * e3 + e0 * e2), 2 * (e2 * e3 - e0 * e1), e0**2 - e1**2 - e2**2 + e3**2),
    )
    return np.column_stack(columns[axis])


def first_crossing(times: np.ndarray, signal: np.ndarray, level: float, rising: bool = True) -> float:
    """The first time ``signal`` crosses ``level`` (upwards, or downwards with ``rising=False``),
    interpolated linearly between the two steps around it."""
    s = signal - level if rising else level - signal
    above = np.nonzero((s[:-1] < 0.0) & (s[1:] >= 0.0))[0]
    if above.size == 0:
        return float("nan")
    i = int(above[0])
    return float(times[i] + (times[i + 1] - times[i]) * (-s[i]) / (s[i + 1] - s[i]))


def crossings(times: np.ndarray, signal: np.ndarray, level: float = 0.0) -> np.ndarray:
    """Every upward crossing of ``level``, interpolated."""
    s = signal - level
    idx = np.nonzero((s[:-1] < 0.0) & (s[1:] >= 0.0))[0]
    return times[idx] + (times[idx + 1] - times[idx]) * (-s[idx]) / (s[idx + 1] - s[idx])


def mean_period(times: np.ndarray, signal: np.ndarray, level: float | None = None) -> float:
    """The mean time between upward crossings of ``level`` (default: the signal's mean)."""
    ups = crossings(times, signal, float(np.mean(signal)) if level is None else level)
    return float(np.mean(np.diff(ups))) if ups.size >= 2 else float("nan")


def settling_time(times: np.ndarray, signal: np.ndarray, final: float, band: float) -> float:
    """The last time ``signal`` is outside ``final ± band`` (nan if it never settles by the end)."""
    outside = np.nonzero(np.abs(signal - final) > band)[0]
    if outside.size == 0:
        return float(times[0])
    last = int(outside[-1])
    if last >= len(times) - 1:
        return float("nan")
    return float(times[last + 1])


def local_maxima(signal: np.ndarray) -> np.ndarray:
    """Indices of strict interior local maxima."""
    return np.nonzero((signal[1:-1] > signal[:-2]) & (signal[1:-1] >= signal[2:]))[0] + 1


def value_at(times: np.ndarray, signal: np.ndarray, t: float) -> float:
    """``signal`` at time ``t``, interpolated linearly (nan outside the recorded times)."""
    if t < times[0] - 1e-12 or t > times[-1] + 1e-12:
        return float("nan")
    return float(np.interp(t, times, signal))


def highest_after_first_rise(signal: np.ndarray) -> float:
    """The largest value from the first step on which ``signal`` rises (a ball's height after its
    first rebound); ``nan`` if it never rises."""
    rising = np.nonzero(np.diff(signal) > 0.0)[0]
    return float(np.max(signal[rising[0]:])) if rising.size else float("nan")
