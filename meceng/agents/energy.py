"""The energy check of ``self_check``: code run around the program's solver call that prints the
total mechanical energy at start and end, the parser of that line, and the motion's own energy at
the motion record's samples (kinetic energy, gravity's potential) that ``balance.py`` reads the
change against."""

from __future__ import annotations

import json
from typing import Any

import numpy as np

from meceng.eval.bodies import read_bodies

ENERGY_MARK = "MECENG_ENERGY "

#: Appended around the solver call by ``self_check``: total mechanical energy at start and end,
#: from Exudyn's own body kinetic energies and spring potentials plus the potential of gravity and
#: constant forces. Printed with a marker; it only ever describes the agent's own program.
ENERGY_CODE = """
def _meceng_energy(mbs):
    import json as _json
    import numpy as _np
    _out = exu.OutputVariableType
    energy = 0.0
    for _i in range(mbs.systemData.NumberOfObjects()):
        _type = mbs.GetObject(_i)['objectType']
        try:
            if _type in ('MassPoint', 'RigidBody', 'MassPoint2D', 'RigidBody2D'):
                energy += mbs.GetObjectOutputBody(_i, _out.KineticEnergy, localPosition=[0, 0, 0])
            elif 'SpringDamper' in _type:
                energy += mbs.GetObjectOutput(_i, _out.PotentialEnergy)
        except Exception:
            pass
    for _j in range(mbs.systemData.NumberOfLoads()):
        _load = mbs.GetLoad(_j)
        _marker = mbs.GetMarker(_load['markerNumber'])
        _body = _marker.get('bodyNumber')
        if _body is None or _load.get('loadVectorUserFunction', 0) != 0:
            continue
        _vector = _np.asarray(_load['loadVector'], dtype=float)
        if _load['loadType'] == 'MassProportional':
            _object = mbs.GetObject(_body)
            _com = list(_object.get('centerOfMass', [0, 0, 0]))
            _pos = mbs.GetObjectOutputBody(_body, _out.Position, localPosition=_com)
            energy -= float(_object.get('mass', 0.0)) * float(_np.dot(_vector, _pos))
        elif _load['loadType'] == 'ForceVector' and not _load.get('bodyFixed', False):
            _local = list(_marker.get('localPosition', [0, 0, 0]))
            _pos = mbs.GetObjectOutputBody(_body, _out.Position, localPosition=_local)
            energy -= float(_np.dot(_vector, _pos))
    return energy
"""


def parse_energy(stdout: str) -> tuple[float, float] | None:
    for line in reversed(stdout.splitlines()):
        if line.startswith(ENERGY_MARK):
            try:
                start, end = json.loads(line[len(ENERGY_MARK):])
                return float(start), float(end)
            except (ValueError, TypeError):
                return None
    return None


# ----------------------------------------------------------------------------- the motion's own energy


def kinetic_energy(motion: dict[str, Any] | None) -> tuple[np.ndarray, np.ndarray] | None:
    """(times, the bodies' total kinetic energy) at the motion record's samples: ½ m |v|² of each
    centre of mass plus ½ Σ J_k (ω · axis_k)² about its principal axes."""
    bodies = read_bodies(motion)
    if not bodies or not len(bodies[0].t):
        return None
    n = min(len(b.t) for b in bodies)
    total = np.zeros(n)
    for b in bodies:
        total += 0.5 * b.mass * np.sum(b.v[:n] ** 2, axis=1)
        axes = b.global_axes()
        if b.w is not None and b.principal is not None and axes is not None and b.principal.size == 3:
            along = np.einsum("ni,nik->nk", b.w[:n], axes[:n])  # ω in principal axes
            total += 0.5 * np.sum(b.principal * along ** 2, axis=1)
        elif b.w is not None and b.principal is not None and b.principal.size == 1:  # a 2D body: about z
            total += 0.5 * float(b.principal[0]) * b.w[:n, 2] ** 2
    return bodies[0].t[:n], total


def gravity_potential(motion: dict[str, Any] | None, items: dict[str, list[dict[str, Any]]] | None
                      ) -> np.ndarray | None:
    """Gravity's potential -Σ m g·p of the bodies' centres of mass at the motion record's samples,
    from the program's constant mass-proportional loads; None without any."""
    bodies = {b.index: b for b in read_bodies(motion) or []}
    if not bodies or items is None:
        return None
    markers = items.get("markers", [])
    n = min(len(b.t) for b in bodies.values())
    total, found = np.zeros(n), False
    for load in items.get("loads", []):
        marker = load.get("markerNumber")
        if load.get("loadType") != "MassProportional" or load.get("loadVectorUserFunction", 0) not in (0, None):
            continue
        body = markers[int(marker)].get("bodyNumber") if isinstance(marker, int) and 0 <= marker < len(markers) \
            else None
        vector = np.asarray(load.get("loadVector") or (0.0, 0.0, 0.0), dtype=float).ravel()
        if body is None or int(body) not in bodies or vector.size != 3:
            continue
        b = bodies[int(body)]
        total -= b.mass * (b.p[:n] @ vector)
        found = True
    return total if found else None
