"""Master parameters of the flexible slider-crank parts (parts 67-72), shared with the flexible
slider crank assemblies (83 simple: parts 67, 68, 69; 84 advanced: parts 70, 71, 72).

- ``crank_length``: distance between the crank's two joint axes (ground pin 'hole_a' at the
  origin, crank pin 'hole_b' at x = crank_length).
- ``rod_length``: distance between the rod's two joint axes (crank pin 'hole_a' at the origin,
  slider pin 'hole_b' at x = rod_length); at least twice the crank length for every draw, so the
  mechanism can turn fully.
- ``pin_radius``: radius of every joint hole/bore (and so of the pins of the assembly).
- ``thickness``: thickness along z (the joint axis) of the crank's and the rod's joint regions;
  the mid-plane of crank and rod is z = 0, so the mechanism moves in the xy-plane.

Every part's own ranges keep its geometry valid for any combination of these values.
"""

from __future__ import annotations

from meceng.tasks.base import Param

SLIDER_CRANK_MASTERS = (
    Param("crank_length", 0.05, 0.08, "m"),
    Param("rod_length", 0.16, 0.26, "m"),
    Param("pin_radius", 0.005, 0.008, "m"),
    Param("thickness", 0.010, 0.016, "m"),
)


def masters(*names: str) -> tuple[Param, ...]:
    """The master parameters with the given names, in the order given."""
    by_name = {p.name: p for p in SLIDER_CRANK_MASTERS}
    return tuple(by_name[n] for n in names)
