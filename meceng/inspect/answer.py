"""The model inspector's answer: a system view as text a model reads in one pass.

The default answer is bounded (about 2,000 tokens for the largest level-2 task): items of one kind
with the same parameters are summarised in one line, long lists are cut, and every cut says what
was left out and which argument brings it back (``bodies``, ``times``, ``quantities``).
"""

from __future__ import annotations

from collections import defaultdict

from meceng.inspect.bodies import Ask, bodies_section, motion_section, numbers, ranges_section
from meceng.inspect.orientation import CONVENTION
from meceng.inspect.system import Connector, Load, SystemView
from meceng.inspect.words import connector_line as _connector_line
from meceng.inspect.words import name_of as _name_of
from meceng.inspect.words import num, vec
from meceng.inspect.words import value_text as _value


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
             f"conventions: global frame, SI units; positions are centres of mass; inertia about the centre of mass in "
             f"body axes; {CONVENTION}"]
    movers = view.moving_bodies()
    counts: dict[str, int] = defaultdict(int)
    for item in (*view.bodies, *view.connectors):
        counts[item.kind] += 1
    total = sum(b.mass for b in movers if b.mass is not None)
    load_counts: dict[str, int] = defaultdict(int)
    for load in view.loads:
        load_counts[load.kind.split(" (")[0]] += 1
    per_kind = f" ({', '.join(f'{n} {k}' for k, n in load_counts.items())})" if view.loads else ""
    lines.append(f"system: {', '.join(f'{n} {k}' for k, n in counts.items())}; "
                 f"{len(view.loads)} loads{per_kind}; degrees of freedom {view.degrees_of_freedom}, "
                 f"redundant constraints {view.redundant_constraints}; total mass {num(total)}")
    shown = [b for b in movers if not ask.focused or b.index in ask.bodies]
    lines += bodies_section(view, shown, ask)
    grounds = [b for b in view.bodies if b.is_ground]
    if grounds:
        lines.append("  ground: " + ", ".join(b.label for b in grounds))
    lines += _connectors(view, ask)
    lines += _loads(view, ask)
    lines += motion_section(view, shown, ask, end_time)
    lines += ranges_section(view, shown, ask)
    return "\n".join(lines)


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
    out = ["loads (n × : n alike loads, one on each body named):"]
    for (kind, vector), bodies in groups.items():
        if vector.startswith("#"):
            _, _, rest = vector.partition(" ")
            out.append(f"  {kind} on {_name_of(view, bodies[0])}: {rest}")
            continue
        if len(bodies) == 1:
            out.append(f"  {kind} {vector} on {_name_of(view, bodies[0])}")
            continue
        on = [b for b in bodies if b is not None]
        targets = numbers(sorted(on)) + (f" and {len(bodies) - len(on)} node coordinates" if len(on) < len(bodies)
                                         else "")
        out.append(f"  {len(bodies)} × {kind} {vector}, one on each of {targets}")
    return _cut(out, ask.max_items + 1, "load lines", "call again with bodies=[#numbers]")


def _load_values(load: Load) -> str:
    if not load.values:
        return " (not evaluated: no sampled state)"
    return "; its values (the function called at the sampled states): " + ", ".join(
        f"t={num(t)} {value if isinstance(value, str) else vec(value)}" for t, value in load.values)
