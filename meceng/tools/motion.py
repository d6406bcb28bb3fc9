"""The child side of the behaviour comparison: every body's motion on a bounded time grid, read
from Exudyn itself (see ``MotionRecorder``); the parent compares it in ``eval/behaviour.py``."""

from __future__ import annotations

from typing import Any

import numpy as np

from meceng.tools.inspection import BODY_TYPES, FLEXIBLE_TYPES, MAX_MARKERS
from meceng.tools.inspection import vector as finite_vector

#: At most this many numbers per execution in the motion record (float64: 8 bytes each); the
#: number of samples shrinks with the number of bodies (27 bodies: 201 samples, ~0.78 MB).
MOTION_BUDGET = 100_000
_MOTION_WIDTH = 18  # p, v, w (3 each) and the rotation matrix (9) per body and sample


def _float(value: Any) -> float | None:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if np.isfinite(number) else None


class MotionRecorder:
    """Each body's centre of mass, velocity, angular velocity and rotation on a bounded time grid.

    What the behaviour comparison (``eval/behaviour.py``) needs and the trajectory cannot give
    without Exudyn's kinematics: the centre of mass wherever the program put the reference point,
    in global terms whatever the node type. Rigid bodies and mass points (2D too) are read with
    ``GetObjectOutputBody`` at their centre of mass; a flexible body by its floating frame's node,
    moved to the undeformed body's centre of mass. A sample is taken at the first step at or after
    each grid time, with the step's own time (adaptive steps land beside the grid)."""

    def __init__(self, mbs: Any, api: dict[str, Any], end_time: float, samples: int) -> None:
        self.mbs = mbs
        self.api = api
        self.out = api["OutputVariableType"]
        self.current = api["ConfigurationType"].Current
        self.bodies: list[dict[str, Any]] = []
        for index in range(api["NumberOfObjects"](mbs.systemData)):
            item = api["GetObject"](mbs, index)
            kind = str(item.get("objectType", ""))
            if kind in FLEXIBLE_TYPES and not item.get("nodeNumbers"):
                continue
            if (kind in BODY_TYPES and kind != "Ground") or kind in FLEXIBLE_TYPES:
                self.bodies.append(self._describe(index, kind, item))
        # a flexible body's deformation: the global positions of the markers on its mesh (its interfaces)
        flexible = {b["index"]: k for k, b in enumerate(self.bodies) if b["type"] in FLEXIBLE_TYPES}
        self.points: list[tuple[int, int]] = []  # (marker, position of its body in ``bodies``)
        if flexible:
            for m in range(min(api["NumberOfMarkers"](mbs.systemData), MAX_MARKERS)):
                marker = api["GetMarker"](mbs, m)
                body = marker.get("bodyNumber")
                if str(marker.get("markerType", "")).startswith("SuperElement") and body is not None and \
                        int(body) in flexible:
                    self.points.append((m, flexible[int(body)]))
        width = _MOTION_WIDTH * len(self.bodies) + 3 * len(self.points)
        count = max(2, min(int(samples), MOTION_BUDGET // max(1, width)))
        self.grid = list(np.linspace(0.0, float(end_time), count)) if end_time > 0 else [0.0]
        self.rows: list[np.ndarray] = []
        self.point_rows: list[np.ndarray] = []
        self.times: list[float] = []
        self.failed: str | None = None

    @staticmethod
    def _describe(index: int, kind: str, item: dict[str, Any]) -> dict[str, Any]:
        def vector(*keys: str) -> list[float] | None:
            for key in keys:
                if key in item:
                    try:
                        return finite_vector(item[key])
                    except (TypeError, ValueError):
                        return None
            return None

        mass = _float(item.get("mass", item.get("physicsMass")))
        com = (vector("centerOfMass", "physicsCenterOfMass") or [0.0, 0.0, 0.0])[:3]
        com += [0.0] * (3 - len(com))
        node = (item.get("nodeNumbers") or [None])[0] if kind in FLEXIBLE_TYPES else item.get("nodeNumber")
        return {"index": index, "type": kind, "mass": mass, "inertia": vector("inertia", "physicsInertia"),
                "com": com, "node": None if node is None else int(node)}

    def _sample(self, initial: bool = False) -> np.ndarray:
        configuration = self.api["ConfigurationType"].Initial if initial else self.current
        row = np.full((len(self.bodies), _MOTION_WIDTH), np.nan)
        get_body, get_node = self.api["GetObjectOutputBody"], self.api["GetNodeOutput"]
        for k, body in enumerate(self.bodies):
            flexible = body["type"] in FLEXIBLE_TYPES
            for column, name in ((0, "Position"), (3, "Velocity"), (6, "AngularVelocity"), (9, "RotationMatrix")):
                try:
                    if flexible:
                        value = get_node(self.mbs, body["node"], getattr(self.out, name), configuration=configuration)
                    else:
                        value = get_body(self.mbs, body["index"], getattr(self.out, name),
                                         localPosition=body["com"], configuration=configuration)
                except Exception:
                    continue
                array = np.asarray(value, dtype=float).ravel()
                width = 9 if column == 9 else 3
                if array.size == width:
                    row[k, column:column + width] = array
            if flexible and np.all(np.isfinite(row[k])):
                rotation = row[k, 9:].reshape(3, 3)
                arm = rotation @ np.asarray(body["com"])
                row[k, 0:3] += arm
                row[k, 3:6] += np.cross(row[k, 6:9], arm)
        return row

    def _points(self, initial: bool) -> np.ndarray:
        configuration = self.api["ConfigurationType"].Initial if initial else self.current
        out = np.full((len(self.points), 3), np.nan)
        for k, (marker, _) in enumerate(self.points):
            try:
                value = np.asarray(self.api["GetMarkerOutput"](self.mbs, marker, self.out.Position,
                                                               configuration=configuration), dtype=float).ravel()
            except Exception:
                continue
            if value.size == 3:
                out[k] = value
        return out

    def after_step(self, t: float, initial: bool = False) -> None:
        """Called from the harness's post-step hook, and with ``initial`` once before the solve."""
        if self.failed is not None:
            return
        end = self.grid[-1]
        while self.grid and t >= self.grid[0] - 1e-9 * max(end, 1.0):
            self.grid.pop(0)
            if self.times and abs(self.times[-1] - t) <= 1e-12:
                continue
            try:
                self.rows.append(self._sample(initial))
                self.point_rows.append(self._points(initial))
            except Exception as exc:  # never a failed run for the inspector's sake
                self.failed = f"{type(exc).__name__}: {exc}"
                return
            self.times.append(float(t))

    def arrays(self) -> dict[str, np.ndarray]:
        """The record as arrays: ``t`` (n), ``states`` (n, bodies, 18: p, v, w, rotation row-major),
        ``points`` (n, markers, 3) and ``point_bodies`` (the body of each, its position in ``bodies``)."""
        states = np.stack(self.rows) if self.rows else np.zeros((0, len(self.bodies), _MOTION_WIDTH))
        points = np.stack(self.point_rows) if self.point_rows else np.zeros((0, len(self.points), 3))
        return {"t": np.asarray(self.times, dtype=float), "states": states, "points": points,
                "point_bodies": np.asarray([k for _, k in self.points], dtype=int)}
