"""The child side of the model inspector: the state of a program's system, read from Exudyn itself.

What a body's items say (mass, inertia, reference coordinates) the parent reads from the captured
items; what only the live system knows is recorded here: where every body is, how it is turned and
how fast it moves (Exudyn's own outputs, so Euler parameters, Rxyz rotations and 2D nodes all come
out alike), the global position of every marker, and which ODE2 coordinates belong to which node.
States are taken at t = 0 (after ``Assemble``) and at the first step at or after each requested
time. Every call is guarded: an item Exudyn cannot describe is left out, never a failed run.
"""

from __future__ import annotations

from typing import Any

import numpy as np

#: Object types whose state is read with ``GetObjectOutputBody``.
BODY_TYPES = frozenset({"MassPoint", "MassPoint2D", "RigidBody", "RigidBody2D", "Ground"})
#: Flexible bodies: their floating frame is a rigid node, read with ``GetNodeOutput``.
FLEXIBLE_TYPES = frozenset({"ObjectFFRFreducedOrder", "FFRFreducedOrder", "ObjectFFRF", "FFRF"})
_QUANTITIES = (("p", "Position"), ("v", "Velocity"), ("R", "RotationMatrix"), ("w", "AngularVelocity"))
_MAX_MARKERS = 2000


def _vector(value: Any) -> list[float] | None:
    array = np.asarray(value, dtype=float).ravel()
    if not np.all(np.isfinite(array)):
        return None
    return [float(x) for x in array]


class InspectionRecorder:
    """Collects states of one system at t = 0 and at requested times."""

    def __init__(self, mbs: Any, api: dict[str, Any], times: list[float], loads: bool = False) -> None:
        self.mbs = mbs
        self.loads = loads  # call user-function loads at each state (the agent's tools only)
        self.api = api
        self.out = api["OutputVariableType"]  # bound before the program ran (it may replace exudyn's)
        self.configurations = api["ConfigurationType"]
        self.pending = sorted(float(t) for t in times)
        self.states: list[dict[str, Any]] = []
        data = mbs.systemData
        self.objects = [api["GetObject"](mbs, i) for i in range(api["NumberOfObjects"](data))]
        self.n_markers = min(api["NumberOfMarkers"](data), _MAX_MARKERS)
        self.marker_kinds = [str(api["GetMarker"](mbs, m).get("markerType", "")) for m in range(self.n_markers)]

    def ode2_indices(self) -> dict[str, int]:
        """First ODE2 index of every node that has ODE2 coordinates (the trajectory's columns)."""
        out: dict[str, int] = {}
        for node in range(self.api["NumberOfNodes"](self.mbs.systemData)):
            try:
                index = int(self.api["GetNodeODE2Index"](self.mbs, node))
            except Exception:
                continue
            if index >= 0:
                out[str(node)] = index
        return out

    def _body_state(self, index: int, item: dict[str, Any], configuration: Any) -> dict[str, Any] | None:
        kind = str(item.get("objectType", ""))
        state: dict[str, Any] = {}
        if kind in BODY_TYPES:
            com = [float(x) for x in np.ravel(item.get("centerOfMass", [0.0, 0.0, 0.0]))][:3] or [0.0, 0.0, 0.0]
            com += [0.0] * (3 - len(com))
            for key, name in _QUANTITIES:
                try:
                    value = self.api["GetObjectOutputBody"](self.mbs, index, getattr(self.out, name),
                                                            localPosition=com, configuration=configuration)
                except Exception:
                    continue
                state[key] = _vector(value)
        elif kind in FLEXIBLE_TYPES:
            nodes = item.get("nodeNumbers") or []
            if not nodes:
                return None
            for key, name in _QUANTITIES:
                try:
                    value = self.api["GetNodeOutput"](self.mbs, int(nodes[0]), getattr(self.out, name),
                                                      configuration=configuration)
                except Exception:
                    continue
                state[key] = _vector(value)
        else:
            return None
        return state or None

    def take(self, t: float, initial: bool = False) -> None:
        configuration = self.configurations.Initial if initial else self.configurations.Current
        bodies = {}
        for index, item in enumerate(self.objects):
            state = self._body_state(index, item, configuration)
            if state is not None:
                bodies[str(index)] = state
        markers = {}
        for m in range(self.n_markers):
            if self.marker_kinds[m] not in ("BodyPosition", "BodyRigid", "NodePosition", "NodeRigid",
                                            "SuperElementRigid", "SuperElementPosition"):
                continue
            marker: dict[str, Any] = {}
            for key, name in (("p", "Position"), ("R", "RotationMatrix")):
                if key == "R" and "Rigid" not in self.marker_kinds[m]:
                    continue
                try:
                    value = self.api["GetMarkerOutput"](self.mbs, m, getattr(self.out, name),
                                                        configuration=configuration)
                except Exception:
                    continue
                marker[key] = _vector(value)
            if marker.get("p") is not None:
                markers[str(m)] = marker
        self.states.append({"t": float(t), "bodies": bodies, "markers": markers})
        if self.loads:
            self.states[-1]["loads"] = user_load_values(self.mbs, self.api, t)

    def after_step(self, t: float) -> None:
        """Called from the harness's post-step hook: a state at the first step past each pending time."""
        while self.pending and t >= self.pending[0] - 1e-12:
            self.pending.pop(0)
            if not self.states or abs(self.states[-1]["t"] - t) > 1e-12:
                self.take(t)

    def result(self) -> dict[str, Any]:
        return {"ode2": self.ode2_indices(), "states": self.states}


#: A load's user-function keys and the key of the value Exudyn passes it as its third argument.
_LOAD_FUNCTIONS = (("loadVectorUserFunction", "loadVector"), ("loadUserFunction", "load"))


def user_load_values(mbs: Any, api: dict[str, Any], t: float) -> dict[str, Any]:
    """What every load given by a user function returns at time ``t`` in the current state, called
    here in the sandbox as the solver calls it (``f(mbs, t, loadVector)``): so a model sees its drive
    torques' values and signs, not only that a function exists. A function that raises is named
    with its exception's type; the run goes on."""
    out: dict[str, Any] = {}
    for index in range(api["NumberOfLoads"](mbs.systemData)):
        try:
            load = api["GetLoad"](mbs, index)
        except Exception:
            continue
        for key, given in _LOAD_FUNCTIONS:
            function = load.get(key)
            if isinstance(function, dict):  # Exudyn keeps it as {'function': f, 'type': 'Python'}
                function = function.get("function")
            if not callable(function):
                continue
            try:
                value = _vector(function(mbs, float(t), load.get(given, 0.0)))
            except Exception as exc:
                out[str(index)] = {"error": type(exc).__name__}
                break
            if value is not None:
                out[str(index)] = value
            break
    return out


# ----------------------------------------------------------------------------- motion (behaviour)

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
            for m in range(min(api["NumberOfMarkers"](mbs.systemData), _MAX_MARKERS)):
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
                        return _vector(item[key])
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
