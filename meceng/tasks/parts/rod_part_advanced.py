"""Part 71: the advanced flexible connecting rod, an I-section shank between two different eyes.

The rod of the flexible slider crank (assembly 84) connects the crank pin in the big end 'hole_a'
(axis = z-axis) with the slider's pin in the small end 'hole_b' (axis through (rod_length, 0, 0)).
Eyes and shank have the full thickness (mid-plane z = 0); a rectangular pocket in the top and in the
bottom face of the shank, between the two eyes, turns the shank into an I-section. rod_length,
pin_radius and thickness are master parameters. Own ranges keep the geometry valid for every
master draw: the eyes leave at least 4 mm of material around the largest hole, the shank (<= 20 mm)
is narrower than the small eye (>= 24 mm across), the pocket flanges are at least 3 mm wide, and the
pocket depth is 22-30 % of the thickness, so the web between the pockets keeps 40-56 % of it. The
pockets start at x = eye_a_radius and end at x = rod_length - eye_b_radius, i.e. entirely outside
the eye cylinders.

The pockets remove 8.5-42 % of the volume. maxh = (thickness - 2 pocket_depth) / 1.5 puts about two
elements through the web between the pockets.
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters


def _derive(v: dict) -> dict:
    return {"pocket_depth": round_significant(v["pocket_ratio"] * v["thickness"], 3)}


TASK = PartModel(
    id=71,
    name="rod part advanced",
    description="""
An advanced flexible connecting rod made of a big eye and a small eye joined by a shank with an
I-shaped cross section, each eye with a circular through hole for a joint pin. Coordinate frame: the
axis of the first hole (big end) is the z-axis, the axis of the second hole (small end) is parallel
to z through the point (rod_length, 0, 0) with rod length rod_length = {rod_length} m, and the rod is
symmetric to its mid-plane z = 0. Eyes and shank have the thickness thickness = {thickness} m along z
(-{thickness}/2 <= z <= {thickness}/2). The big eye is a solid circular cylinder of radius
eye_a_radius = {eye_a_radius} m whose axis is the z-axis; the small eye is a solid circular cylinder
of radius eye_b_radius = {eye_b_radius} m whose axis is the second hole's axis. The shank is a
rectangular bar between the two hole axes, 0 <= x <= {rod_length} and -{shank_width}/2 <= y <=
{shank_width}/2 with shank width shank_width = {shank_width} m; eyes and shank are fused into one
solid. Two equal rectangular pockets are cut into the shank, one into its top face and one into its
bottom face: each pocket spans {eye_a_radius} <= x <= {rod_length} - {eye_b_radius} (from
x = eye_a_radius to x = rod_length - eye_b_radius) and -{pocket_width}/2 <= y <= {pocket_width}/2 with
pocket width pocket_width = {pocket_width} m, and has the depth pocket_depth = {pocket_depth} m, i.e.
the top pocket occupies {thickness}/2 - {pocket_depth} <= z <= {thickness}/2 and the bottom pocket
-{thickness}/2 <= z <= -{thickness}/2 + {pocket_depth}; pocket edges and corners are sharp. Both holes
have the radius pin_radius = {pin_radius} m, are coaxial with the eyes and go through the whole
thickness; there are no other features (no chamfers, no fillets). Define two interfaces: the
cylindrical surface of the hole at the origin (big end, the joint with the crank pin) named 'hole_a'
and the cylindrical surface of the hole at x = {rod_length} (small end, the joint with the slider)
named 'hole_b'.
""",
    params=(*masters("rod_length", "pin_radius", "thickness"), Param("eye_a_radius", 0.015, 0.019, "m"),
            Param("eye_b_radius", 0.012, 0.015, "m"), Param("shank_width", 0.015, 0.02, "m"),
            Param("pocket_width", 0.006, 0.009, "m", digits=2), Param("pocket_ratio", 0.22, 0.3, digits=2)),
    master=("rod_length", "pin_radius", "thickness"),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
eye_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=eye_a_radius, h=thickness)
eye_b = Cylinder(Pnt(rod_length, 0, -thickness / 2), Z, r=eye_b_radius, h=thickness)
shank = Box(Pnt(0, -shank_width / 2, -thickness / 2), Pnt(rod_length, shank_width / 2, thickness / 2))
top_pocket = Box(Pnt(eye_a_radius, -pocket_width / 2, thickness / 2 - pocket_depth),
                 Pnt(rod_length - eye_b_radius, pocket_width / 2, thickness / 2))
bottom_pocket = Box(Pnt(eye_a_radius, -pocket_width / 2, -thickness / 2),
                    Pnt(rod_length - eye_b_radius, pocket_width / 2, -thickness / 2 + pocket_depth))
hole_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
hole_b = Cylinder(Pnt(rod_length, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
shape = eye_a + eye_b + shank - top_pocket - bottom_pocket - hole_a - hole_b
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'hole_a'
shape.faces.Nearest(Pnt(rod_length + pin_radius, 0, 0)).name = 'hole_b'
""",
    interfaces=("hole_a", "hole_b"),
    mesh_size=lambda v: (v["thickness"] - 2 * v["pocket_depth"]) / 1.5,
    material=STEEL,
)
