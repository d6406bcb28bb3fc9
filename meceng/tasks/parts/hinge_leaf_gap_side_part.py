"""Part 63: the gap-side leaf of a three-knuckle door hinge (assembly 81 with part 64).

A flat leaf plate with the lower and the upper knuckle (tubes about the hinge axis) on one edge;
between them the plate is notched, which is the gap the pin-side leaf's middle knuckle fits into.
Both leaves are given in one common frame, the hinge fully opened (flat): the hinge axis is the
z-axis, the hinge spans 0 <= z <= 3 * knuckle_length, the leaves' mid-plane is y = 0, this leaf
lies on the +x side and the pin-side leaf (part 64) on the -x side. Placed with the identity, the
two parts fit: this leaf's knuckles sit on the pin-side leaf's pin, its notch leaves
``knuckle_clearance`` around the middle knuckle.

Interfaces for the assembly: 'bore' - the two bore surfaces (radius pin_radius, coaxial with the
hinge axis, centre (0, 0, 1.5 knuckle_length)), the revolute joint with the pin-side leaf's 'pin';
'door' - the two screw hole surfaces, where the door (a mass, a load) is attached.

The knuckle dimensions, the leaf thickness and the clearance are master parameters
(masters_hinge.py); the leaf width and the screw holes are the part's own. maxh = leaf_thickness / 2
puts two elements through the plate and the 4-7 mm knuckle wall: 1800-3500 nodes over seeds 0-19,
4600 at the corner of the ranges that meshes finest (thin, long, wide leaf with large knuckles).
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_hinge import HINGE_MASTER_NAMES, HINGE_MASTERS, hinge_derive

TASK = PartModel(
    id=63,
    name="hinge leaf gap side part",
    description="""
The gap-side leaf of a door hinge with three knuckles of equal length: this leaf carries the lower
and the upper knuckle, the middle one belongs to the other (pin-side) leaf. The leaf is described in
the hinge's fully opened position in this frame: the hinge axis is the z-axis, the hinge spans
0 <= z <= hinge_length = 3 * knuckle_length = {hinge_length} m with knuckle_length = {knuckle_length} m,
and the leaf lies on the +x side of the axis, symmetric to the plane y = 0.
(1) Leaf plate: a rectangular plate of thickness leaf_thickness = {leaf_thickness} m occupying
0 <= x <= leaf_width = {leaf_width} m, -{leaf_thickness}/2 <= y <= {leaf_thickness}/2 and
0 <= z <= {hinge_length}.
(2) Gap: a rectangular notch removes the plate region 0 <= x <= notch_depth = {notch_depth} m
(notch_depth = knuckle_outer_radius + knuckle_clearance with knuckle_clearance = {knuckle_clearance} m)
over the middle third {knuckle_length} <= z <= {knuckle_top}, through the full plate thickness.
(3) Knuckles: two solid cylinders of radius knuckle_outer_radius = {knuckle_outer_radius} m about the
z-axis, the lower one over 0 <= z <= {knuckle_length}, the upper one over {knuckle_top} <= z <= {hinge_length},
fused with the plate.
(4) Bore: a cylindrical bore of radius pin_radius = {pin_radius} m about the z-axis is cut from the fused
solid over the full length 0 <= z <= {hinge_length}, so each knuckle is a tube and no plate material
remains inside the bore.
(5) Screw holes: two cylindrical through holes of radius hole_radius = {hole_radius} m through the plate
thickness (axis parallel to y), centred at x = hole_x = {hole_x} m and z = {hole_z1} m and
z = {hole_z2} m respectively.
There are no other features (no chamfers, no fillets). Define two interfaces: the two cylindrical bore
surfaces of the knuckles (radius {pin_radius} m) together named 'bore', and the two cylindrical surfaces
of the screw holes together named 'door'.
""",
    params=(*HINGE_MASTERS, Param("leaf_width", 0.04, 0.055, "m"), Param("hole_radius", 0.003, 0.0045, "m")),
    master=HINGE_MASTER_NAMES,
    derive=hinge_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
t2 = leaf_thickness / 2
plate = Box(Pnt(0, -t2, 0), Pnt(leaf_width, t2, hinge_length))
plate = plate - Box(Pnt(0, -t2, knuckle_length), Pnt(notch_depth, t2, knuckle_top))
knuckles = (Cylinder(Pnt(0, 0, 0), Z, r=knuckle_outer_radius, h=knuckle_length)
            + Cylinder(Pnt(0, 0, knuckle_top), Z, r=knuckle_outer_radius, h=knuckle_length))
shape = plate + knuckles
shape = shape - Cylinder(Pnt(0, 0, 0), Z, r=pin_radius, h=hinge_length)
for zh in (hole_z1, hole_z2):
    shape = shape - Cylinder(Pnt(hole_x, -t2, zh), Y, r=hole_radius, h=leaf_thickness)
# name after the booleans: each face through a point on its surface
for zk in (knuckle_length / 2, knuckle_top + knuckle_length / 2):
    shape.faces.Nearest(Pnt(-pin_radius, 0, zk)).name = 'bore'
for zh in (hole_z1, hole_z2):
    shape.faces.Nearest(Pnt(hole_x, 0, zh + hole_radius)).name = 'door'
""",
    interfaces=("bore", "door"),
    mesh_size=lambda v: v["leaf_thickness"] / 2,
    material=STEEL,
)
