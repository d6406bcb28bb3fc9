"""The model inspector's answer: a system view as text a model reads in one pass.

The default answer is bounded (about 2,000 tokens for the largest level-2 task): items of one kind
with the same parameters are summarised in one line, long lists are cut, and every cut says what
was left out and which argument brings it back (``bodies``, ``times``, ``quantities``).
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass

from meceng.agents.inspect.system import ANGLES, Body, BodyState, Connector, Load, SystemView
from meceng.agents.inspect.words import connector_line as _connector_line
from meceng.agents.inspect.words import name_of as _name_of
from meceng.agents.inspect.words import num, vec
from meceng.agents.inspect.words import value_text as _value

QUANTITIES = ("position", "angles", "velocity", "angular_velocity")


@dataclass(frozen=True)
class Ask:
    """What the model asked to see; empty means the default answer."""

    bodies: tuple[int, ...] = ()
    quantities: tuple[str, ...] = QUANTITIES
    max_items: int = 12  # per list in the default answer

    @property
    def focused(self) -> bool:
        return bool(self.bodies)


def _state(body: Body, state: BodyState, quantities: Sequence[str]) -> str:
    parts = []
    if "position" in quantities:
        parts.append(f"position {vec(state.position)}")
    if "angles" in quantities and state.angles is not None and body.kind != "MassPoint":
        parts.append(f"angles {vec(state.angles)}")
    if "velocity" in quantities and state.velocity is not None:
        parts.append(f"velocity {vec(state.velocity)}")
    if "angular_velocity" in quantities and state.angular_velocity is not None and body.kind != "MassPoint":
        parts.append(f"angular velocity {vec(state.angular_velocity)}")
    return ", ".join(parts)


def _body_line(body: Body, ask: Ask) -> str:
    facts = []
    if body.mass is not None:
        facts.append(f"mass {num(body.mass)}")
    if body.kind in ("RigidBody", "FlexibleBody") and any(abs(c) > 1e-12 for c in body.centre_local):
        origin = "its floating frame's origin" if body.kind == "FlexibleBody" else "its reference point"
        facts.append(f"centre of mass {vec(body.centre_local)} from {origin} (body axes)")
    if body.principal_inertia is not None:
        facts.append(f"principal inertia {vec(body.principal_inertia)}")
    start = body.state_at(0.0)
    if start is not None:
        facts.append(_state(body, start, ask.quantities))
    return f"{body.label}: " + ", ".join(f for f in facts if f)


def _group_key(c: Connector) -> tuple[str, str]:
    return c.kind, ", ".join(f"{k} {_value(v)}" for k, v in sorted(c.parameters.items()))


def _cut(lines: list[str], limit: int, what: str, how: str) -> list[str]:
    if len(lines) <= limit:
        return lines
    return [*lines[:limit], f"  … {len(lines) - limit} more {what} not shown: {how}"]


def render(view: SystemView, stage: str, error: str | None, ask: Ask | None = None,
           end_time: float | None = None) -> str:
    """The inspector's answer for one run of the program."""
    ask = ask or Ask()
    lines = [f"stage: {stage}" + (f"; error: {error}" if error else " (no error)"),
             f"conventions: global frame, SI units; positions are centres of mass; {ANGLES}"]
    movers = view.moving_bodies()
    counts: dict[str, int] = defaultdict(int)
    for item in (*view.bodies, *view.connectors):
        counts[item.kind] += 1
    total = sum(b.mass for b in movers if b.mass is not None)
    lines.append(f"system: {', '.join(f'{n} {k}' for k, n in counts.items())}; "
                 f"{len(view.loads)} loads; degrees of freedom {view.degrees_of_freedom}, redundant constraints "
                 f"{view.redundant_constraints}; total mass {num(total)}")
    shown = [b for b in movers if not ask.focused or b.index in ask.bodies]
    hint = "call again with bodies=[#numbers] to see those bodies"
    lines.append("bodies at t = 0:")
    limit = len(shown) if ask.focused else ask.max_items
    lines += [f"  {_body_line(b, ask)}" for b in shown[:limit]]
    if len(shown) > limit:
        groups: dict[tuple[str, str], list[int]] = defaultdict(list)
        for b in shown[limit:]:
            groups[(b.kind, "?" if b.mass is None else num(b.mass))].append(b.index)
        kinds = "; ".join(f"{len(n)} {kind} of mass {mass} ({_numbers(n)})" for (kind, mass), n in groups.items())
        lines.append(f"  … {len(shown) - limit} more bodies not shown: {kinds}; {hint}")
    grounds = [b for b in view.bodies if b.is_ground]
    if grounds:
        lines.append("  ground: " + ", ".join(b.label for b in grounds))
    lines += _connectors(view, ask)
    lines += _loads(view, ask)
    lines += _motion(view, shown, ask, end_time)
    lines += _ranges(view, shown, ask)
    return "\n".join(lines)


def _numbers(indices: list[int]) -> str:
    """#13–#25, #86: runs of object numbers folded."""
    runs: list[list[int]] = []
    for i in indices:
        if runs and i == runs[-1][-1] + 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    return ", ".join(f"#{r[0]}–#{r[-1]}" if len(r) > 2 else ", ".join(f"#{i}" for i in r) for r in runs)


def _touches(c: Connector, ask: Ask) -> bool:
    return not ask.focused or any(b in ask.bodies for b in c.bodies if b is not None)


def _connectors(view: SystemView, ask: Ask) -> list[str]:
    chosen = [c for c in view.connectors if _touches(c, ask)]
    if not chosen:
        return []
    out = ["connectors (at t = 0):"]
    groups: dict[tuple[str, str], list[Connector]] = defaultdict(list)
    for c in chosen:
        groups[_group_key(c)].append(c)
    if ask.focused or len(chosen) <= ask.max_items:
        return out + [f"  {_connector_line(view, c)}" for c in chosen]
    for (kind, params), members in groups.items():
        first = members[0]
        lengths = [c.derived.get("initial_length") for c in members if "initial_length" in c.derived]
        extra = f"; initial lengths {num(min(lengths))}…{num(max(lengths))}" if lengths else ""
        gaps = [c.derived["initial_gap"] for c in members if "initial_gap" in c.derived]
        extra += f"; initial gaps {num(min(gaps))}…{num(max(gaps))}" if gaps else ""
        numbers = ", ".join(f"#{c.index}" for c in members[:6]) + (" …" if len(members) > 6 else "")
        out.append(f"  {len(members)} × {kind} ({numbers}){': ' + params if params else ''}{extra}"
                   if len(members) > 1 else f"  {_connector_line(view, first)}")
    return _cut(out, ask.max_items + 1, "connector groups", "call again with bodies=[#numbers]")


def _loads(view: SystemView, ask: Ask) -> list[str]:
    chosen = [load for load in view.loads if not ask.focused or load.body in ask.bodies]
    if not chosen:
        return []
    groups: dict[tuple[str, str], list[int | None]] = defaultdict(list)
    for load in chosen:
        if load.vector is None:  # a user function: its own line, with its values where it was called
            vector = f"#{load.index} given by a user function" + _load_values(load)
        else:
            vector = vec(load.vector)
        fixed = " (body-fixed)" if load.body_fixed else ""
        groups[(load.kind, vector + fixed)].append(load.body)
    out = ["loads:"]
    for (kind, vector), bodies in groups.items():
        if vector.startswith("#"):
            _, _, rest = vector.partition(" ")
            out.append(f"  {kind} on {_name_of(view, bodies[0])}: {rest}")
            continue
        targets = ", ".join(_name_of(view, b) for b in bodies[:4]) + (f" and {len(bodies) - 4} more" if len(bodies) > 4
                                                                      else "")
        out.append(f"  {kind} {vector} on {targets}")
    return out


def _load_values(load: Load) -> str:
    if not load.values:
        return " (not evaluated: no sampled state)"
    return "; its values (the function called at the sampled states): " + ", ".join(
        f"t={num(t)} {value if isinstance(value, str) else vec(value)}" for t, value in load.values)


def _motion(view: SystemView, shown: list[Body], ask: Ask, end_time: float | None) -> list[str]:
    times = [t for t in view.times if t > 0]
    if not times:
        return ["motion: no state after t = 0 (the solver did not advance)"]
    bodies = shown if ask.focused else shown[: max(1, min(len(shown), ask.max_items // max(len(times), 1)))]
    out = ["motion (sampled):"]
    for t in times:
        for body in bodies:
            state = body.state_at(t)
            if state is not None:
                out.append(f"  t={num(state.t)} {body.label}: {_state(body, state, ask.quantities)}")
    if len(bodies) < len(shown):
        out.append(f"  … motion of {len(shown) - len(bodies)} more bodies not shown: call again with "
                   "bodies=[#numbers]; times=[...] picks other times")
    if end_time is not None and times[-1] < end_time * (1 - 1e-6):
        out.append(f"  the run ended at t={num(times[-1])} before the end time {num(end_time)}")
    return out


def _ranges(view: SystemView, shown: list[Body], ask: Ask) -> list[str]:
    indices = {b.index for b in shown}
    per_body: dict[int, list[str]] = defaultdict(list)
    for r in view.ranges:
        if r.body in indices:
            per_body[r.body].append(f"{r.name} [{num(r.low)}, {num(r.high)}]")
    if not per_body:
        return []
    lines = [f"  {_name_of(view, b)}: " + ", ".join(parts) for b, parts in per_body.items()]
    return ["ranges over the run (reference points, every step):",
            *_cut(lines, len(lines) if ask.focused else ask.max_items, "bodies",
                  "call again with bodies=[#numbers]")]
