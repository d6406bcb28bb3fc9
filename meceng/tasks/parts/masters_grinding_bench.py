"""Master parameters of the grinding bench (assembly 80: spindle part 62 + housing part 61).

The spindle turns in two bearing seats at the ends of the motor housing, so the parts share

- ``spindle_radius``: radius of the spindle's bearing journals = radius of the housing's bore;
- ``housing_length``: length of the housing along the spindle axis; the journals end at
  x = -housing_length/2 and x = +housing_length/2 of the spindle frame;
- ``bearing_length``: thickness of the housing's two end walls = length of each bearing bore =
  length of each spindle journal, so the interfaces 'bearing_left' / 'bearing_right' of the two
  parts have the same extent and centre when the spindle is placed;
- ``axis_height``: height of the spindle axis above the housing's bottom face (housing only; the
  assembly needs it to place the spindle).

Placement in the assembly (housing frame = global frame, z up, spindle axis along x): the spindle
frame is the housing frame shifted by (0, 0, axis_height).
"""

from __future__ import annotations

from meceng.tasks.base import Param

SPINDLE_RADIUS = Param("spindle_radius", 0.009, 0.013, "m")
HOUSING_LENGTH = Param("housing_length", 0.2, 0.28, "m")
BEARING_LENGTH = Param("bearing_length", 0.02, 0.03, "m")
AXIS_HEIGHT = Param("axis_height", 0.12, 0.15, "m")

GRINDING_BENCH_MASTERS = (SPINDLE_RADIUS, HOUSING_LENGTH, BEARING_LENGTH, AXIS_HEIGHT)
