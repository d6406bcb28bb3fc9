"""The child side of the model inspector: the state of a program's system, read from Exudyn itself.

What a body's items say (mass, inertia, reference coordinates) the parent reads from the captured
items; what only the live system knows is recorded here: where every body is, how it is turned and
how fast it moves (Exudyn's own outputs, so Euler parameters, Rxyz rotations and 2D nodes all come
out alike), the global position of every marker, and which ODE2 coordinates belong to which node.
States are taken at t = 0 (after ``Assemble``) and, for each requested time, at the solver step
nearest to it (a step that lands within half a step of it: shortened steps, after an impact, leave the
grid, and the first step past 0.5 s may be 0.5001 s while 0.499998 s was nearer); each state keeps the
times it was asked for (``asked``) so the answer can say the time asked, or why the step differs.
Every call is guarded: an item Exudyn cannot describe is left out, never a failed run.
"""

from __future__ import annotations

from typing import Any

import numpy as np

#: Object types whose state is read with ``GetObjectOutputBody``.
BODY_TYPES = frozenset({"MassPoint", "MassPoint2D", "RigidBody", "RigidBody2D", "Ground"})
#: Flexible bodies: their floating frame is a rigid node, read with ``GetNodeOutput``.
FLEXIBLE_TYPES = frozenset({"ObjectFFRFreducedOrder", "FFRFreducedOrder", "ObjectFFRF", "FFRF"})
_QUANTITIES = (("p", "Position"), ("v", "Velocity"), ("R", "RotationMatrix"), ("w", "AngularVelocity"))
MAX_MARKERS = 2000


def vector(value: Any) -> list[float] | None:
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
        self.last_t: float | None = None  # the previous step's time: the step size, for the nearest step
        data = mbs.systemData
        self.objects = [api["GetObject"](mbs, i) for i in range(api["NumberOfObjects"](data))]
        self.n_markers = min(api["NumberOfMarkers"](data), MAX_MARKERS)
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
                state[key] = vector(value)
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
                state[key] = vector(value)
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
                marker[key] = vector(value)
            if marker.get("p") is not None:
                markers[str(m)] = marker
        self.states.append({"t": float(t), "bodies": bodies, "markers": markers, "asked": []})
        if self.loads:
            self.states[-1]["loads"] = user_load_values(self.mbs, self.api, t)
            self.states[-1]["connectors"] = user_connector_values(self.mbs, self.api, self.objects, self.out)
        if initial:
            self.last_t = float(t)
            while self.pending and self.pending[0] <= float(t) + 1e-12:
                self.states[-1]["asked"].append(self.pending.pop(0))

    def after_step(self, t: float) -> None:
        """Called from the harness's post-step hook: a state at the step nearest each pending time,
        judged by this step's size (the next one is taken to be as long)."""
        half = 0.5 * (t - self.last_t) if self.last_t is not None else 0.0
        self.last_t = t
        while self.pending and t >= self.pending[0] - max(half, 1e-12):
            asked = self.pending.pop(0)
            if not self.states or abs(self.states[-1]["t"] - t) > 1e-12:
                self.take(t)
                self.states[-1]["step"] = 2.0 * half
            self.states[-1]["asked"].append(asked)

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
                value = vector(function(mbs, float(t), load.get(given, 0.0)))
            except Exception as exc:
                out[str(index)] = {"error": type(exc).__name__}
                break
            if value is not None:
                out[str(index)] = value
            break
    return out


#: What a connector given by a user function applies (the first output its type has), and what the
#: function was given (its measured rotation, length or displacement).
_CONNECTOR_OUTPUTS = ("TorqueLocal", "ForceLocal", "Force")
_CONNECTOR_INPUTS = ("Rotation", "Distance", "Displacement")


def _callable(value: Any) -> bool:
    if isinstance(value, dict):  # Exudyn keeps it as {'function': f, 'type': 'Python'}
        value = value.get("function")
    return callable(value)


def user_connector_values(mbs: Any, api: dict[str, Any], objects: list[dict[str, Any]], out: Any
                          ) -> dict[str, Any]:
    """What every connector whose force or torque a user function gives applies in the current state,
    read with Exudyn's own connector outputs (which call the function as the solver does), with the
    quantity the function was given: a model sees its drives' torques and signs, not only that a
    function exists. A connector whose outputs raise is named with the exception's type."""
    values: dict[str, Any] = {}
    for index, item in enumerate(objects):
        if not any(key.endswith("UserFunction") and "offset" not in key and _callable(value)
                   for key, value in item.items()):
            continue
        said: dict[str, Any] = {}
        for key, names in (("value", _CONNECTOR_OUTPUTS), ("input", _CONNECTOR_INPUTS)):
            for name in names:
                try:
                    value = vector(api["GetObjectOutput"](mbs, index, getattr(out, name)))
                except Exception as exc:
                    if key == "value" and name == names[-1] and not said:
                        said["error"] = type(exc).__name__
                    continue
                if value is not None:
                    said[key], said[key + "_name"] = value, name
                    break
        if said:
            values[str(index)] = said
    return values
