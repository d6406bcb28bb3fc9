"""Where ``compare``'s tolerances come from, in words a model can check against its own motion.

A tolerance is a fraction of a scale of the motion (``eval/bodies.scales``); said only as "of the
range of speeds, 37.63 m/s", a model that knows no centre of mass of its gyroscope moves faster than
0.15 m/s cannot tell that the scale is the disc's rim speed, and reads a velocity check four times
looser than it is as a real one. So each scale is named with its source (which body, which quantity)
and the fastest centre of mass is said beside the speed scale.

The numbers are the comparison's own (``Agreement.scales``); here they are only explained: the
candidate sources are recomputed from both programs' motions and the one equal to the scale named. A
scale none of them explains (the comparison changed its rule) is said with its number alone.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np

from meceng.eval.bodies import TRAVEL_FLOOR, BodyMotion, Scales
from meceng.inspect.words import num as _num

#: A (side, label of a body) namer: ``("A", 3) -> "A's #3 RigidBody"``.
Label = Callable[[str, int], str]


def _same(a: float, b: float) -> bool:
    return bool(np.isfinite(a) and np.isfinite(b) and abs(a - b) <= 1e-9 * max(abs(a), abs(b), 1e-300))


def _finite(bodies: list[BodyMotion]) -> list[BodyMotion]:
    """The bodies' samples up to the first non-finite state (as the comparison takes its scales)."""
    n = min((len(b.t) for b in bodies), default=0)
    for b in bodies:
        bad = ~np.all(np.isfinite(b.p[:n]) & np.isfinite(b.v[:n]), axis=1)
        if b.w is not None:
            bad |= ~np.all(np.isfinite(b.w[:n]), axis=1)
        if bad.any():
            n = min(n, int(np.argmax(bad)))
    n = max(n, 1)
    return [BodyMotion(b.index, b.kind, b.mass, b.principal, b.axes, b.t[:n], b.p[:n], b.v[:n],
                       None if b.w is None else b.w[:n], None) for b in bodies]


def _travel(b: BodyMotion) -> float:
    return float(np.linalg.norm(np.ptp(b.p, axis=0))) if len(b.p) else 0.0


def _size(bodies: list[BodyMotion]) -> float:
    positions = np.concatenate([b.p for b in bodies])
    return max(float(np.linalg.norm(np.ptp(positions, axis=0))) if len(positions) else 0.0,
               max(b.size for b in bodies), 1e-6)


def travel_sources(side: str, bodies: list[BodyMotion], label: Label) -> Iterable[tuple[float, str]]:
    """(value, words) of every candidate the position scale may be."""
    for b in bodies:
        yield _travel(b), f"the farthest a centre of mass travels: {label(side, b.index)}, the box around its path"
    yield TRAVEL_FLOOR * _size(bodies), (f"{100 * TRAVEL_FLOOR:g} % of {side}'s system size {_num(_size(bodies))} m "
                                         "(its floor: no centre of mass travels farther)")


def speed_sources(side: str, bodies: list[BodyMotion], label: Label) -> Iterable[tuple[float, str]]:
    """(value, words) of every candidate the speed scale may be."""
    velocities = np.concatenate([b.v for b in bodies])
    if len(velocities):
        yield (float(np.linalg.norm(np.ptp(velocities, axis=0))),
               f"the spread of {side}'s centre-of-mass velocities (the diagonal of the box around all of them)")
    for b in bodies:
        if b.w is not None and len(b.w) and b.size > 0:
            spin = float(np.max(np.linalg.norm(b.w, axis=1)))
            yield spin * b.size, (f"{label(side, b.index)}'s |ω|·r: its largest angular speed {_num(spin)} rad/s "
                                  f"at its inertia radius r = √(3·J_max/m) = {_num(b.size)} m (a point there, not "
                                  "its centre of mass, moves that fast)")
        if len(b.v):
            yield float(np.max(np.linalg.norm(b.v, axis=1))), f"{label(side, b.index)}'s largest centre-of-mass speed"
    duration = float(bodies[0].t[-1] - bodies[0].t[0]) if len(bodies[0].t) > 1 else 1.0
    for b in bodies:
        yield _travel(b) / max(duration, 1e-9), (f"{label(side, b.index)}'s travel {_num(_travel(b))} m over the "
                                                 f"{_num(duration)} s run")


def _source(value: float, sides: dict[str, list[BodyMotion]], label: Label,
            sources: Callable[[str, list[BodyMotion], Label], Iterable[tuple[float, str]]]) -> str | None:
    for side, bodies in sides.items():
        if bodies:
            for candidate, words in sources(side, _finite(bodies), label):
                if _same(candidate, value):
                    return words
    return None


def fastest_centre(sides: dict[str, list[BodyMotion]], label: Label) -> str | None:
    """The fastest centre of mass of either program, at any sampled time: what a speed scale set by
    a spinning body's rim is to be read against."""
    best: tuple[float, str] | None = None
    for side, bodies in sides.items():
        for b in _finite(bodies) if bodies else []:
            if len(b.v):
                speed = float(np.max(np.linalg.norm(b.v, axis=1)))
                if best is None or speed > best[0]:
                    best = (speed, label(side, b.index))
    return None if best is None else f"the fastest centre of mass, {best[1]}, moves at {_num(best[0])} m/s"


def scale_words(relative: float, scale: Scales, sides: dict[str, list[BodyMotion]], label: Label) -> str:
    """Positions and velocities: each tolerance, the scale it is a fraction of and where that comes from."""
    percent = f"{_num(100 * relative)} %"
    travel = _source(scale.travel, sides, label, travel_sources)
    speed = _source(scale.speed, sides, label, speed_sources)
    fastest = fastest_centre(sides, label)
    positions = (f"positions within {_num(relative * scale.travel)} m ({percent} of {_num(scale.travel)} m"
                 + (f", {travel})" if travel else ", the motions' travel scale)"))
    velocities = (f"velocities within {_num(relative * scale.speed)} m/s ({percent} of {_num(scale.speed)} m/s"
                  + (f", {speed}" if speed else ", the motions' speed scale")
                  + (f"; {fastest}" if fastest and (speed is None or "centre-of-mass speed" not in speed) else "")
                  + ")")
    return f"{positions}; {velocities}"

