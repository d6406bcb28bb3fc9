"""Master parameters of the flexible table (part 58), shared with the flexible table with load
(assembly 78): what the assembly needs to place the table on the floor and to find its feet.

The table's frame has its origin at the centre of the top plate (the plate's centre of mass), so
the feet's bottom faces lie at z = -(plate_thickness / 2 + leg_height): the assembly must lift the
part by that amount to stand it on a floor at z = 0 (the paper's reported LLM error: lifting it by
the leg height alone). The foot centres are at x = +-(table_length / 2 - leg_inset - leg_size / 2),
y = +-(table_width / 2 - leg_inset - leg_size / 2).

Ranges: the legs always carry at least ~24 % of the volume (4 * 0.05^2 * 0.45 against
0.8 * 0.55 * 0.03 and the pad), so a 5 % error in the leg height moves the mass by more than 1 %;
the plate is at least 20 mm thick and at most 0.8 m x 0.55 m, so maxh = plate_thickness keeps the
largest table below ~5500 nodes. The legs (<= 0.05 + 0.07 m from the edges) stay clear of the
load pad (<= 0.15 m square) on the narrowest plate.
"""

from __future__ import annotations

from meceng.tasks.base import Param

TABLE_MASTERS = (
    Param("table_length", 0.6, 0.8, "m"),
    Param("table_width", 0.4, 0.55, "m"),
    Param("plate_thickness", 0.02, 0.03, "m"),
    Param("leg_height", 0.45, 0.7, "m"),
    Param("leg_size", 0.05, 0.07, "m"),
    Param("leg_inset", 0.02, 0.05, "m"),
)
