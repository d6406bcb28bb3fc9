"""Master parameters of the flexible beams (parts 54-57), shared with the flexible pendulum and
the cantilever beam (assemblies 76, 77): the beam's outer dimensions.

The four beams share the frame (left end face centre at the origin, axis along x) and the
interface names ('left' at x = 0, 'right' at x = beam_length), so one assembly text works with
any of them.

The height starts at 20 mm (not 15 mm): the fillet beam rounds its long edges with up to ~0.45
times the height, and Netgen refines curved faces by their radius whatever ``maxh`` says; below
~8 mm fillet radius a 0.8 m beam needs more than 6000 nodes. The width is never smaller than the
height (0.03 >= 0.03), so the height is the beam's thin direction for every combination.
"""

from __future__ import annotations

from meceng.tasks.base import Param

BEAM_MASTERS = (
    Param("beam_length", 0.4, 0.8, "m"),
    Param("beam_width", 0.03, 0.05, "m"),
    Param("beam_height", 0.02, 0.03, "m"),
)
