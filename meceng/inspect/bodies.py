"""The inspector's bodies: every body in the default answer, in a compact form.

A small system gets one line per body (at t = 0, at each sampled time and over the run). A large
one (more than ``Ask.max_items`` moving bodies) keeps one line for each body that differs from the
others, and folds each family of alike bodies (same kind, mass and inertia; at least ``FAMILY``
of them) into one line that covers every member: where they are, how fast the fastest moves. So
no body is silently left out; what is cut says so where it is cut, with the argument that shows it.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from meceng.inspect.orientation import axes_text, turned_text
from meceng.inspect.system import Body, BodyState, SystemView, direction
from meceng.inspect.words import name_of, num, vec

QUANTITIES = ("position", "orientation", "velocity", "angular_velocity")
FAMILY = 4  # alike bodies folded into one line in a large system
MOTION_LINES = 24  # single bodies' lines in the default motion section
HINT = "call again with bodies=[#numbers] to see them one by one"


@dataclass(frozen=True)
class Ask:
    """What the model asked to see; empty means the default answer."""

    bodies: tuple[int, ...] = ()
    quantities: tuple[str, ...] = QUANTITIES
    max_items: int = 12  # per list in the default answer

    @property
    def focused(self) -> bool:
        return bool(self.bodies)


def numbers(indices: Sequence[int]) -> str:
    """#13–#25, #86: runs of object numbers folded."""
    runs: list[list[int]] = []
    for i in indices:
        if runs and i == runs[-1][-1] + 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    return ", ".join(f"#{r[0]}–#{r[-1]}" if len(r) > 2 else ", ".join(f"#{i}" for i in r) for r in runs)


def state_text(view: SystemView, body: Body, state: BodyState, quantities: Sequence[str]) -> str:
    parts = []
    if "position" in quantities:
        parts.append(f"position {vec(state.position)}")
    if "orientation" in quantities and state.rotation is not None and body.kind != "MassPoint":
        parts.append(axes_text(state.rotation))
        turned = turned_text(view.spins.get(body.index), state.t)
        if turned:
            parts.append(turned)
    if "velocity" in quantities and state.velocity is not None:
        parts.append(f"velocity {vec(state.velocity)}")
    if "angular_velocity" in quantities and state.angular_velocity is not None and body.kind != "MassPoint":
        parts.append(f"angular velocity {vec(state.angular_velocity)}")
    return ", ".join(parts)


def body_line(view: SystemView, body: Body, quantities: Sequence[str]) -> str:
    facts = []
    if body.mass is not None:
        facts.append(f"mass {num(body.mass)}")
    if body.kind in ("RigidBody", "FlexibleBody") and any(abs(c) > 1e-12 for c in body.centre_local):
        origin = "its floating frame's origin" if body.kind == "FlexibleBody" else "its reference point"
        facts.append(f"centre of mass {vec(body.centre_local)} from {origin} (body axes)")
    if body.principal_inertia is not None:
        facts.append(inertia_text(body))
    start = body.state_at(0.0)
    if start is not None:
        facts.append(state_text(view, body, start, quantities))
    return f"{body.label}: " + ", ".join(f for f in facts if f)


def inertia_text(body: Body) -> str:
    """Inertia about the centre of mass in the body's own axes (so a link's length along local y
    shows as a small Iyy), and where the axes are not principal, the principal axes' directions."""
    tensor = body.inertia_local
    if tensor is None:
        return f"inertia about z {vec(body.principal_inertia)}" if body.principal_inertia else ""
    text = f"inertia Ixx, Iyy, Izz {vec(np.diag(tensor))}"
    off = (tensor[1, 2], tensor[0, 2], tensor[0, 1])
    if max(abs(x) for x in off) <= 1e-9 * max(float(np.abs(tensor).max()), 1e-300):
        return text
    pairs = zip(body.principal_inertia or (), (body.principal_axes.T if body.principal_axes is not None else ()),
                strict=False)
    return (f"{text}, Iyz, Ixz, Ixy {vec(off)}; principal "
            + ", ".join(f"{num(value)} along {direction(_positive(axis))}" for value, axis in pairs)
            + " (body axes)")


def _positive(axis: np.ndarray) -> tuple[float, ...]:
    """An eigenvector's sign is arbitrary: its largest component is made positive (deterministic)."""
    axis = np.where(np.abs(axis) < 1e-12, 0.0, axis)
    sign = 1.0 if axis[int(np.argmax(np.abs(axis)))] > 0 else -1.0
    return tuple(float(x) + 0.0 for x in sign * axis)


def _signature(body: Body) -> tuple[str, str, str]:
    inertia = "" if body.principal_inertia is None else vec(body.principal_inertia)
    return body.kind, "?" if body.mass is None else num(body.mass), inertia


def split(view: SystemView, shown: list[Body], ask: Ask) -> tuple[list[Body], list[list[Body]]]:
    """Single bodies and families of alike ones: families only in a large system's default answer."""
    if ask.focused or len(shown) <= ask.max_items:
        return shown, []
    alike: dict[tuple[str, str, str], list[Body]] = defaultdict(list)
    for body in shown:
        alike[_signature(body)].append(body)
    families = [members for members in alike.values() if len(members) >= FAMILY]
    folded = {b.index for members in families for b in members}
    return [b for b in shown if b.index not in folded], families


def _spread(values: list[tuple[float, ...]]) -> str:
    array = np.asarray(values, dtype=float)
    low, high = array.min(axis=0), array.max(axis=0)
    if np.allclose(low, high, atol=1e-12):
        return f"all {vec(low)}"
    return f"from {vec(low)} to {vec(high)}"


def family_line(members: list[Body], t: float | None) -> str:
    """Every member of a family in one line: the box their positions fill, the fastest's speed."""
    first = members[0]
    head = f"{len(members)} × {first.kind}" + (f" of mass {num(first.mass)}" if first.mass is not None else "")
    head += f" ({numbers([b.index for b in members])})"
    states = [(b, b.state_at(t if t is not None else 0.0)) for b in members]
    states = [(b, s) for b, s in states if s is not None]
    if not states:
        return head + ": no state"
    facts = [f"positions {_spread([s.position for _, s in states])}"]
    speeds = [(float(np.linalg.norm(s.velocity)), b) for b, s in states if s.velocity is not None]
    if speeds:
        fastest, body = max(speeds, key=lambda x: x[0])
        facts.append("all at rest" if fastest < 1e-12 else f"fastest #{body.index} at speed {num(fastest)}")
    if t is None and first.principal_inertia is not None:
        facts.insert(0, inertia_text(first))
    return f"{head}: " + ", ".join(facts)


def bodies_section(view: SystemView, shown: list[Body], ask: Ask) -> list[str]:
    singles, families = split(view, shown, ask)
    lines = ["bodies at t = 0:"]
    limit = len(singles) if ask.focused else ask.max_items
    lines += [f"  {body_line(view, b, ask.quantities)}" for b in singles[:limit]]
    if len(singles) > limit:
        left = [b.index for b in singles[limit:]]
        lines.append(f"  … {len(left)} more bodies not shown here ({numbers(left)}): {HINT}")
    lines += [f"  {family_line(members, None)}" for members in families]
    return lines


def time_label(view: SystemView, t: float) -> str:
    """``t=0.5``: the time asked where the state's step says it to four digits; else the step's time
    and why it is not the one asked (the solver's steps do not meet it)."""
    k = view.times.index(t) if t in view.times else -1
    asked = view.asked[k] if 0 <= k < len(view.asked) else ()
    step = view.steps[k] if 0 <= k < len(view.steps) else None
    other = [a for a in asked if num(a) != num(t)]
    if not other:
        return f"t={num(t)}"
    there = f"; steps of {num(step)} s there" if step else ""
    return (f"t={num(t)} (the solver step nearest to the asked t = {', '.join(num(a) for a in other)}{there})")


def motion_section(view: SystemView, shown: list[Body], ask: Ask, end_time: float | None) -> list[str]:
    times = [t for t in view.times if t > 0]
    if not times:
        return ["motion: no state after t = 0 (the solver did not advance)"]
    singles, families = split(view, shown, ask)
    per_time = len(singles) if ask.focused else max(1, MOTION_LINES // len(times))
    out = ["motion (sampled):"]
    for t in times:
        label = time_label(view, t)
        for body in singles[:per_time]:
            state = body.state_at(t)
            if state is not None:
                out.append(f"  {label} {body.label}: {state_text(view, body, state, ask.quantities)}")
        out += [f"  {label} {family_line(members, t)}" for members in families]
        if len(singles) > per_time:
            left = [b.index for b in singles[per_time:]]
            out.append(f"  … t={num(t)}: {len(left)} more bodies not shown here ({numbers(left)}): {HINT}; "
                       "times=[...] picks other times")
    reached = view.run_end if view.run_end is not None else times[-1]
    if end_time is not None and reached < end_time * (1 - 1e-6):
        out.append(f"  the run ended at t={num(reached)} before the end time {num(end_time)}")
    return out


def ranges_section(view: SystemView, shown: list[Body], ask: Ask) -> list[str]:
    singles, families = split(view, shown, ask)
    per_body: dict[int, list[str]] = defaultdict(list)
    for r in view.ranges:
        per_body[r.body].append(f"{r.name} = {num(r.low)}" if num(r.low) == num(r.high)
                                else f"{r.name} [{num(r.low)}, {num(r.high)}]")
    lines = [f"  {name_of(view, b.index)}: " + ", ".join(per_body[b.index]) for b in singles if per_body[b.index]]
    limit = len(lines) if ask.focused else ask.max_items
    if len(lines) > limit:
        left = [b.index for b in singles if per_body[b.index]][limit:]
        lines = [*lines[:limit], f"  … {len(left)} more bodies not shown here ({numbers(left)}): {HINT}"]
    for members in families:
        indices = {b.index for b in members}
        names: dict[str, list[float]] = defaultdict(list)
        for r in view.ranges:
            if r.body in indices:
                names[r.name] += [r.low, r.high]
        if names:
            lines.append(f"  {len(members)} × {members[0].kind} ({numbers(sorted(indices))}), all of them: "
                         + ", ".join(f"{n} [{num(min(v))}, {num(max(v))}]" for n, v in names.items()))
    if not lines:
        return []
    return ["ranges over the run (reference points, every step):", *lines]
