"""Master parameters of the door hinge (parts 63 and 64, assembly 81 "door hinge").

The hinge has three knuckles of equal length along the hinge axis (the z-axis): the gap-side leaf
carries the lower and the upper knuckle, the pin-side leaf the middle knuckle and the pin. For the
two leaves to fit, they share the pin radius (= the gap-side knuckles' bore radius), the knuckle
length and outer radius, the leaf thickness and the clearance by which each leaf's notch is deeper
than the other leaf's knuckle radius.

Ranges: a heavy door or gate hinge, 60-90 mm long, with 4.5-6 mm leaves. The knuckle wall (outer
radius minus pin radius) is at least 4 mm, so with maxh = leaf_thickness / 2 (2.2-3 mm) both the
leaf and the wall get about two elements and every combination stays below ~5000 nodes.
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant

HINGE_MASTERS = (
    Param("pin_radius", 0.004, 0.005, "m"),
    Param("knuckle_outer_radius", 0.009, 0.011, "m"),
    Param("knuckle_length", 0.02, 0.03, "m"),
    Param("leaf_thickness", 0.0045, 0.006, "m"),
    Param("knuckle_clearance", 0.0005, 0.0015, "m"),
)

HINGE_MASTER_NAMES = tuple(p.name for p in HINGE_MASTERS)


def exact(value: float) -> float:
    """A sum or multiple of drawn values without float noise (they have at most 3 significant digits)."""
    return float(round(value, 9))


def hinge_derive(v: dict) -> dict:
    """Positions both leaves' texts and programs use: the hinge length, the knuckle ends, the notch
    depth, and the screw holes (midway between the notch and the leaf's outer edge)."""
    knuckle = v["knuckle_length"]
    notch_depth = exact(v["knuckle_outer_radius"] + v["knuckle_clearance"])
    return {
        "hinge_length": exact(3 * knuckle),
        "knuckle_top": exact(2 * knuckle),
        "notch_depth": notch_depth,
        "hole_x": round_significant((notch_depth + v["leaf_width"]) / 2, 3),
        "hole_z1": exact(knuckle / 2),
        "hole_z2": exact(5 * knuckle / 2),
    }
