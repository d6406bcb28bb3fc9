"""Where ``compare``'s tolerances come from, in words a model can check against its own motion.

A tolerance is a fraction of a scale of the motion; said only as "of the range of speeds, 37.63
m/s", a model cannot tell which of its bodies set it, nor check it against its own motion. So each
scale is named with its source (which body, which quantity) and the fastest centre of mass is said
beside the speed scale.

The numbers and their candidates are the comparison's own (``eval/bodies``: ``travel_sources``,
``speed_sources``, ``rim_sources``); here they are only put in words: the scale is the smaller of the
two motions' scales, so the side whose largest candidate equals it is the one named. A scale none of
them explains is said with its number alone.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from meceng.eval.agreement import finite_head
from meceng.eval.bodies import (
    TRAVEL_FLOOR,
    BodyMotion,
    Scales,
    ScaleSource,
    largest,
    rim_sources,
    speed_sources,
    travel_sources,
)
from meceng.inspect.words import num as _num

#: A (side, label of a body) namer: ``("A", 3) -> "A's #3 RigidBody"``.
Label = Callable[[str, int], str]
Sources = Callable[[list[BodyMotion]], list[ScaleSource]]


def _same(a: float, b: float) -> bool:
    return bool(np.isfinite(a) and np.isfinite(b) and abs(a - b) <= 1e-9 * max(abs(a), abs(b), 1e-300))


def _words(source: ScaleSource, side: str, bodies: list[BodyMotion], label: Label) -> str:
    body = next((b for b in bodies if b.index == source.body), None)
    name = label(side, source.body) if source.body is not None else side
    duration = float(bodies[0].t[-1] - bodies[0].t[0]) if len(bodies[0].t) > 1 else 1.0
    if source.what == "travel":
        return f"the farthest a centre of mass travels: {name}, the box around its path"
    if source.what == "travel_floor":
        return (f"{100 * TRAVEL_FLOOR:g} % of {side}'s system size (its floor: no centre of mass travels "
                "farther)")
    if source.what == "velocity_spread":
        return f"the spread of {side}'s centre-of-mass velocities (the diagonal of the box around all of them)"
    if source.what == "mean_speed":
        return f"{name}'s travel over the {_num(duration)} s run"
    size = body.size if body is not None else 0.0
    return (f"{name}'s |ω|·r: its largest angular speed {_num(source.value / size if size else 0.0)} rad/s at "
            f"its inertia radius r = √(3·J_max/m) = {_num(size)} m (a point there, not its centre of mass, moves "
            "that fast)")


def _source(value: float, sides: dict[str, list[BodyMotion]], label: Label, sources: Sources) -> str | None:
    for side, bodies in sides.items():
        if bodies:
            finite = finite_head(bodies)
            found = sources(finite)
            if found and _same(largest(found).value, value):
                return _words(largest(found), side, finite, label)
    return None


def fastest_centre(sides: dict[str, list[BodyMotion]], label: Label) -> str | None:
    """The fastest centre of mass of either program, at any sampled time: what the speed scale is to
    be read against."""
    best: tuple[float, str] | None = None
    for side, bodies in sides.items():
        for b in finite_head(bodies) if bodies else []:
            if len(b.v):
                speed = float(np.max(np.linalg.norm(b.v, axis=1)))
                if best is None or speed > best[0]:
                    best = (speed, label(side, b.index))
    return None if best is None else f"the fastest centre of mass, {best[1]}, moves at {_num(best[0])} m/s"


def scale_words(relative: float, scale: Scales, sides: dict[str, list[BodyMotion]], label: Label) -> str:
    """Positions, velocities and rotations: each tolerance, the scale it is a fraction of and where
    that comes from."""
    percent = f"{_num(100 * relative)} %"
    travel = _source(scale.travel, sides, label, travel_sources)
    speed = _source(scale.speed, sides, label, speed_sources)
    rim = _source(scale.turning, sides, label, rim_sources) if scale.turning > scale.speed else None
    fastest = fastest_centre(sides, label)
    positions = (f"positions within {_num(relative * scale.travel)} m ({percent} of {_num(scale.travel)} m"
                 + (f", {travel})" if travel else ", the motions' travel scale)"))
    velocities = (f"centre-of-mass velocities within {_num(relative * scale.speed)} m/s ({percent} of "
                  f"{_num(scale.speed)} m/s" + (f", {speed}" if speed else ", the motions' speed scale")
                  + (f"; {fastest}" if fastest else "") + ")")
    turning = (f"angular velocities and axes by what moves a point at the body's inertia radius as much: within "
               f"{_num(relative * scale.turning)} m/s there ({percent} of {_num(scale.turning)} m/s, "
               + (rim if rim else "the centres' speed scale, no body turning faster") + ")")
    return f"{positions}; {velocities}; {turning}"
