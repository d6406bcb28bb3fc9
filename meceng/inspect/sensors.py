"""The program's own sensors in words, for the agent's ``simulate``: what each reads and its values
over a time window, so a model can measure what its task asks (an event's time, a height, an
extreme) from its own program. Only the program's numbers: never a target or a verdict."""

from __future__ import annotations

from typing import Any

import numpy as np

#: The most rows one sensor's table shows.
MAX_SAMPLES = 200


def _reads(sensor: dict[str, Any]) -> str:
    if sensor.get("sensorType") == "UserFunction":
        return "UserFunction sensor: the values its sensorUserFunction returns"
    what = sensor.get("outputVariableType", "?")
    for key, noun in (("bodyNumber", "body"), ("nodeNumber", "node"), ("markerNumber", "marker"),
                      ("objectNumber", "object"), ("loadNumber", "load")):
        if key in sensor and sensor[key] is not None and sensor[key] != -1:
            where = f"{noun} #{sensor[key]}"
            break
    else:
        where = "?"
    local = sensor.get("localPosition")
    at = f" at local position {np.round(local, 6).tolist()}" if local is not None and any(local) else ""
    return f"{sensor.get('sensorType', '?')} sensor: {what} of {where}{at}"


def sensor_words(sensors: list[dict[str, Any]] | None, window: tuple[float, float] | None, samples: int,
                 end_time: float) -> str:
    """Each sensor's values at ``samples`` evenly spaced times of ``window`` (default: the whole run),
    interpolated linearly between stored rows, with the largest and smallest value of each column
    over the window and when they occur."""
    if not sensors:
        return ("Sensors: none in the program (add mbs.AddSensor(SensorBody(...)) or SensorNode/SensorMarker to "
                "read a quantity over the run here; the tool stores every step).")
    lo, hi = window if window is not None else (0.0, end_time)
    samples = max(2, min(int(samples), MAX_SAMPLES))
    lines = [f"Sensors (values interpolated between the stored steps; window {lo:g} to {hi:g} s, {samples} times):"]
    for sensor in sensors:
        name = sensor.get("name") or f"sensor{sensor['index']}"
        rows = np.asarray(sensor.get("rows") or [], dtype=float)
        head = f"- #{sensor['index']} {name}: {_reads(sensor)}"
        if sensor.get("error") or rows.ndim != 2 or len(rows) < 2:
            lines.append(f"{head}: no stored values ({sensor.get('error') or 'nothing recorded'})")
            continue
        t, values = rows[:, 0], rows[:, 1:]
        inside = (t >= lo - 1e-12) & (t <= hi + 1e-12)
        if not inside.any():
            lines.append(f"{head}: no stored values in the window")
            continue
        times = np.linspace(max(lo, t[0]), min(hi, t[-1]), samples)
        table = np.column_stack([times, *(np.interp(times, t, values[:, j]) for j in range(values.shape[1]))])
        lines.append(f"{head}; stored every {np.median(np.diff(t)):.3g} s")
        for j in range(values.shape[1]):
            col, tt = values[inside, j], t[inside]
            lines.append(f"  column {j}, over every stored step from {lo:g} to {hi:g} s: largest {col.max():.7g} at "
                         f"t = {tt[col.argmax()]:.6g} s, smallest {col.min():.7g} at t = {tt[col.argmin()]:.6g} s")
        lines.append("  t, " + ", ".join(f"column {j}" for j in range(values.shape[1])))
        lines.extend("  " + ", ".join(f"{x:.7g}" for x in row) for row in table)
    return "\n".join(lines)
