"""Master parameters of the rotor / bearing-block family (parts 51, 52, 53, 66), shared with the
assemblies 73 rotor in bearing block (51 + 52), 74 rotor in bearing block with pedestal (66 + 52) and
75 rotor in two bearing blocks with pedestal (53 + 66 twice).

- ``shaft_radius``: radius of the rotors' bearing seats = radius of the blocks' bores (the seat sits
  in the bore, so the interfaces 'left'/'right' of a rotor and 'bore' of a block coincide).
- ``bearing_width``: width of a block along the bore axis = length of a rotor's bearing seat; a
  block's bore and a rotor's seat have the same length, so their interface centres can coincide.
- ``axis_height``: height of the bore axis above a block's bottom face (its 'bottom' interface,
  bolted to the ground); the rotor's axis lies this high above the ground in an assembly. It is
  larger than every unbalanced rotor's disc radius (<= 0.09 m), so the disc clears the ground.
- ``bearing_span``: distance along the axis between the centres of a rotor's two bearing seats;
  in assembly 75 the two blocks stand this far apart.

Frames, for placing the parts: a block has its bottom-face centre at its origin, the bore axis along
x at (y, z) = (0, axis_height), the bore centre at (0, 0, axis_height). A rotor has its axis on the
x-axis starting at x = 0; the unbalanced rotor (52) has its seat centres at x = bearing_width/2 and
bearing_width/2 + bearing_span, the balanced rotor (53) at x = end_length + bearing_width/2 and
end_length + bearing_width/2 + bearing_span (``end_length`` is 53's own parameter).
"""

from __future__ import annotations

from meceng.tasks.base import Param

SHAFT_RADIUS = Param("shaft_radius", 0.012, 0.018, "m")
BEARING_WIDTH = Param("bearing_width", 0.04, 0.06, "m")
AXIS_HEIGHT = Param("axis_height", 0.1, 0.12, "m")
BEARING_SPAN = Param("bearing_span", 0.3, 0.45, "m")

#: every master of the family; a part lists the ones it uses in ``master=``
ROTOR_MASTERS = (SHAFT_RADIUS, BEARING_WIDTH, AXIS_HEIGHT, BEARING_SPAN)
#: the masters of a bearing block (parts 51, 66)
BLOCK_MASTERS = (SHAFT_RADIUS, BEARING_WIDTH, AXIS_HEIGHT)
#: the masters of a rotor (parts 52, 53)
SHAFT_MASTERS = (SHAFT_RADIUS, BEARING_WIDTH, BEARING_SPAN)


def names(params: tuple[Param, ...]) -> tuple[str, ...]:
    return tuple(p.name for p in params)
