"""The Exudyn harness a program runs under in the child, and what it captures of the built system.

``Harness.install`` patches Exudyn before the program runs: ``Assemble`` records the stages, every
solver call of the program hands control back (``HandOver``) so the ground truth's simulation
block runs instead, renderers become no-ops, a post-step hook records the coordinates. The
capture functions turn the assembled system's items into JSON for the parent.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np


class HandOver(BaseException):
    """Raised at the program's solver call; BaseException so ``except Exception`` can't eat it."""


class Harness:
    def __init__(self, workdir: Path, token: str = "") -> None:
        self.workdir = workdir
        self.token = token
        self.guard: Any = lambda active: None
        self.stage_log = open(workdir / "stage.log", "a", buffering=1)  # noqa: SIM115
        self.stage = "started"
        self.mbs: Any = None
        self.user_post_step: dict[int, Any] = {}
        self.warnings: list[str] = []
        self.rows: list[tuple[float, Any]] = []
        self.inspector: Any = None  # an InspectionRecorder when the job asks for the model inspector
        self.motion: Any = None  # a MotionRecorder when the job asks for the bodies' motion (behaviour)
        self.sensor_rows: int | None = None  # keep the program's sensors (the agent's simulate)
        self.mark("started")

    def mark(self, stage: str) -> None:
        self.stage = stage
        self.stage_log.write(stage + "\n")

    def install(self) -> None:
        import exudyn as exu

        main_system = exu.MainSystem
        original_assemble = main_system.Assemble
        self._original_set_post = main_system.SetPostStepUserFunction
        harness = self

        def assemble(mbs: Any, *args: Any, **kwargs: Any) -> Any:
            if harness.stage == "started":
                harness.mark("reached_assemble")
            result = original_assemble(mbs, *args, **kwargs)
            harness.mbs = mbs
            if harness.stage in ("started", "reached_assemble"):
                harness.mark("finished_assemble")
            return result

        def hand_over(*args: Any, **kwargs: Any) -> Any:
            system = args[0] if args and isinstance(args[0], main_system) else kwargs.get("mbs")
            if system is not None:
                harness.mbs = system
            raise HandOver

        def set_post_step(mbs: Any, function: Any) -> Any:
            harness.user_post_step[id(mbs)] = function
            return None

        def noop(*args: Any, **kwargs: Any) -> Any:
            return None

        # bind the harness to the real accessors before the program could replace them
        data_class = type(exu.SystemContainer().AddSystem().systemData)
        self.api = {name: getattr(data_class, name) for name in (
            "GetODE2CoordinatesTotal", "NumberOfNodes", "NumberOfObjects", "NumberOfMarkers", "NumberOfLoads",
            "NumberOfSensors")}
        self.api.update({name: getattr(main_system, name) for name in (
            "GetNode", "GetObject", "GetMarker", "GetLoad", "GetSensor", "SetSensorParameter", "GetSensorStoredData",
            "ComputeSystemDegreeOfFreedom", "GetObjectOutputBody", "GetObjectOutput", "GetNodeOutput",
            "GetMarkerOutput", "GetNodeODE2Index")})
        # the inspector's enums, before the program could replace them with objects of its own
        self.api.update(OutputVariableType=exu.OutputVariableType, ConfigurationType=exu.ConfigurationType)
        main_system.Assemble = assemble
        main_system.SetPostStepUserFunction = set_post_step
        import exudyn.solver as solver

        targets: list[Any] = [main_system, exu, solver]
        try:
            import exudyn.utilities as utilities

            targets.append(utilities)
        except Exception:
            pass
        self._solver_patches: list[tuple[Any, str, Any]] = []
        for target in targets:
            for name in ("SolveDynamic", "SolveStatic"):
                if hasattr(target, name):
                    self._solver_patches.append((target, name, getattr(target, name)))
                    setattr(target, name, hand_over)
        for name in ("StartRenderer", "StopRenderer", "DoRendererIdleTasks"):
            setattr(exu, name, noop)
        for name in ("SolutionViewer", "PlotSensor", "DrawSystemGraph"):
            if hasattr(main_system, name):
                setattr(main_system, name, noop)
        try:
            import exudyn.interactive as interactive

            interactive.SolutionViewer = noop
        except Exception:
            pass

    def solve(self, sim_block: str, namespace: dict[str, Any]) -> None:
        """Run the ground truth's simulation block on the program's assembled system."""
        import exudyn

        mbs = self.mbs
        user_post = self.user_post_step.get(id(mbs))
        get_total = self.api["GetODE2CoordinatesTotal"]

        inspector = self.inspector
        motion = self.motion

        def record(system: Any, t: float) -> bool:
            self.rows.append((t, np.array(get_total(system.systemData))))
            if inspector is not None:
                inspector.after_step(t)
            if motion is not None:
                motion.after_step(t)
            if user_post is not None:
                return bool(user_post(system, t))
            return True

        for target, name, original in self._solver_patches:
            setattr(target, name, original)
        # sensor files are written from C++, past the audit hook, to any path the program named:
        # none are written (the harness records the coordinates itself)
        for index in range(self.api["NumberOfSensors"](mbs.systemData)):
            self.api["SetSensorParameter"](mbs, index, "writeToFile", False)
            if self.sensor_rows:  # the agent reads the program's sensors back: stored in memory
                self.api["SetSensorParameter"](mbs, index, "storeInternal", True)
        self._original_set_post(mbs, record)
        namespace["mbs"] = mbs
        namespace["exu"] = exudyn
        self.mark("solver_started")
        exec(compile(sim_block, "<simulation block>", "exec"), namespace)
        self.mark("solved")


# ----------------------------------------------------------------------------- capture


#: A sensor's fields that say what it reads (the rest is bookkeeping or file settings).
SENSOR_FIELDS = ("name", "sensorType", "outputVariableType", "bodyNumber", "nodeNumber", "markerNumber",
                 "objectNumber", "loadNumber", "localPosition")


def capture_sensors(mbs: Any, api: dict[str, Any], rows: int) -> list[dict[str, Any]]:
    """Every sensor of the program: what it reads and its stored values, at most ``rows`` rows
    (evenly picked, the first and last kept), each [t, value...]."""
    sensors = []
    for index in range(api["NumberOfSensors"](mbs.systemData)):
        fields = api["GetSensor"](mbs, index)
        entry: dict[str, Any] = {"index": index, **{k: to_jsonable(fields[k]) for k in SENSOR_FIELDS if k in fields}}
        for key in ("sensorType", "outputVariableType"):  # enums: their names, not their numbers
            if key in fields:
                entry[key] = str(fields[key]).rpartition(".")[2]
        try:
            data = np.atleast_2d(np.asarray(api["GetSensorStoredData"](mbs, index), dtype=float))
        except Exception as exc:  # a sensor Exudyn stores nothing for (e.g. no storeInternal support)
            entry["error"] = str(exc)
            sensors.append(entry)
            continue
        if data.size and len(data) > rows:
            data = data[np.unique(np.linspace(0, len(data) - 1, rows).round().astype(int))]
        entry["rows"] = data.tolist() if data.size else []
        sensors.append(entry)
    return sensors


def to_jsonable(value: Any) -> Any:
    """Item dict values to JSON: arrays to lists, index types to int, callables to a marker."""
    if callable(value) and not isinstance(value, type):
        return "<function>"
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, bool | int | float | str) or value is None:
        return value
    if isinstance(value, list | tuple):
        return [to_jsonable(v) for v in value]
    if isinstance(value, dict):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    try:
        return int(value)  # NodeIndex, ObjectIndex, MarkerIndex, ...
    except (TypeError, ValueError):
        return str(value)


#: Reduced FE matrices and mode bases of flexible bodies: both programs load the same part, and
#: the matrices would make the graph annotations megabytes large; they are left out.
REDUCED_FE_KEYS = frozenset({
    "massMatrixReduced", "stiffnessMatrixReduced", "dampingMatrixReduced", "modeBasis", "outputVariableModeBasis",
    "referencePositions", "mPsiTildePsi", "mPsiTildePsiTilde", "mPhitTPsi", "mPhitTPsiTilde", "mXRefTildePsi",
    "mXRefTildePsiTilde", "tempUserFunctionForce",
})


def capture_items(mbs: Any, api: dict[str, Any]) -> dict[str, list[dict[str, Any]]]:
    """Every item of the system as a plain dict, without visualization ('V*') entries and
    without the reduced FE matrices of flexible bodies."""
    items: dict[str, list[dict[str, Any]]] = {}
    data = mbs.systemData
    for kind in ("Node", "Object", "Marker", "Load", "Sensor"):
        count = api[f"NumberOf{kind}s"](data)
        getter = api[f"Get{kind}"]
        entries = []
        for i in range(count):
            raw = getter(mbs, i)
            entries.append({k: to_jsonable(v) for k, v in raw.items()
                            if not k.startswith("V") and k not in REDUCED_FE_KEYS})
        items[kind.lower() + "s"] = entries
    return items


def system_summary(mbs: Any, api: dict[str, Any]) -> dict[str, Any]:
    try:
        dof = api["ComputeSystemDegreeOfFreedom"](mbs)
        return {k: to_jsonable(v) for k, v in dof.items()}
    except Exception as exc:
        return {"error": str(exc)}
