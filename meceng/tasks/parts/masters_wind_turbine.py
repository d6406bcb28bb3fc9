"""Master parameters of the simplified wind turbine (assembly 79: tower part 59 + rotor part 60).

The rotor's shaft sits in the nacelle's horizontal bore, so the two parts share

- ``shaft_radius``: radius of the rotor shaft = radius of the nacelle bore (the paper's example of
  a master parameter);
- ``nacelle_length``: length of the nacelle along the rotor axis = length of the bore = length of
  the rotor shaft, so the shaft's cylindrical surface (rotor interface 'shaft') and the bore
  (tower interface 'bore') have the same extent and the same centre when the rotor is placed;
- ``hub_height``: height of the bore axis above the ground (used by the tower only; the assembly
  needs it to place the rotor).

Placement in the assembly (tower frame = global frame, z up, rotor axis along x): the rotor frame
is the tower frame shifted by (-nacelle_length/2, 0, hub_height); the hub then sits directly in front
of the nacelle's front face x = nacelle_length/2.
"""

from __future__ import annotations

from meceng.tasks.base import Param

SHAFT_RADIUS = Param("shaft_radius", 0.018, 0.025, "m")
NACELLE_LENGTH = Param("nacelle_length", 0.2, 0.28, "m")
HUB_HEIGHT = Param("hub_height", 0.8, 1.1, "m")

WIND_TURBINE_MASTERS = (SHAFT_RADIUS, NACELLE_LENGTH, HUB_HEIGHT)
