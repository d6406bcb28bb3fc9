"""The energy check of ``self_check``: code run around the program's solver call that prints the
total mechanical energy at start and end, and the parser of that line."""

from __future__ import annotations

import json

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
