"""The inspector's picture of a system: bodies, connectors, loads, coordinate ranges and their states,
in the global frame and SI units, as ``view.build_view`` makes them from one execution."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class BodyState:
    """A body at one time: centre of mass, orientation, velocity of the centre of mass, angular velocity."""

    t: float
    position: tuple[float, ...]
    rotation: np.ndarray | None = None  # 3x3, body to global
    velocity: tuple[float, ...] | None = None
    angular_velocity: tuple[float, ...] | None = None



@dataclass(frozen=True)
class Spin:
    """A body's accumulated rotation about one of its own axes, at every step of the run."""

    axis: int  # 0, 1, 2: local x, y, z
    times: np.ndarray
    angles: np.ndarray

    def at(self, t: float) -> float:
        return float(self.angles[int(np.argmin(np.abs(self.times - t)))])

    @property
    def name(self) -> str:
        return f"local {'xyz'[self.axis]}"


@dataclass(frozen=True)
class Body:
    index: int
    kind: str  # the catalog's name
    exudyn_type: str
    name: str | None  # the program's own name; None where Exudyn named it
    mass: float | None
    centre_local: tuple[float, ...]  # centre of mass in body coordinates
    principal_inertia: tuple[float, ...] | None  # about the centre of mass, ascending
    node: int | None
    principal_axes: np.ndarray | None = None  # columns: the principal axes in body coordinates
    inertia_local: np.ndarray | None = None  # 3x3 about the centre of mass, body axes
    states: tuple[BodyState, ...] = ()

    @property
    def label(self) -> str:
        return f"#{self.index} {self.kind}" + (f" '{self.name}'" if self.name else "")

    @property
    def is_ground(self) -> bool:
        return self.kind == "Ground"

    def state_at(self, t: float) -> BodyState | None:
        if not self.states:
            return None
        return min(self.states, key=lambda s: abs(s.t - t))


@dataclass(frozen=True)
class Connector:
    index: int
    kind: str
    exudyn_type: str
    name: str | None
    bodies: tuple[int | None, ...]  # object numbers of the connected bodies (None: not a body marker)
    points: tuple[tuple[float, ...] | None, ...]  # global marker positions at t = 0
    axis: tuple[float, ...] | None  # the joint's or spring's axis in global terms
    free: str = ""
    locked: str = ""
    parameters: dict[str, Any] = field(default_factory=dict)
    derived: dict[str, float] = field(default_factory=dict)  # initial length, gap, ...
    markers: tuple[int, ...] = ()
    geometry: dict[str, Any] = field(default_factory=dict)  # contact geometry (``geometry.py``)
    #: parameters the program set that do nothing there: name -> (value, why) (``acting.py``)
    idle: dict[str, tuple[Any, str]] = field(default_factory=dict)
    #: a user function's force or torque: its key, and at each sampled time what Exudyn applied (and the
    #: rotation, length or displacement the function was given), as the sandbox read it
    user_function: str = ""
    values: tuple[tuple[float, dict[str, Any]], ...] = ()

    @property
    def label(self) -> str:
        return f"#{self.index} {self.kind}" + (f" '{self.name}'" if self.name else "")


@dataclass(frozen=True)
class Load:
    index: int
    kind: str
    body: int | None
    point: tuple[float, ...] | None
    vector: tuple[float, ...] | None  # None: given by a user function
    body_fixed: bool = False
    #: a user function's values at the sampled times (evaluated in the sandbox); text where it raised
    values: tuple[tuple[float, tuple[float, ...] | str], ...] = ()

    @property
    def label(self) -> str:
        return f"load {self.index} {self.kind}"


@dataclass(frozen=True)
class CoordinateRange:
    body: int
    name: str  # x, y, z, rx, ry, rz, phi
    low: float
    high: float


@dataclass(frozen=True)
class SystemView:
    bodies: tuple[Body, ...]
    connectors: tuple[Connector, ...]
    loads: tuple[Load, ...]
    times: tuple[float, ...]  # the sample times with states (0 first)
    ranges: tuple[CoordinateRange, ...]
    degrees_of_freedom: int | None
    redundant_constraints: int | None
    marker_states: tuple[dict[int, tuple[float, ...]], ...] = ()  # marker positions at each sample time
    marker_rotations: tuple[dict[int, np.ndarray], ...] = ()  # rigid markers' rotations at each sample time
    spins: dict[int, Spin] = field(default_factory=dict)  # accumulated rotation per body (``orientation.py``)
    asked: tuple[tuple[float, ...], ...] = ()  # per sample time, the times the model asked that it answers
    steps: tuple[float | None, ...] = ()  # per sample time, the solver's step size there
    run_end: float | None = None  # the last time the solver reached (the requested times need not be it)

    def body(self, index: int) -> Body | None:
        return next((b for b in self.bodies if b.index == index), None)

    def moving_bodies(self) -> tuple[Body, ...]:
        return tuple(b for b in self.bodies if not b.is_ground)


def direction(vector: tuple[float, ...] | list[float] | None) -> str:
    """A direction: the axis's name where it is a global axis (``-y``), else its components."""
    if vector is None:
        return "?"
    for k, name in enumerate("xyz"):
        if len(vector) == 3 and abs(abs(vector[k]) - 1.0) < 1e-6 and sum(abs(v) for v in vector) < 1.0 + 1e-6:
            return ("-" if vector[k] < 0 else "") + name
    return "(" + ", ".join(f"{x:.4g}" for x in vector) + ")"
