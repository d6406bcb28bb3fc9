"""Part 64: the pin-side leaf of a three-knuckle door hinge (assembly 81 with part 63).

A flat leaf plate with the middle knuckle on one edge and the hinge pin fused into it; above and
below the knuckle the plate is notched, and the pin runs through these gaps, where the gap-side
leaf's knuckles (part 63) turn on it. Common frame of both leaves, the hinge fully opened (flat):
the hinge axis is the z-axis, the hinge spans 0 <= z <= 3 * knuckle_length, the leaves' mid-plane
is y = 0, this leaf lies on the -x side, the gap-side leaf on the +x side. Placed with the
identity, the two parts fit.

Interfaces for the assembly: 'pin' - the two cylindrical pin surfaces outside the knuckle
(radius pin_radius, coaxial with the hinge axis, centre (0, 0, 1.5 knuckle_length)), the revolute
joint with the gap-side leaf's 'bore'; 'mount' - the two screw hole surfaces, where the leaf is
fixed to the door frame (ground).

The knuckle dimensions, the leaf thickness and the clearance are master parameters
(masters_hinge.py); the leaf width and the screw holes are the part's own. maxh = leaf_thickness / 2
puts two elements through the plate: 1500-2900 nodes over seeds 0-19, 4250 at the corner of the
ranges that meshes finest.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_hinge import HINGE_MASTER_NAMES, HINGE_MASTERS, hinge_derive

TASK = PartModel(
    id=64,
    name="hinge leaf pin side part",
    description="""
The pin-side leaf of a door hinge with three knuckles of equal length: this leaf carries the middle
knuckle and the hinge pin, the lower and the upper knuckle belong to the other (gap-side) leaf. The
leaf is described in the hinge's fully opened position in this frame: the hinge axis is the z-axis,
the hinge spans 0 <= z <= hinge_length = 3 * knuckle_length = {hinge_length} m with
knuckle_length = {knuckle_length} m, and the leaf lies on the -x side of the axis, symmetric to the
plane y = 0.
(1) Leaf plate: a rectangular plate of thickness leaf_thickness = {leaf_thickness} m occupying
-{leaf_width} <= x <= 0 (leaf_width = {leaf_width} m), -{leaf_thickness}/2 <= y <= {leaf_thickness}/2 and
0 <= z <= {hinge_length}.
(2) Gaps: two rectangular notches remove the plate region -notch_depth <= x <= 0 with
notch_depth = {notch_depth} m (notch_depth = knuckle_outer_radius + knuckle_clearance with
knuckle_clearance = {knuckle_clearance} m) over the lower third 0 <= z <= {knuckle_length} and over the upper third {knuckle_top} <= z <= {hinge_length},
through the full plate thickness.
(3) Knuckle: a solid cylinder of radius knuckle_outer_radius = {knuckle_outer_radius} m about the
z-axis over the middle third {knuckle_length} <= z <= {knuckle_top}, fused with the plate.
(4) Pin: a solid cylinder of radius pin_radius = {pin_radius} m about the z-axis over the full length
0 <= z <= {hinge_length}, fused with the knuckle; it passes through the knuckle and through both gaps.
(5) Screw holes: two cylindrical through holes of radius hole_radius = {hole_radius} m through the plate
thickness (axis parallel to y), centred at x = -{hole_x} m and z = {hole_z1} m and z = {hole_z2} m
respectively.
There are no other features (no chamfers, no fillets). Define two interfaces: the cylindrical surface of
the pin in the lower gap (0 <= z <= {knuckle_length}) and in the upper gap
({knuckle_top} <= z <= {hinge_length}) together named 'pin' (the pin's flat end faces are not part of
it), and the two cylindrical surfaces of the screw holes together named 'mount'.
""",
    params=(*HINGE_MASTERS, Param("leaf_width", 0.04, 0.055, "m"), Param("hole_radius", 0.003, 0.0045, "m")),
    master=HINGE_MASTER_NAMES,
    derive=hinge_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
t2 = leaf_thickness / 2
plate = Box(Pnt(-leaf_width, -t2, 0), Pnt(0, t2, hinge_length))
plate = plate - Box(Pnt(-notch_depth, -t2, 0), Pnt(0, t2, knuckle_length))
plate = plate - Box(Pnt(-notch_depth, -t2, knuckle_top), Pnt(0, t2, hinge_length))
knuckle = Cylinder(Pnt(0, 0, knuckle_length), Z, r=knuckle_outer_radius, h=knuckle_length)
pin = Cylinder(Pnt(0, 0, 0), Z, r=pin_radius, h=hinge_length)
shape = plate + knuckle + pin
for zh in (hole_z1, hole_z2):
    shape = shape - Cylinder(Pnt(-hole_x, -t2, zh), Y, r=hole_radius, h=leaf_thickness)
# name after the booleans: each face through a point on its surface
for zp in (knuckle_length / 2, knuckle_top + knuckle_length / 2):
    shape.faces.Nearest(Pnt(pin_radius, 0, zp)).name = 'pin'
for zh in (hole_z1, hole_z2):
    shape.faces.Nearest(Pnt(-hole_x, 0, zh + hole_radius)).name = 'mount'
""",
    interfaces=("pin", "mount"),
    mesh_size=lambda v: v["leaf_thickness"] / 2,
    material=STEEL,
)
