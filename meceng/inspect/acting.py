"""Which of a contact's parameters act: what the program set, and what Exudyn uses there.

A contact item carries every parameter of its models (friction, adhesion, impact), most at Exudyn's
defaults; listed whole, ``frictionProportionalZone 0.001, contactStiffnessExponent 1, adhesionExponent
1`` read as if they were chosen and mattered. The inspector shows a parameter where it acts and was
set (or always matters: ``view._ALWAYS_SHOWN``), and says of a value the program set that does nothing
there (a friction zone without friction) that it does nothing, and why.

The defaults are Exudyn 1.13's (``exudyn.itemInterface``; tests/test_tools_truth.py checks them
against the installed Exudyn, so a new default shows as a failing test, not a wrong answer).
"""

from __future__ import annotations

from typing import Any

import numpy as np

_CONTACT = {"dynamicFriction": 0.0, "frictionProportionalZone": 0.001, "contactStiffness": 0.0,
            "contactDamping": 0.0, "contactStiffnessExponent": 1.0, "restitutionCoefficient": 1.0,
            "minimumImpactVelocity": 0.0, "impactModel": 0}

#: Exudyn's defaults of the contacts' parameters, per object type.
DEFAULTS: dict[str, dict[str, Any]] = {
    "ContactSphereSphere": {**_CONTACT, "isHollowSphere1": False, "constantPullOffForce": 0.0,
                            "contactPlasticityRatio": 0.0, "adhesionCoefficient": 0.0, "adhesionExponent": 1.0},
    "ContactSphereTriangle": {**_CONTACT, "includeEdges": 7},
    "ContactCoordinate": {key: _CONTACT[key] for key in ("contactStiffness", "contactDamping",
                                                         "contactStiffnessExponent", "restitutionCoefficient",
                                                         "minimumImpactVelocity", "impactModel")},
}

#: A parameter that acts only when another one is set: (that one, why it does nothing without it).
_NEEDS: dict[str, tuple[str, str]] = {
    "frictionProportionalZone": ("dynamicFriction", "no friction: dynamicFriction 0"),
    "adhesionExponent": ("adhesionCoefficient", "no adhesion: adhesionCoefficient 0"),
    "restitutionCoefficient": ("impactModel", "impactModel 0 uses contactDamping only"),
    "minimumImpactVelocity": ("impactModel", "impactModel 0 uses contactDamping only"),
}


#: Of those, the ones that act at their default value too once their condition holds (a friction
#: zone regularises any friction; restitution 1 is an elastic impact).
_ACTS_AT_DEFAULT = frozenset({"frictionProportionalZone", "restitutionCoefficient"})


def _equal(a: Any, b: Any) -> bool:
    try:
        return bool(np.allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=1e-12, atol=0.0))
    except (TypeError, ValueError):
        return a == b


def _set(value: Any) -> bool:
    try:
        return bool(np.any(np.asarray(value, dtype=float) != 0))
    except (TypeError, ValueError):
        return bool(value)


def sort_contact(exudyn_type: str, item: dict[str, Any], shown: frozenset[str]
                 ) -> tuple[dict[str, Any], dict[str, tuple[Any, str]]] | None:
    """(the parameters to show, {name: why it does nothing} of those set to no effect) of a contact;
    None for an item type this module does not know (the caller keeps its own rule)."""
    defaults = DEFAULTS.get(exudyn_type)
    if defaults is None:
        return None
    acting: dict[str, Any] = {}
    idle: dict[str, tuple[Any, str]] = {}
    for key, value in item.items():
        if key not in defaults and key not in shown:
            continue
        need = _NEEDS.get(key)
        if need is not None and not _set(item.get(need[0], defaults.get(need[0]))):
            if key in defaults and not _equal(value, defaults[key]):
                idle[key] = (value, need[1])
            continue
        if key in shown or key in _ACTS_AT_DEFAULT or key not in defaults or not _equal(value, defaults[key]):
            acting[key] = value
    return acting, idle
