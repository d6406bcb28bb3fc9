"""The energy check of ``self_check``: code run around the program's solver call that prints the
total mechanical energy at start and end, the parser of that line, and the balance read against the
motion's own energy.

The total's size depends on where gravity's potential is zero: a pendulum that lost half its energy
in two impacts read "-5.35 %" against a total of -1.5 J. So the change is said as a fraction of the
motion's energy (its largest kinetic energy, from the motion record: ``eval/bodies.read_bodies``),
beside the elements that dissipate or feed energy (contacts with their restitution, dampers, drives,
loads whose work the total leaves out), so that a loss the system explains reads differently from
one it does not."""

from __future__ import annotations

import json
from typing import Any

import numpy as np

from meceng.eval.bodies import read_bodies
from meceng.inspect.system import SystemView

ENERGY_MARK = "MECENG_ENERGY "

#: Appended around the solver call by ``self_check``: total mechanical energy at start and end,
#: from Exudyn's own body kinetic energies and spring potentials plus the potential of gravity and
#: constant forces. Printed with a marker; it only ever describes the agent's own program.
ENERGY_CODE = """
def _meceng_energy(mbs):
    import json as _json
    import numpy as _np
    _out = exu.OutputVariableType
    energy = 0.0
    for _i in range(mbs.systemData.NumberOfObjects()):
        _type = mbs.GetObject(_i)['objectType']
        try:
            if _type in ('MassPoint', 'RigidBody', 'MassPoint2D', 'RigidBody2D'):
                energy += mbs.GetObjectOutputBody(_i, _out.KineticEnergy, localPosition=[0, 0, 0])
            elif 'SpringDamper' in _type:
                energy += mbs.GetObjectOutput(_i, _out.PotentialEnergy)
        except Exception:
            pass
    for _j in range(mbs.systemData.NumberOfLoads()):
        _load = mbs.GetLoad(_j)
        _marker = mbs.GetMarker(_load['markerNumber'])
        _body = _marker.get('bodyNumber')
        if _body is None or _load.get('loadVectorUserFunction', 0) != 0:
            continue
        _vector = _np.asarray(_load['loadVector'], dtype=float)
        if _load['loadType'] == 'MassProportional':
            _object = mbs.GetObject(_body)
            _com = list(_object.get('centerOfMass', [0, 0, 0]))
            _pos = mbs.GetObjectOutputBody(_body, _out.Position, localPosition=_com)
            energy -= float(_object.get('mass', 0.0)) * float(_np.dot(_vector, _pos))
        elif _load['loadType'] == 'ForceVector' and not _load.get('bodyFixed', False):
            _local = list(_marker.get('localPosition', [0, 0, 0]))
            _pos = mbs.GetObjectOutputBody(_body, _out.Position, localPosition=_local)
            energy -= float(_np.dot(_vector, _pos))
    return energy
"""


def parse_energy(stdout: str) -> tuple[float, float] | None:
    for line in reversed(stdout.splitlines()):
        if line.startswith(ENERGY_MARK):
            try:
                start, end = json.loads(line[len(ENERGY_MARK):])
                return float(start), float(end)
            except (ValueError, TypeError):
                return None
    return None


# ----------------------------------------------------------------------------- the balance, read against the motion

#: A change below this fraction of the motion's energy is the integrator's own (generalised-alpha
#: damps a little); above it, the answer says whether the system's elements explain it.
KEPT = 1e-2


def _user(value: Any) -> bool:
    """A user function as the captured items hold it: ``'<function>'`` or ``{'function': ..., 'type': 'Python'}``."""
    if isinstance(value, dict):
        value = value.get("function")
    return value not in (0, None, "", False)


def _number(item: dict[str, Any], key: str, default: float = 0.0) -> float:
    try:
        return float(np.max(np.abs(np.asarray(item.get(key, default), dtype=float))))
    except (TypeError, ValueError):
        return default


def kinetic_energy(motion: dict[str, Any] | None) -> tuple[np.ndarray, np.ndarray] | None:
    """(times, the bodies' total kinetic energy) at the motion record's samples: ½ m |v|² of each
    centre of mass plus ½ Σ J_k (ω · axis_k)² about its principal axes."""
    bodies = read_bodies(motion)
    if not bodies or not len(bodies[0].t):
        return None
    n = min(len(b.t) for b in bodies)
    total = np.zeros(n)
    for b in bodies:
        total += 0.5 * b.mass * np.sum(b.v[:n] ** 2, axis=1)
        axes = b.global_axes()
        if b.w is not None and b.principal is not None and axes is not None and b.principal.size == 3:
            along = np.einsum("ni,nik->nk", b.w[:n], axes[:n])  # ω in principal axes
            total += 0.5 * np.sum(b.principal * along ** 2, axis=1)
        elif b.w is not None and b.principal is not None and b.principal.size == 1:  # a 2D body: about z
            total += 0.5 * float(b.principal[0]) * b.w[:n, 2] ** 2
    return bodies[0].t[:n], total


def _contact(label: str, item: dict[str, Any]) -> tuple[str | None, str | None]:
    """(what dissipates in a contact, or None; what it stores and the total does not count)."""
    said = []
    model = int(_number(item, "impactModel"))
    e = _number(item, "restitutionCoefficient", 1.0)
    if model in (1, 2) and e < 1.0:
        said.append(f"restitution {e:.4g} (impact model {model}): an impact keeps about e² = {e * e:.3g} of its "
                    "normal approach energy")
    if _number(item, "contactDamping") > 0:
        said.append(f"contactDamping {_number(item, 'contactDamping'):.4g}")
    if _number(item, "dynamicFriction") > 0:
        said.append(f"friction {_number(item, 'dynamicFriction'):.4g}")
    if any(_number(item, k) > 0 for k in ("adhesionCoefficient", "constantPullOffForce", "contactPlasticityRatio")):
        said.append("adhesion or plasticity")
    stored = f"{label} stores energy while it is compressed, which the total does not count"
    return (f"{label} dissipates: " + "; ".join(said) if said else None), stored


def energy_elements(view: SystemView, items: dict[str, list[dict[str, Any]]]) -> tuple[list[str], list[str]]:
    """(elements that dissipate energy, elements that feed or take it: drives, loads whose work the
    total leaves out), each in words with the number that says how much."""
    objects = items.get("objects", [])
    raw_loads = items.get("loads", [])
    dissipate: list[str] = []
    feed: list[str] = []
    for c in view.connectors:
        item = objects[c.index] if 0 <= c.index < len(objects) else {}
        user = [k for k, v in item.items() if "UserFunction" in k and _user(v)]
        if "Contact" in c.exudyn_type:
            lost, _ = _contact(c.label, item)
            if lost:
                dissipate.append(lost)
        elif "SpringDamper" in c.exudyn_type and _number(item, "damping") > 0 and not user:
            dissipate.append(f"{c.label} dissipates: damping {_number(item, 'damping'):.4g}")
        if user:
            feed.append(f"{c.label} feeds or takes energy: its {', '.join(user)} sets its force or motion")
        elif "SpringDamper" in c.exudyn_type and any(_number(item, k) > 0 for k in ("force", "torque",
                                                                                     "velocityOffset")):
            feed.append(f"{c.label} feeds or takes energy: a constant force, torque or velocity offset")
    for load, raw in zip(view.loads, raw_loads, strict=False):
        kind = str(raw.get("loadType", ""))
        on = f"{load.kind} on #{load.body}" if load.body is not None else load.kind
        if load.vector is None:
            feed.append(f"{on} feeds or takes energy: a user function")
        elif kind not in ("MassProportional", "ForceVector") or load.body_fixed:
            feed.append(f"{on} feeds or takes energy: its work is not in the total")
    return dissipate, feed


def energy_balance(start: float, end: float, motion: dict[str, Any] | None, view: SystemView | None,
                   items: dict[str, list[dict[str, Any]]] | None) -> dict[str, Any]:
    """The change of the total against the motion's own energy (its largest kinetic energy), and
    whether the system's elements explain it: ``explained`` True, False, or None (kept)."""
    change = end - start
    report: dict[str, Any] = {"start": start, "end": end, "change": change}
    series = kinetic_energy(motion)
    if series is not None and len(series[1]) and float(np.max(series[1])) > 1e-12:
        k = int(np.argmax(series[1]))
        report["motion_energy"] = float(series[1][k])
        report["motion_energy_time"] = float(series[0][k])
    scale = report.get("motion_energy") or max(abs(start), abs(end), 1e-12)
    report["relative_change"] = change / scale
    dissipate, feed = energy_elements(view, items or {}) if view is not None else ([], [])
    report["dissipate"], report["feed"] = dissipate, feed
    if abs(report["relative_change"]) <= KEPT:
        report["explained"] = None
    else:
        report["explained"] = bool(feed) or (change < 0 and bool(dissipate))
    return report


def energy_words(report: dict[str, Any]) -> list[str]:
    """The balance as a model reads it: the numbers, the scale they are read against, what in the
    system can change them and whether that explains the change."""
    numbers = (f"energy (kinetic + spring + gravity/constant-force potential; contact, constraint and drive forces "
               f"not counted): {report['start']:.6g} J at t = 0, {report['end']:.6g} J at the end: a change of "
               f"{report['change']:.4g} J")
    if "motion_energy" in report:
        numbers += (f", {100 * report['relative_change']:.3g} % of the motion's energy, its largest kinetic energy "
                    f"{report['motion_energy']:.4g} J (at t = {report['motion_energy_time']:.4g} s; the total's own "
                    "size depends on where gravity's potential is zero and says nothing)")
    else:
        numbers += f" ({100 * report['relative_change']:.3g} % of the total: no body moves)"
    lines = [numbers]
    elements = report["dissipate"] + report["feed"]
    lines.append("what dissipates or feeds energy: " + ("; ".join(elements) if elements else
                                                        "nothing (no damper, lossy contact, drive or working load)"))
    if report["explained"] is None:
        lines.append(f"so: the energy is kept (within {100 * KEPT:g} % of the motion's energy)")
    elif report["explained"]:
        lines.append("so: a " + ("loss" if report["change"] < 0 else "gain") + " the elements above can explain")
    else:
        lines.append("so: a " + ("loss" if report["change"] < 0 else "gain") + " no element of the system explains: "
                     "check the initial velocities against the constraints, the loads and the units")
    return lines
