"""Part 52: the unbalanced rotor, a stepped shaft with a central disc that carries an unbalance hole.

A Laval-type rotor: two bearing seats of the master radius at both shaft ends, a thicker shaft body
between them (shoulders at the seats) and a disc in the middle of the shaft. The unbalance is a
cylindrical through hole in the disc, parallel to the axis, on the +z side, midway between the shaft
body's surface and the disc's rim. Seat length = bearing_width and seat distance = bearing_span are
masters, so the seats fit the blocks' bores and the blocks' positions follow from the masters.

Frame: the shaft axis is the x-axis, the left end face's centre is the origin; the seats are
0 <= x <= bearing_width and bearing_span <= x <= bearing_span + bearing_width. Interfaces: 'left' and
'right', the cylindrical surfaces of the two bearing seats (assemblies 73 and 74: one seat in the
flexible bearing block, the other e.g. in a bearing to ground).

Ranges: the hole keeps >= 6 mm of material to the shaft body and to the rim and removes >= 2 % of
the volume (the disc >= 20 %), so a missing or misplaced unbalance fails the mass and mesh metrics;
the disc radius (<= 0.09 m) stays below the master axis height (>= 0.1 m), so the disc clears the
ground in the assemblies. maxh = shaft_radius (12-18 mm): two elements across a seat's diameter,
Netgen refines around the hole and the shoulders by curvature; the GT has ~1100-1600 nodes
(the linear tets lose ~1.2 % of the volume to faceting).
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_rotor import SHAFT_MASTERS, names


def _derive(v: dict) -> dict:
    total = v["bearing_span"] + v["bearing_width"]
    return {
        "total_length": round(total, 7),
        "disc_start": round(total / 2 - v["disc_thickness"] / 2, 7),
        "disc_end": round(total / 2 + v["disc_thickness"] / 2, 7),
        "hole_offset": round((v["body_radius"] + v["disc_radius"]) / 2, 7),
    }


TASK = PartModel(
    id=52,
    name="unbalanced rotor part",
    description="""
An unbalanced rotor: a stepped round shaft with a disc in the middle; the disc carries an unbalance in
the form of an off-axis hole. Coordinate frame: the shaft axis is the x-axis and the centre of the
shaft's left end face is the origin; the shaft occupies 0 <= x <= total_length = bearing_span +
bearing_width = {total_length} m. The shaft consists of three coaxial cylindrical sections: a left
bearing seat of radius shaft_radius = {shaft_radius} m for 0 <= x <= bearing_width = {bearing_width} m,
the shaft body of radius body_radius = {body_radius} m for {bearing_width} <= x <= bearing_span =
{bearing_span} m, and a right bearing seat of radius shaft_radius for {bearing_span} <= x <=
{total_length}. The disc is a coaxial cylinder of radius disc_radius = {disc_radius} m and thickness
disc_thickness = {disc_thickness} m, centred at the middle of the shaft, so it occupies
{disc_start} <= x <= {disc_end}. The unbalance is a cylindrical hole of radius hole_radius =
{hole_radius} m through the whole thickness of the disc, parallel to the x-axis, with its axis at y = 0,
z = hole_offset = (body_radius + disc_radius)/2 = {hole_offset} m (on the +z side, midway between the
shaft body's surface and the disc's rim). There are no chamfers, fillets or keyways. Define two
interfaces: the cylindrical surface of the left bearing seat named 'left' and the cylindrical surface
of the right bearing seat named 'right' (only the seats' cylindrical faces, not the end faces or the
shoulders).
""",
    params=(
        *SHAFT_MASTERS,
        Param("body_radius", 0.02, 0.024, "m"),
        Param("disc_radius", 0.078, 0.09, "m"),
        Param("disc_thickness", 0.04, 0.05, "m"),
        Param("hole_radius", 0.017, 0.021, "m"),
    ),
    master=names(SHAFT_MASTERS),
    derive=_derive,
    components=("Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
left_seat = Cylinder(Pnt(0, 0, 0), X, r=shaft_radius, h=bearing_width)
body = Cylinder(Pnt(bearing_width, 0, 0), X, r=body_radius, h=bearing_span - bearing_width)
right_seat = Cylinder(Pnt(bearing_span, 0, 0), X, r=shaft_radius, h=bearing_width)
disc = Cylinder(Pnt(disc_start, 0, 0), X, r=disc_radius, h=disc_thickness)
shape = left_seat + body + right_seat + disc
# the unbalance hole; the tool reaches beyond the disc (only air there), no coincident faces
hole = Cylinder(Pnt(disc_start - disc_thickness, 0, hole_offset), X, r=hole_radius, h=3 * disc_thickness)
shape = shape - hole
shape.faces.Nearest(Pnt(bearing_width / 2, 0, shaft_radius)).name = 'left'
shape.faces.Nearest(Pnt(bearing_span + bearing_width / 2, 0, shaft_radius)).name = 'right'
""",
    interfaces=("left", "right"),
    mesh_size=lambda v: v["shaft_radius"],
    material=STEEL,
)
