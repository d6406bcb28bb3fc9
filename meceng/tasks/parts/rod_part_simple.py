"""Part 68: the simple flexible connecting rod, a straight shank with a round eye at each end.

The rod of the flexible slider crank (assembly 83) connects the crank pin ('hole_a', axis = z-axis)
with the slider's pin ('hole_b', axis through (rod_length, 0, 0)). Both eyes are cylinders of the
same radius, coaxial with the holes; the shank is a rectangular bar between the two hole axes; eyes
and shank have the full thickness, mid-plane z = 0. rod_length, pin_radius and thickness are master
parameters. Own ranges: the eye radius leaves at least 5 mm of material around the largest hole,
the shank is narrower than the eyes (shank_width <= 18 mm < 2 * 13 mm), so the shank's side faces
meet the eye cylinders and no tangent faces occur.

maxh = thickness / 3: three elements through the thickness; with two, the first bending frequencies
of this slender bar moved by up to 3 % between two correct constructions (linear tetrahedra are stiff),
with three by up to about 2 %. Over the ranges the holes are 3-18 % of the volume and a 5 % longer
rod adds 3-4.8 % mass.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters

TASK = PartModel(
    id=68,
    name="rod part simple",
    description="""
A simple flexible connecting rod made of a straight shank with a round eye at each end, each eye
with a circular through hole for a joint pin. Coordinate frame: the axis of the first hole is the
z-axis, the axis of the second hole is parallel to z through the point (rod_length, 0, 0) with rod
length rod_length = {rod_length} m, and the rod's mid-plane is z = 0. All parts of the rod have the
thickness thickness = {thickness} m along z (-{thickness}/2 <= z <= {thickness}/2). The two eyes are
solid circular cylinders of radius eye_radius = {eye_radius} m with their axes on the two hole axes.
The shank is a rectangular bar between the two hole axes: 0 <= x <= {rod_length},
-{shank_width}/2 <= y <= {shank_width}/2 with shank width shank_width = {shank_width} m; shank and
eyes are fused into one solid. Both holes have the radius pin_radius = {pin_radius} m, are coaxial
with the eyes and go through the whole thickness; there are no other features (no chamfers, no
fillets). Define two interfaces: the cylindrical surface of the hole at the origin (the joint with
the crank pin) named 'hole_a' and the cylindrical surface of the hole at x = {rod_length} (the joint
with the slider) named 'hole_b'.
""",
    params=(*masters("rod_length", "pin_radius", "thickness"), Param("eye_radius", 0.013, 0.017, "m"),
            Param("shank_width", 0.012, 0.018, "m")),
    master=("rod_length", "pin_radius", "thickness"),
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
eye_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=eye_radius, h=thickness)
eye_b = Cylinder(Pnt(rod_length, 0, -thickness / 2), Z, r=eye_radius, h=thickness)
shank = Box(Pnt(0, -shank_width / 2, -thickness / 2), Pnt(rod_length, shank_width / 2, thickness / 2))
hole_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
hole_b = Cylinder(Pnt(rod_length, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
shape = eye_a + eye_b + shank - hole_a - hole_b
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'hole_a'
shape.faces.Nearest(Pnt(rod_length + pin_radius, 0, 0)).name = 'hole_b'
""",
    interfaces=("hole_a", "hole_b"),
    mesh_size=lambda v: v["thickness"] / 3,
    material=STEEL,
)
