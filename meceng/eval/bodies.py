"""Bodies and their motion as the behaviour comparison sees them, and how candidate bodies are
matched to the ground truth's.

What a physicist can observe of a body, whatever the program chose to write: its mass, its principal
moments of inertia about the centre of mass (ascending) and the principal axes, and over time the
centre of mass, its velocity, the angular velocity and the principal axes in global terms. Item
types, creation order, reference points and local axes are not part of it. Read from the motion
record the child writes (``tools/inspection.MotionRecorder``, ``Execution.motion``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import linear_sum_assignment

_E = np.eye(3)
#: The motion's range is taken as at least this fraction of the system's size.
TRAVEL_FLOOR = 1e-2


@dataclass(frozen=True)
class BodyMotion:
    """One body: its physics and its motion at the record's sample times (global frame, SI)."""

    index: int  # the program's object number
    kind: str  # Exudyn's object type, for messages only
    mass: float
    principal: np.ndarray | None  # principal moments about the centre of mass, ascending; None: a point
    axes: np.ndarray | None  # the principal axes in body coordinates (columns, in ``principal``'s order)
    t: np.ndarray  # (n,)
    p: np.ndarray  # (n, 3) centre of mass
    v: np.ndarray  # (n, 3) its velocity
    w: np.ndarray | None  # (n, 3) angular velocity (None: a mass point)
    rotation: np.ndarray | None  # (n, 3, 3) body to global
    points: np.ndarray | None = None  # (n, m, 3) a flexible body's interface markers: its deformation

    @property
    def size(self) -> float:
        """Radius of the body's inertia: sqrt(3 J_max / m) (a slender rod: half its length; a
        sphere: about its radius); 0 for a point."""
        if self.principal is None or self.mass <= 0:
            return 0.0
        return float(np.sqrt(max(3.0 * float(np.max(self.principal)) / self.mass, 0.0)))

    def global_axes(self) -> np.ndarray | None:
        """(n, 3, 3): the principal axes in global terms over time."""
        if self.axes is None or self.rotation is None:
            return None
        return self.rotation @ self.axes


def principal_inertia(inertia: list[float] | None, mass: float, com: list[float]
                      ) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Exudyn keeps a rigid body's inertia about its reference point (6 numbers xx, yy, zz, yz, xz,
    xy; a flexible body's 3x3; a 2D body's one moment about z): moved to the centre of mass, its
    principal values (ascending) and axes (columns, body coordinates)."""
    if inertia is None:
        return None, None
    values = np.asarray(inertia, dtype=float).ravel()
    if values.size == 1:
        return values.copy(), None
    if values.size == 9:
        tensor = values.reshape(3, 3)
    elif values.size == 6:
        xx, yy, zz, yz, xz, xy = values
        tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    else:
        return None, None
    c = np.asarray(com, dtype=float)[:3]
    tensor = tensor - mass * (float(c @ c) * _E - np.outer(c, c))
    principal, axes = np.linalg.eigh(0.5 * (tensor + tensor.T))
    return principal, axes


def read_bodies(motion: dict[str, Any] | None) -> list[BodyMotion] | None:
    """The bodies of one execution's motion record; None when there is none."""
    if not motion or "states" not in motion:
        return None
    states = np.asarray(motion["states"], dtype=float)
    t = np.asarray(motion["t"], dtype=float)
    points = np.asarray(motion.get("points", np.zeros((len(t), 0, 3))), dtype=float)
    owners = np.asarray(motion.get("point_bodies", np.zeros(0, dtype=int)), dtype=int)
    out = []
    for k, body in enumerate(motion.get("bodies", [])):
        mass = float(body.get("mass") or 0.0)
        rows = states[:, k, :] if states.ndim == 3 and k < states.shape[1] else np.zeros((len(t), 18))
        principal, axes = principal_inertia(body.get("inertia"), mass, body.get("com") or [0.0, 0.0, 0.0])
        w = rows[:, 6:9] if np.all(np.isfinite(rows[:, 6:9])) else None
        rotation = rows[:, 9:18].reshape(-1, 3, 3) if np.all(np.isfinite(rows[:, 9:18])) else None
        if w is None:
            principal, axes = None, None
        own = points[:, owners == k, :] if points.ndim == 3 and len(owners) == points.shape[1] else None
        out.append(BodyMotion(int(body.get("index", k)), str(body.get("type", "")), mass, principal, axes, t,
                              rows[:, 0:3], rows[:, 3:6], w, rotation, own if own is not None and own.size else None))
    return out


@dataclass(frozen=True)
class Scales:
    """The ground truth's own sizes, which every tolerance is a fraction of."""

    length: float  # the system's size: the box around every centre of mass over the whole run, or the largest body
    # the range of the centres of mass' velocities (at least travel / duration): what a centre of mass's
    # velocity is compared against. Not the rim speeds: a gyroscope's rim moves at 38 m/s while its
    # centre of mass never passes 0.15 m/s: at the rim's scale its velocity had a quarter of its size as tolerance
    speed: float
    duration: float
    # the motion's range: the farthest one centre of mass travels (the box around its path), at least
    # TRAVEL_FLOOR of the size (a truss deflects millimetres in metres; a disc spins in place)
    travel: float = 0.0
    # the rotations' scale: the largest rim speed (|w| times the body's inertia radius), at least
    # ``speed``; a body's angular velocity is compared at its inertia radius against it (0: ``speed``)
    rim: float = 0.0

    @property
    def turning(self) -> float:
        """The speed scale of angular quantities: the rim speed, never below the centres' speed."""
        return max(self.rim, self.speed)

    def to_json(self) -> dict[str, float]:
        return {"length_m": self.length, "travel_m": self.travel, "speed_m_s": self.speed,
                "rim_speed_m_s": self.turning, "duration_s": self.duration}


@dataclass(frozen=True)
class ScaleSource:
    """One candidate for a scale: its value, what it measures and of which body (None: all of them).

    A scale is the largest of its candidates; ``compare`` says which one it was, so the candidates
    are listed here, once, for both."""

    value: float
    what: str  # "travel", "travel_floor", "velocity_spread", "mean_speed", "rim_speed"
    body: int | None = None  # BodyMotion.index


def _length(bodies: list[BodyMotion]) -> float:
    positions = np.concatenate([b.p for b in bodies])
    size = max(b.size for b in bodies)
    return max(float(np.linalg.norm(np.ptp(positions, axis=0))) if len(positions) else 0.0, size, 1e-6)


def _duration(bodies: list[BodyMotion]) -> float:
    return max(float(bodies[0].t[-1] - bodies[0].t[0]) if len(bodies[0].t) > 1 else 1.0, 1e-9)


def _path(b: BodyMotion) -> float:
    return float(np.linalg.norm(np.ptp(b.p, axis=0))) if len(b.p) else 0.0


def travel_sources(bodies: list[BodyMotion]) -> list[ScaleSource]:
    """The position scale's candidates: each centre of mass's path (the box around it) and the floor."""
    return ([ScaleSource(_path(b), "travel", b.index) for b in bodies]
            + [ScaleSource(TRAVEL_FLOOR * _length(bodies), "travel_floor")])


def speed_sources(bodies: list[BodyMotion]) -> list[ScaleSource]:
    """The velocity scale's candidates: the spread of all centre-of-mass velocities and each centre's
    travel over the run (a slow creep still has a scale)."""
    velocities = np.concatenate([b.v for b in bodies])
    spread = float(np.linalg.norm(np.ptp(velocities, axis=0))) if len(velocities) else 0.0
    duration = _duration(bodies)
    return ([ScaleSource(spread, "velocity_spread")]
            + [ScaleSource(max(_path(b), TRAVEL_FLOOR * _length(bodies)) / duration, "mean_speed", b.index)
               for b in bodies])


def rim_sources(bodies: list[BodyMotion]) -> list[ScaleSource]:
    """The rotations' candidates: each body's largest angular speed times its inertia radius."""
    return [ScaleSource(float(np.max(np.linalg.norm(b.w, axis=1))) * b.size, "rim_speed", b.index)
            for b in bodies if b.w is not None and len(b.w)]


def largest(sources: list[ScaleSource]) -> ScaleSource:
    return max(sources, key=lambda s: s.value)


def scales(bodies: list[BodyMotion]) -> Scales:
    if not bodies:
        return Scales(1.0, 1.0, 1.0)
    travel = largest(travel_sources(bodies)).value
    speed = largest(speed_sources(bodies)).value
    rim = max((s.value for s in rim_sources(bodies)), default=0.0)
    return Scales(_length(bodies), speed, _duration(bodies), travel, max(rim, speed))


def _common(a: BodyMotion, b: BodyMotion) -> int:
    return min(len(a.t), len(b.t))


def match_cost(candidate: BodyMotion, truth: BodyMotion, scale: Scales) -> float:
    """How unlike two bodies are, as fractions of the ground truth's scales: mass, principal
    moments, where they start and how their centres of mass move (identical bodies are told apart
    by the last two)."""
    mass = abs(candidate.mass - truth.mass) / max(abs(truth.mass), 1e-12)
    inertia_scale = max(truth.mass * scale.length ** 2, 1e-12)
    if candidate.principal is not None and truth.principal is not None and \
            candidate.principal.size == truth.principal.size:
        inertia = float(np.max(np.abs(candidate.principal - truth.principal))) / max(
            float(np.max(truth.principal)), 1e-9 * inertia_scale)
    else:
        present = candidate.principal if candidate.principal is not None else truth.principal
        inertia = 0.0 if present is None else float(np.max(present)) / inertia_scale
    n = _common(candidate, truth)
    if n == 0:
        return mass + inertia + 1e6
    start = float(np.linalg.norm(candidate.p[0] - truth.p[0])) / scale.length
    motion = float(np.sqrt(np.mean(np.sum((candidate.p[:n] - truth.p[:n]) ** 2, axis=1)))) / scale.length
    return mass + inertia + start + motion


def match_bodies(candidates: list[BodyMotion], truths: list[BodyMotion], scale: Scales
                 ) -> list[tuple[int, int]]:
    """The assignment (positions in the two lists) of least total cost; with unequal numbers the
    surplus bodies stay unmatched."""
    if not candidates or not truths:
        return []
    cost = np.array([[match_cost(c, g, scale) for g in truths] for c in candidates])
    rows, columns = linear_sum_assignment(cost)
    return sorted((int(c), int(g)) for c, g in zip(rows, columns, strict=True))
