"""Part 67: the simple flexible crank, a flat rectangular plate with two joint holes.

The crank of the flexible slider crank (assembly 83) turns about a ground pin in 'hole_a' (axis =
z-axis) and carries the crank pin, which connects it to the rod, in 'hole_b' (axis through
(crank_length, 0, 0)). The plate's mid-plane is z = 0, so crank, rod and slider move in the
xy-plane. crank_length, pin_radius and thickness are master parameters; the plate width is the
part's own and at least 2 * 7 mm wider than the largest hole, so the ligament around a hole is
never thinner than 7 mm. The plate ends crank_width / 2 beyond each hole axis, so each hole sits in
the centre of a square end.

maxh = thickness / 2 puts two elements through the thickness (the thinnest dimension). Over the
ranges the holes are 3-20 % of the plate's volume and a 5 % longer crank adds 2.7-4.1 % mass.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters

TASK = PartModel(
    id=67,
    name="crank part simple",
    description="""
A simple flexible crank made of a flat rectangular plate with two circular through holes for the
joint pins. Coordinate frame: the axis of the first hole is the z-axis, the axis of the second hole
is parallel to z through the point (crank_length, 0, 0) with crank length crank_length =
{crank_length} m, and the plate's mid-plane is z = 0. The plate has thickness thickness =
{thickness} m along z and width crank_width = {crank_width} m along y, and it ends crank_width/2
beyond each hole axis in x, so it occupies -{crank_width}/2 <= x <= {crank_length} + {crank_width}/2,
-{crank_width}/2 <= y <= {crank_width}/2 and -{thickness}/2 <= z <= {thickness}/2. Both holes have
the radius pin_radius = {pin_radius} m and go through the whole thickness; there are no other
features (no chamfers, no fillets). Define two interfaces: the cylindrical surface of the hole at
the origin (the crank's bearing on the ground pin) named 'hole_a' and the cylindrical surface of
the hole at x = {crank_length} (the crank pin connecting to the rod) named 'hole_b'.
""",
    params=(*masters("crank_length", "pin_radius", "thickness"), Param("crank_width", 0.03, 0.045, "m")),
    master=("crank_length", "pin_radius", "thickness"),
    components=("Box", "Cylinder", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
plate = Box(Pnt(-crank_width / 2, -crank_width / 2, -thickness / 2),
            Pnt(crank_length + crank_width / 2, crank_width / 2, thickness / 2))
hole_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
hole_b = Cylinder(Pnt(crank_length, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
shape = plate - hole_a - hole_b
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'hole_a'
shape.faces.Nearest(Pnt(crank_length + pin_radius, 0, 0)).name = 'hole_b'
""",
    interfaces=("hole_a", "hole_b"),
    mesh_size=lambda v: v["thickness"] / 2,
    material=STEEL,
)
