"""Orientation that reads right for spinning bodies: one convention everywhere.

A body's orientation is said as its local axes in global terms (the columns of its rotation matrix)
and, where it turns, as the rotation accumulated about the body axis it turns about most since
t = 0: the sum over every step of the step's rotation expressed in body axes, never wrapped. A wheel
rolling about its local y axis reads "turned 44.2 rad about local y", not as Tait-Bryan angles that
jump by 2π and make plain spinning look like tumbling. The same numbers give the sampled states and
the ranges over the run, so the two agree.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from meceng.inspect.system import Body, Spin, direction

CONVENTION = ("orientation: a body's local axes x and y in global terms (z = x × y); 'turned': the rotation since "
              "t = 0 about the body axis it turns about most (its angular velocity along that axis integrated, not "
              "wrapped)")
_AXES = "xyz"


def _rotations(node_type: str, q: np.ndarray) -> Rotation | None:
    """Every step's rotation of a node from its coordinates (reference + displacement)."""
    if node_type == "RigidBodyEP" and q.shape[1] >= 7:
        ep = q[:, 3:7]
        return Rotation.from_quat(np.column_stack([ep[:, 1:], ep[:, 0]]))
    if node_type == "RigidBodyRxyz" and q.shape[1] >= 6:
        return Rotation.from_euler("XYZ", q[:, 3:6])
    if node_type in ("RigidBodyRotVecLG", "RigidBodyRotVec") and q.shape[1] >= 6:
        return Rotation.from_rotvec(q[:, 3:6])
    return None


def spins(bodies: tuple[Body, ...], nodes: list[dict[str, Any]], ode2: dict[str, int],
          trajectory: np.ndarray | None, times: np.ndarray | None) -> dict[int, Spin]:
    """Accumulated rotation of every rigid body with a 3D rotation node, from the run's every step."""
    if trajectory is None or times is None or len(times) != len(trajectory) or len(times) < 2:
        return {}
    out: dict[int, Spin] = {}
    for body in bodies:
        if body.node is None or str(body.node) not in ode2 or body.node >= len(nodes):
            continue
        node = nodes[body.node]
        start = ode2[str(body.node)]
        width = 7 if str(node.get("nodeType")) == "RigidBodyEP" else 6
        if start + width > trajectory.shape[1]:
            continue
        # the trajectory holds total coordinates (reference included)
        rotations = _rotations(str(node.get("nodeType", "")), trajectory[:, start:start + width])
        if rotations is None:
            continue
        steps = (rotations[:-1].inv() * rotations[1:]).as_rotvec()  # each step's rotation in body axes
        accumulated = np.vstack([np.zeros(3), np.cumsum(steps, axis=0)])
        axis = int(np.argmax(np.abs(accumulated).max(axis=0)))
        out[body.index] = Spin(axis, np.asarray(times, dtype=float), accumulated[:, axis])
    return out


def axes_text(rotation: np.ndarray) -> str:
    """The body's local axes in global terms, or that they are the global ones."""
    if np.allclose(rotation, np.eye(3), atol=1e-9):
        return "axes = global axes"
    return "axes " + ", ".join(f"{_AXES[k]}→{direction(_clean(rotation[:, k]))}" for k in range(2))


def _clean(vector: np.ndarray) -> tuple[float, ...]:
    """Round-off to zero and unit length kept, so an axis along a global one is named by it."""
    v = np.where(np.abs(vector) < 1e-9, 0.0, vector)
    return tuple(float(x) for x in v / (np.linalg.norm(v) or 1.0))


def turned_text(spin: Spin | None, t: float) -> str:
    if spin is None or t <= 0:
        return ""
    angle = spin.at(t)
    if abs(angle) < 1e-9:
        return ""
    return f"turned {angle:.4g} rad ({angle / (2 * np.pi):.3g} turns) about {spin.name}"
