"""Items in words: numbers, vectors and connector lines as the inspector writes them (one place, so
the answer and the picture's words agree)."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from meceng.inspect.coordinates import SAID as COORDINATE_SAID
from meceng.inspect.coordinates import constraint_words, end_words
from meceng.inspect.geometry import edges_words, rolling_frame, rolling_words
from meceng.inspect.system import Connector, SystemView, direction


def num(x: float) -> str:
    """Four significant digits; round-off below 1e-12 shows as 0."""
    text = f"{0.0 if abs(x) < 1e-12 else x:.4g}"
    return "0" if text in ("-0", "0", "-0.0") else text


def vec(values: Iterable[float] | None) -> str:
    return "?" if values is None else "(" + ", ".join(num(v) for v in values) + ")"


def name_of(view: SystemView, index: int | None) -> str:
    if index is None:
        return "a node coordinate"
    body = view.body(index)
    return body.label if body is not None else f"#{index}"


def connector_line(view: SystemView, c: Connector) -> str:
    coordinates = c.geometry.get("coordinates")
    if coordinates is not None:  # a coordinate connector: each end is one coordinate, not a body
        ends = " — ".join(end_words(k, lambda b: name_of(view, b)) for k in coordinates)
    else:
        ends = " — ".join(name_of(view, b) for b in c.bodies)
    facts = [f"{c.label}: {ends}"]
    points = [p for p in c.points if p is not None]
    said = _SAID.get(c.exudyn_type, frozenset())  # said above in global terms
    if coordinates is not None:
        if c.exudyn_type == "ConnectorCoordinate":  # what it holds, in Exudyn's equation
            facts[0] += ": " + constraint_words(coordinates, c.parameters, c.geometry.get("user_offset", False),
                                                lambda b: name_of(view, b), num)
            said = COORDINATE_SAID
    elif "corners" in c.geometry:
        facts.append(_triangle(c))
    elif "axis_local" in c.geometry:
        facts += rolling_words(c.geometry, rolling_frame(c.geometry, c.points[1], c.geometry.get("disc_rotation")),
                               vec, direction)
    elif points:
        same = len(points) == 2 and np.allclose(points[0], points[1], atol=1e-9)
        facts.append(f"at {vec(points[0])}" if same or len(points) == 1 else "at " + " and ".join(map(vec, points)))
    if c.axis is not None and not c.free:
        facts.append(f"axis {vec(c.axis)}")
    if c.free:
        facts.append(f"free: {c.free}")
    if c.locked:
        facts.append(f"locked: {c.locked}")
    facts.extend(f"{k} {value_text(v)}" for k, v in c.parameters.items() if k != "constrainedAxes" and k not in said)
    facts.extend(f"{k.replace('_', ' ')} {num(v)}" for k, v in c.derived.items())
    if c.user_function:
        facts.append(_user_values(c))
    if c.idle:
        facts.append("set but without effect here: "
                     + ", ".join(f"{k} {value_text(v)} ({why})" for k, (v, why) in c.idle.items()))
    return ", ".join(facts)


_SAID = {"JointRollingDisc": frozenset({"discRadius", "discAxis", "planeNormal", "planePosition"}),
         "ContactSphereTriangle": frozenset({"sphereRadius", "includeEdges"})}


def value_text(v: object) -> str:
    if isinstance(v, bool):
        return str(v).lower()
    if isinstance(v, int | float):
        return num(float(v))
    if isinstance(v, list):
        return vec(np.ravel(np.asarray(v, dtype=float)))
    return str(v)




def _triangle(c: Connector) -> str:
    """A sphere-triangle contact: where the sphere is, the triangle's corners, normal and the gap."""
    g = c.geometry
    centre = c.points[0] if c.points else None
    side = "+" if g["side"] > 0 else "-"
    normal = direction(tuple(float(x) for x in g["normal"]))
    return (f"sphere (radius {num(g['radius'])}) centred at {vec(centre)}; triangle corners "
            + ", ".join(vec(p) for p in g["corners"])
            + f" (global), normal {normal} (right-hand rule over the corners in order); the sphere's centre is on "
            f"its {side} side; either side acts alike: the contact pushes the sphere away from the triangle on the "
            "side its centre is on (a centre that passes through the triangle is pushed out on the other side); "
            f"contact with {edges_words(int(g.get('edges', 7)))}; gap {num(g['gap'])} (centre to the triangle minus "
            "the radius; negative: penetrating)")


_OUTPUTS = {"TorqueLocal": ("torque", "N·m"), "ForceLocal": ("force", "N"), "Force": ("force", "N")}
_INPUTS = {"Rotation": ("rotation", "rad"), "Distance": ("length", "m"), "Displacement": ("displacement", "m")}


def _user_values(c: Connector) -> str:
    """A connector given by a user function: what it applied at each sampled time (Exudyn's connector
    output, which is the function's value) and what it was given, so a drive's sign and size show."""
    what = _OUTPUTS.get(next((v.get("value_name", "") for _, v in c.values if "value_name" in v), ""),
                        ("force or torque", ""))
    head = f"{c.user_function}: its {what[0]} at the sampled states"
    if what[0] == "torque":
        head += " (itemNumbers[1] receives minus it)"
    if not c.values:
        return head + ": not evaluated (no sampled state)"
    said = []
    for t, v in c.values:
        if "value" not in v:
            said.append(f"t={num(t)}: raised {v.get('error', 'an error')}")
            continue
        value = v["value"]
        text = num(value[0]) if len(value) == 1 else vec(value)
        text += f" {what[1]}" if what[1] else ""
        given = _INPUTS.get(str(v.get("input_name", "")))
        if given is not None and v.get("input") is not None:
            put = v["input"]
            text += f" at {given[0]} {num(put[0]) if len(put) == 1 else vec(put)} {given[1]}"
        said.append(f"t={num(t)}: {text}")
    return head + ": " + "; ".join(said)
