"""Run a ground-truth program in the test process and return its trajectory.

Used by the physics tests, which check ground truths against what mechanics predicts. The
pipeline itself never runs programs in-process; it uses the isolated executor.
"""

from __future__ import annotations

import numpy as np

from meceng.tasks.registry import default_registry

SOLVE = "mbs.SolveDynamic(simulationSettings)"


def params(slug: str, seed: int, **changes) -> dict:
    """The sampled parameters of a task instance, with some of them changed."""
    values = dict(default_registry().get(slug).sample_params(seed))
    values.update(changes)
    return values


def program_for(slug: str, values: dict, seed: int = 0) -> str:
    """The ground-truth program of ``slug`` for the given parameter values."""
    return default_registry().get(slug).reference_program(values, "", seed)


def reference(slug: str, seed: int, **changes) -> tuple[dict, str]:
    """(parameters, ground-truth program) of an instance, with some parameters changed."""
    values = params(slug, seed, **changes)
    return values, program_for(slug, values, seed)


def perturb(program: str, old: str, new: str) -> str:
    """Replace a text that must occur exactly once (a deliberately wrong ground truth)."""
    assert program.count(old) == 1, old
    return program.replace(old, new)


def retime(program: str, *, refine: int = 1, spectral_radius: float | None = None, end_time: float | None = None,
           extra: str = "") -> str:
    """More steps, a longer time at the same step size, a non-dissipative integrator, extra settings."""
    key_steps = "simulationSettings.timeIntegration.numberOfSteps = "
    key_end = "simulationSettings.timeIntegration.endTime = "
    start = program.index(key_steps) + len(key_steps)
    stop = program.index("\n", start)
    steps = int(program[start:stop])
    t_start = program.index(key_end) + len(key_end)
    t_stop = program.index("\n", t_start)
    old_end = float(program[t_start:t_stop])
    new_end = old_end if end_time is None else end_time
    if refine != 1 or end_time is not None:
        program = program[:start] + str(round(steps * refine * new_end / old_end)) + program[stop:]
        t_start = program.index(key_end) + len(key_end)
        t_stop = program.index("\n", t_start)
        program = program[:t_start] + repr(new_end) + program[t_stop:]
    lines = [extra] if extra else []
    if spectral_radius is not None:
        lines.append(f"simulationSettings.timeIntegration.generalizedAlpha.spectralRadius = {spectral_radius}")
    return program.replace(SOLVE, "\n".join([*lines, SOLVE])) if lines else program


def stored_sensor(mbs, sensor, times: np.ndarray) -> np.ndarray:
    """A sensor's stored values, one row per recorded step (time column dropped)."""
    data = np.asarray(mbs.GetSensorStoredData(sensor))
    _, first = np.unique(data[:, 0], return_index=True)
    data = data[np.sort(first)]
    assert len(data) == len(times) and np.allclose(data[:, 0], times)
    return data[:, 1:]


def simulate(program: str) -> tuple[np.ndarray, np.ndarray, object]:
    """Execute ``program`` and return (times, q_total per step, the MainSystem).

    ``q_total = q_ref + q`` of all ODE2 coordinates, one row per time step including t = 0.
    """
    if SOLVE not in program:
        raise ValueError("program has no standard simulation block")
    rows: list[tuple[float, np.ndarray]] = []

    def record(mbs, t):  # post-step user function
        rows.append((t, np.array(mbs.systemData.GetODE2CoordinatesTotal())))
        return True

    hooked = program.replace(SOLVE, f"_hook(mbs)\n{SOLVE}")
    namespace: dict = {"__name__": "__meceng_test__"}

    def hook(mbs):
        namespace["_mbs"] = mbs
        rows.append((0.0, np.array(mbs.systemData.GetODE2CoordinatesTotal())))
        mbs.SetPostStepUserFunction(record)

    namespace["_hook"] = hook
    exec(compile(hooked, "<reference>", "exec"), namespace)
    times = np.array([r[0] for r in rows])
    # the solver may report t = 0 itself; keep the first row per time
    _, first = np.unique(times, return_index=True)
    first.sort()
    q = np.array([rows[i][1] for i in first])
    return times[first], q, namespace["_mbs"]


_BODY_SENSORS = """
_bodySensors = {}
for _o in range(mbs.systemData.NumberOfObjects()):
    _type = mbs.GetObject(_o)['objectType']
    if _type == 'RigidBody' or (_withPoints and _type == 'MassPoint'):
        _names = ['Position', 'Velocity']
        if _type == 'RigidBody':
            _names += ['AngularVelocity', 'RotationMatrix']
        _bodySensors[_o] = {
            _name: mbs.AddSensor(SensorBody(bodyNumber=_o, storeInternal=True, writeToFile=False,
                                            outputVariableType=getattr(exu.OutputVariableType, _name)))
            for _name in _names}
mbs.variables['_bodySensors'] = _bodySensors
"""


def simulate_bodies(program: str, mass_points: bool = False) -> tuple[np.ndarray, np.ndarray, list[dict]]:
    """Run with sensors on every rigid body (and mass point, if asked), in creation order.

    Returns (times, q_total, bodies); each body is a dict of arrays, one row per step: Position,
    Velocity (n, 3), and for rigid bodies AngularVelocity (n, 3) and RotationMatrix (n, 3, 3).
    """
    assert program.count("mbs.Assemble()") == 1
    sensors = f"_withPoints = {mass_points!r}\n" + _BODY_SENSORS
    program = program.replace("mbs.Assemble()", sensors + "mbs.Assemble()")
    program = program.replace(SOLVE, f"simulationSettings.solution.sensors.writePeriod = 0\n{SOLVE}")
    times, q, mbs = simulate(program)
    bodies = []
    for _obj, body_sensors in sorted(mbs.variables["_bodySensors"].items()):
        data = {}
        for name, sensor in body_sensors.items():
            values = stored_sensor(mbs, sensor, times)
            data[name] = values.reshape(-1, 3, 3) if name == "RotationMatrix" else values
        bodies.append(data)
    return times, q, bodies


def cuboid(density: float, sides: tuple[float, float, float]) -> tuple[float, np.ndarray]:
    """Mass and principal inertia (about the centre, local axes) of a homogeneous cuboid."""
    a, b, c = sides
    m = density * a * b * c
    return m, np.diag([m * (b * b + c * c), m * (a * a + c * c), m * (a * a + b * b)]) / 12


def kinetic_energy(body: dict[str, np.ndarray], m: float, j_local: np.ndarray) -> np.ndarray:
    """Translational + rotational kinetic energy of a rigid body per time step."""
    v, w, rot = body["Velocity"], body["AngularVelocity"], body["RotationMatrix"]
    j_global = rot @ j_local @ np.transpose(rot, (0, 2, 1))
    return 0.5 * m * np.sum(v * v, axis=1) + 0.5 * np.einsum("ni,nij,nj->n", w, j_global, w)


def planar_angle(q: np.ndarray, i0: int, axis: int) -> np.ndarray:
    """Unwrapped rotation angle about a fixed global axis (1, 2, 3 = x, y, z) from Euler parameters."""
    return np.unwrap(2 * np.arctan2(q[:, i0 + 3 + axis], q[:, i0 + 3]))
