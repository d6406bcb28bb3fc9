"""``self_check``'s energy balance read against the motion's own energy, beside what in the system
dissipates or feeds energy.

The total's size depends on where gravity's potential is zero: a pendulum that lost half its energy
in two impacts read "-5.35 %" against a total of -1.5 J. So the change is said as a fraction of the
motion's energy (the larger of its largest kinetic energy and the swing of gravity's potential, from
the motion record: ``energy.py``), beside the elements that dissipate or feed energy (contacts with
their restitution, dampers, drives, loads whose work the total leaves out), so that a loss the system
explains reads differently from one it does not.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Any

import numpy as np

from meceng.agents.energy import gravity_potential, kinetic_energy
from meceng.inspect.bodies import numbers
from meceng.inspect.system import SystemView
from meceng.inspect.words import name_of

#: A change below this fraction of the motion's energy is the integrator's own (generalised-alpha
#: damps a little); above it, the answer says whether the system's elements explain it.
KEPT = 1e-2
DISSIPATE, FEED = ("dissipates", "dissipate"), ("feeds or takes energy", "feed or take energy")


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


def _contact(item: dict[str, Any]) -> str | None:
    """What dissipates in a contact, in words with its numbers; None for an elastic one."""
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
    return "; ".join(said) or None


def energy_elements(view: SystemView, items: dict[str, list[dict[str, Any]]]) -> tuple[list[str], list[str]]:
    """(elements that dissipate energy, elements that feed or take it: drives, loads whose work the
    total leaves out), in words with the numbers that say how much; alike ones in one line."""
    objects = items.get("objects", [])
    found: dict[tuple[tuple[str, str], str, str], list[tuple[int, str]]] = defaultdict(list)
    for c in view.connectors:
        item = objects[c.index] if 0 <= c.index < len(objects) else {}
        user = [k for k, v in item.items() if "UserFunction" in k and _user(v)]
        lost = _contact(item) if "Contact" in c.exudyn_type else None
        if "SpringDamper" in c.exudyn_type and _number(item, "damping") > 0 and not user:
            lost = f"damping {_number(item, 'damping'):.4g}"
        if lost:
            found[(DISSIPATE, c.kind, lost)].append((c.index, c.label))
        if user:
            found[(FEED, c.kind, f"its {', '.join(user)} sets its force or motion")].append((c.index, c.label))
        elif "SpringDamper" in c.exudyn_type and any(_number(item, k) > 0 for k in ("force", "torque",
                                                                                     "velocityOffset")):
            found[(FEED, c.kind, "a constant force, torque or velocity offset")].append((c.index, c.label))
    for load, raw in zip(view.loads, items.get("loads", []), strict=False):
        label = f"{load.kind} on {name_of(view, load.body)}"
        if load.vector is None:
            found[(FEED, label, "a user function")].append((load.index, label))
        elif str(raw.get("loadType", "")) not in ("MassProportional", "ForceVector") or load.body_fixed:
            found[(FEED, label, "its work is not in the total")].append((load.index, label))
    out: dict[tuple[str, str], list[str]] = {DISSIPATE: [], FEED: []}
    for (verb, kind, what), members in found.items():
        if len(members) == 1:
            out[verb].append(f"{members[0][1]} {verb[0]}: {what}")
        else:
            out[verb].append(f"{len(members)} × {kind} ({numbers([i for i, _ in members])}) {verb[1]}: {what}")
    return out[DISSIPATE], out[FEED]


def energy_balance(start: float, end: float, motion: dict[str, Any] | None, view: SystemView | None,
                   items: dict[str, list[dict[str, Any]]] | None) -> dict[str, Any]:
    """The change of the total against the motion's own energy, and whether the system's elements
    explain it: ``explained`` True, False, or None (kept)."""
    change = end - start
    report: dict[str, Any] = {"start": start, "end": end, "change": change}
    series = kinetic_energy(motion)
    if series is not None and len(series[1]):
        k = int(np.argmax(series[1]))
        report["kinetic_max"], report["kinetic_max_time"] = float(series[1][k]), float(series[0][k])
    potential = gravity_potential(motion, items)
    if potential is not None and len(potential):
        report["gravity_swing"] = float(np.ptp(potential))
    motion_energy = max(report.get("kinetic_max", 0.0), report.get("gravity_swing", 0.0))
    if motion_energy > 1e-12:
        report["motion_energy"] = motion_energy
    report["relative_change"] = change / (report.get("motion_energy") or max(abs(start), abs(end), 1e-12))
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
        parts = []
        if "kinetic_max" in report:
            parts.append(f"its largest kinetic energy {report['kinetic_max']:.4g} J at t = "
                         f"{report['kinetic_max_time']:.4g} s")
        if "gravity_swing" in report:
            parts.append(f"the swing of gravity's potential {report['gravity_swing']:.4g} J")
        numbers += (f", {100 * report['relative_change']:.3g} % of the motion's energy {report['motion_energy']:.4g} "
                    f"J (the larger of {' and '.join(parts)}" if len(parts) > 1 else
                    f", {100 * report['relative_change']:.3g} % of the motion's energy ({parts[0]}")
        numbers += "; the total's own size depends on where gravity's potential is zero and says nothing)"
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
