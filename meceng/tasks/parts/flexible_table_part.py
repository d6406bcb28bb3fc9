"""Part 58: the flexible table, a rectangular top plate on four square legs with a load pad on top.

Frame (as in the paper): the origin is the centre of the top plate, i.e. the plate's centre of
mass; x along the table's length, y along its width, z upwards. The legs hang below the plate, so
the feet stand at z = -(plate_thickness / 2 + leg_height); the flexible table with load (assembly
78) must lift the part by that much to put it on a floor at z = 0.

Interfaces: the four feet (bottom faces of the legs) 'foot1'..'foot4', numbered counter-clockwise
seen from above starting at the foot with negative x and y (foot1 (-, -), foot2 (+, -), foot3
(+, +), foot4 (-, +)) - the ground attachments; and 'load', the top face of a square pad centred
on the plate, where the assembly's load acts. A pad rather than the whole top face: an RBE2
interface makes its face rigid, which would turn the whole plate rigid in the reduced model.

Plate size, thickness, leg height, leg size and leg inset are master parameters (masters_table.py)
because the assembly places the table and its feet from them; the pad is the part's own. maxh =
plate_thickness: one to two tetrahedra across the plate, at least two across a leg, ~5400 nodes
for the largest table (two elements across the plate would need four times as many). The pad is
only 0.5-6 % of the volume, but it is the clamped 'load' interface: an answer without it (or with the
whole top face as 'load') is off by ~90 % in the first eigenfrequencies.
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import ALUMINIUM, PartModel
from meceng.tasks.parts.masters_table import TABLE_MASTERS


def _derive(v: dict) -> dict:
    return {
        "leg_x": round_significant(v["table_length"] / 2 - v["leg_inset"] - v["leg_size"] / 2, 6),
        "leg_y": round_significant(v["table_width"] / 2 - v["leg_inset"] - v["leg_size"] / 2, 6),
        "feet_z": round_significant(-(v["plate_thickness"] / 2 + v["leg_height"]), 6),
        "pad_top_z": round_significant(v["plate_thickness"] / 2 + v["pad_height"], 6),
    }


TASK = PartModel(
    id=58,
    name="flexible table part",
    description="""
A flexible table made of one solid: a rectangular top plate standing on four vertical legs of square
cross section, with a square load pad on top of the plate. Frame: the origin is the centre of the top
plate (the plate's centre of mass), x along the table's length, y along its width, z upwards.
The top plate has length table_length = {table_length} m along x, width table_width = {table_width} m
along y and thickness plate_thickness = {plate_thickness} m along z: it occupies -{table_length}/2 <= x
<= {table_length}/2, -{table_width}/2 <= y <= {table_width}/2 and -{plate_thickness}/2 <= z <=
{plate_thickness}/2. Each leg is a square prism of side leg_size = {leg_size} m and length leg_height =
{leg_height} m that extends from the plate's bottom face (z = -{plate_thickness}/2) straight down to
z = -(plate_thickness/2 + leg_height) = {feet_z} m. The legs stand in the four corners, each with its two
outer side faces at the distance leg_inset = {leg_inset} m inside the plate's edges, so the leg axes
are at x = +-leg_x and y = +-leg_y with leg_x = table_length/2 - leg_inset - leg_size/2 = {leg_x} m and
leg_y = table_width/2 - leg_inset - leg_size/2 = {leg_y} m. The load pad, a square block of side
pad_size = {pad_size} m and height pad_height = {pad_height} m, is centred on the plate's top face:
-{pad_size}/2 <= x <= {pad_size}/2, -{pad_size}/2 <= y <= {pad_size}/2 and {plate_thickness}/2 <= z <=
{pad_top_z}. Define five interfaces: the bottom faces of the legs (the feet, at z = {feet_z}) named
'foot1' (leg at x = -{leg_x}, y = -{leg_y}), 'foot2' (x = {leg_x}, y = -{leg_y}), 'foot3'
(x = {leg_x}, y = {leg_y}) and 'foot4' (x = -{leg_x}, y = {leg_y}), and the top face of the load pad
(z = {pad_top_z}) named 'load'.
""",
    params=(*TABLE_MASTERS, Param("pad_size", 0.1, 0.15, "m"), Param("pad_height", 0.015, 0.025, "m")),
    master=tuple(p.name for p in TABLE_MASTERS),
    derive=_derive,
    components=("Box", "BooleanFuse", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
shape = Box(Pnt(-table_length / 2, -table_width / 2, -plate_thickness / 2),
            Pnt(table_length / 2, table_width / 2, plate_thickness / 2))
shape = shape + Box(Pnt(-pad_size / 2, -pad_size / 2, plate_thickness / 2), Pnt(pad_size / 2, pad_size / 2, pad_top_z))
feet = [(-leg_x, -leg_y), (leg_x, -leg_y), (leg_x, leg_y), (-leg_x, leg_y)]
for x, y in feet:
    shape = shape + Box(Pnt(x - leg_size / 2, y - leg_size / 2, feet_z),
                        Pnt(x + leg_size / 2, y + leg_size / 2, -plate_thickness / 2))
for i, (x, y) in enumerate(feet):
    shape.faces.Nearest(Pnt(x, y, feet_z)).name = f'foot{i + 1}'
shape.faces.Max(Z).name = 'load'
""",
    interfaces=("foot1", "foot2", "foot3", "foot4", "load"),
    mesh_size=lambda v: v["plate_thickness"],
    material=ALUMINIUM,
)
