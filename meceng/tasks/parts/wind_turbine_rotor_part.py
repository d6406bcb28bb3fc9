"""Part 60: the rotor of the simplified wind turbine (assembly 79, with the tower part 59).

One aluminium solid: a shaft that sits in the nacelle bore of the tower, a cylindrical hub in
front of it and three flat rectangular blades at 120 degrees, their roots merged into the hub.

Frame: the x-axis is the rotor axis, the origin is the centre of the shaft's rear end face; the
shaft occupies 0 <= x <= nacelle_length, the hub follows directly. Blade 1 points along +z, blades
2 and 3 are blade 1 rotated about the x-axis by 120 and 240 degrees.

Interfaces (for the assembly): 'shaft' = cylindrical surface of the shaft (length nacelle_length,
centre (nacelle_length/2, 0, 0)), joined to the tower's 'bore' by a revolute joint about x;
'hub' = front face of the hub (x = hub_front), where the driving torque about the rotor axis can
act. Placement: rotor frame = tower frame shifted by (-nacelle_length/2, 0, hub_height).

Master parameters (masters_wind_turbine.py): shaft_radius (= nacelle bore radius) and
nacelle_length (= shaft length).

Ranges: blade_width <= hub_radius, so the three blades only overlap each other inside the hub
(their overlap reaches at most 0.58 * blade_width from the axis); blade_thickness < hub_length,
so the blades stay inside the hub's length and the hub's front face is a full disk; the tip radius
(<= 0.55 m) stays below the smallest hub height (0.8 m). maxh = blade_thickness / 2 (two elements
through the blade): with one element per thickness the first (blade bending) frequencies were
~40 % too stiff, with two they agree within ~2 % between differently built but identical
rotors (shaft and hub built with WorkPlane circles, blades rotated the other way round). The blades
make up 38-63 % of the volume. GT: ~1800-3100 nodes, ~0.7-1.3 s (seeds 0-4).
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import ALUMINIUM, PartModel
from meceng.tasks.parts.masters_wind_turbine import NACELLE_LENGTH, SHAFT_RADIUS


def _derive(v: dict) -> dict:
    hub_front = v["nacelle_length"] + v["hub_length"]
    blade_x0 = v["nacelle_length"] + (v["hub_length"] - v["blade_thickness"]) / 2
    return {"hub_front": round_significant(hub_front, 6),
            "blade_x0": round_significant(blade_x0, 6),
            "blade_x1": round_significant(blade_x0 + v["blade_thickness"], 6)}


TASK = PartModel(
    id=60,
    name="wind turbine rotor part",
    description="""
The rotor of a simplified wind turbine, built as one solid from a shaft, a cylindrical hub and three flat
rectangular blades. Coordinate frame: the x-axis is the rotor axis and the origin is the centre of the shaft's
rear end face.
Shaft: a solid cylinder of radius shaft_radius = {shaft_radius} m about the x-axis from x = 0 to
x = nacelle_length = {nacelle_length} m (the shaft is as long as the nacelle bore it sits in).
Hub: a solid cylinder of radius hub_radius = {hub_radius} m about the x-axis that directly follows the shaft,
from x = {nacelle_length} to x = hub_front = nacelle_length + hub_length = {hub_front} m
(hub_length = {hub_length} m).
Blades: three identical flat blades of thickness blade_thickness = {blade_thickness} m along x, width
blade_width = {blade_width} m and tip radius rotor_radius = {rotor_radius} m, each centred in the middle of the
hub's length. Blade 1 is the box {blade_x0} <= x <= {blade_x1}, -{blade_width}/2 <= y <= {blade_width}/2 and
0 <= z <= {rotor_radius}: it starts on the rotor axis, so its root lies inside the hub and is merged with it,
and its tip face is at z = {rotor_radius}. Blades 2 and 3 are blade 1 rotated about the x-axis by 120 and
240 degrees. Shaft, hub and blades are fused into one solid; there are no fillets or chamfers.
Define two interfaces: the cylindrical surface of the shaft (0 < x < {nacelle_length}) named 'shaft' and the
flat front face of the hub (x = {hub_front}) named 'hub'.
""",
    params=(
        SHAFT_RADIUS,
        NACELLE_LENGTH,
        Param("hub_radius", 0.08, 0.1, "m"),
        Param("hub_length", 0.06, 0.09, "m"),
        Param("blade_width", 0.06, 0.08, "m"),
        Param("blade_thickness", 0.025, 0.035, "m"),
        Param("rotor_radius", 0.4, 0.55, "m"),
    ),
    master=("shaft_radius", "nacelle_length"),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanFuse", "Transform", "NamedFaces",
                "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
shaft = Cylinder(Pnt(0, 0, 0), X, r=shaft_radius, h=nacelle_length + hub_length / 2)  # reaches into the hub
hub = Cylinder(Pnt(nacelle_length, 0, 0), X, r=hub_radius, h=hub_length)
blade = Box(Pnt(blade_x0, -blade_width / 2, 0), Pnt(blade_x1, blade_width / 2, rotor_radius))
rotor_axis = Axis(Pnt(0, 0, 0), X)
shape = shaft + hub + blade + blade.Rotate(rotor_axis, 120) + blade.Rotate(rotor_axis, 240)
shape.faces.Nearest(Pnt(nacelle_length / 2, 0, shaft_radius)).name = 'shaft'  # a point on the shaft; one face
shape.faces.Max(X).name = 'hub'
""",
    interfaces=("shaft", "hub"),
    mesh_size=lambda v: v["blade_thickness"] / 2,
    material=ALUMINIUM,
)
