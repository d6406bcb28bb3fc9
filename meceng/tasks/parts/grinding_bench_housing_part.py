"""Part 61: the motor housing of the grinding bench (assembly 80, with the spindle part 62).

One cast-iron solid: a base plate whose bottom has a channel along the axis (leaving two feet),
a motor body whose cross-section is a rectangle topped by a semicircle, an internal cylindrical
motor cavity and a through bore for the spindle; the bore forms a bearing seat in each of the two
end walls left by the cavity.

Frame: origin at the centre of the housing's bottom plane, z up, x along the spindle axis, which
is the line y = 0, z = axis_height; the housing is symmetric to x = 0 and y = 0.

Interfaces (for the assembly): 'feet' = the two bottom faces of the feet (z = 0), fixed to the
ground; 'bearing_left' / 'bearing_right' = the bore surfaces in the end walls at x < 0 / x > 0
(length bearing_length, centres (-/+(housing_length - bearing_length)/2, 0, axis_height)), joined
with the spindle's journals of the same names. Placement: spindle frame = housing frame shifted by
(0, 0, axis_height).

Master parameters (masters_grinding_bench.py): spindle_radius (= bore radius), housing_length,
bearing_length (end wall thickness = journal length) and axis_height.

Ranges: body wall around the cavity >= 15 mm; cavity radius (>= 40 mm) larger than the bore and
than the spindle's armature (<= 34 mm); cavity bottom >= 70 mm above the ground; the channel
(half width <= 50 mm) lies under the body (half width >= 65 mm), so it may be deeper than the base
plate without opening anything; the body is narrower than the base plate (half width >= 95 mm).
maxh = base_thickness (12-18 mm, the thinnest wall: about one element through the feet, 1-2
through the cavity wall); GT ~1900-3100 nodes, ~1.1-2.2 s (seeds 0-4). The cavity is 18-37 % of
the volume, the channel 3-10 %; the bearing bores themselves are small (0.2-0.6 %).
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import CAST_IRON, PartModel
from meceng.tasks.parts.masters_grinding_bench import GRINDING_BENCH_MASTERS


def _derive(v: dict) -> dict:
    return {"half_length": round_significant(v["housing_length"] / 2, 6),
            "inner_x": round_significant(v["housing_length"] / 2 - v["bearing_length"], 6),
            "body_top": round_significant(v["axis_height"] + v["body_radius"], 6)}


TASK = PartModel(
    id=61,
    name="grinding bench housing part",
    description="""
The motor housing of a grinding bench, built as one solid from a base plate with two feet, a motor body with a
rounded top, an internal motor cavity and a through bore for the spindle with a bearing seat in each end wall.
Coordinate frame: the origin is the centre of the housing's bottom plane, the z-axis points up and the x-axis is
parallel to the spindle axis, which is the line y = 0, z = axis_height = {axis_height} m. The housing has the
length housing_length = {housing_length} m along x and occupies -{half_length} <= x <= {half_length}.
Base plate: the box -{half_length} <= x <= {half_length}, -base_width/2 <= y <= base_width/2 and
0 <= z <= base_thickness with base_width = {base_width} m and base_thickness = {base_thickness} m.
Motor body: over the full length (-{half_length} <= x <= {half_length}) the union of the box
-body_radius <= y <= body_radius, 0 <= z <= {axis_height} and a cylinder of radius body_radius = {body_radius} m
about the spindle axis; its cross-section is a rectangle of width 2*body_radius from z = 0 up to the axis,
topped by a semicircle, so the top of the body is at z = axis_height + body_radius = {body_top} m.
Bore: a cylindrical through hole of radius spindle_radius = {spindle_radius} m along the spindle axis over the
full length.
Cavity: a coaxial cylindrical cavity of radius cavity_radius = {cavity_radius} m from x = -{inner_x} to
x = {inner_x} (= housing_length/2 - bearing_length), leaving two end walls of thickness
bearing_length = {bearing_length} m; the bore passes through both end walls. The bore surface in the left end
wall (-{half_length} <= x <= -{inner_x}) is the left bearing seat, the one in the right end wall
({inner_x} <= x <= {half_length}) the right bearing seat.
Feet: a rectangular channel along the full length is cut into the bottom, -recess_width/2 <= y <= recess_width/2
and 0 <= z <= recess_depth with recess_width = {recess_width} m and recess_depth = {recess_depth} m; the two
remaining strips recess_width/2 <= |y| <= base_width/2 at z = 0 are the feet.
There are no fillets or chamfers.
Define three interfaces: the two bottom faces of the feet (z = 0), together named 'feet', the bore surface in
the left end wall named 'bearing_left' and the bore surface in the right end wall named 'bearing_right'.
""",
    params=(
        *GRINDING_BENCH_MASTERS,
        Param("body_radius", 0.065, 0.08, "m"),
        Param("cavity_radius", 0.04, 0.05, "m"),
        Param("base_width", 0.19, 0.23, "m"),
        Param("base_thickness", 0.012, 0.018, "m"),
        Param("recess_width", 0.07, 0.1, "m"),
        Param("recess_depth", 0.01, 0.018, "m"),
    ),
    master=("spindle_radius", "housing_length", "bearing_length", "axis_height"),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "NamedFaces",
                "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
x0 = -housing_length / 2
base = Box(Pnt(x0, -base_width / 2, 0), Pnt(-x0, base_width / 2, base_thickness))
body = (Box(Pnt(x0, -body_radius, 0), Pnt(-x0, body_radius, axis_height))
        + Cylinder(Pnt(x0, 0, axis_height), X, r=body_radius, h=housing_length))
bore = Cylinder(Pnt(x0, 0, axis_height), X, r=spindle_radius, h=housing_length)
cavity = Cylinder(Pnt(x0 + bearing_length, 0, axis_height), X, r=cavity_radius,
                  h=housing_length - 2 * bearing_length)
channel = Box(Pnt(x0, -recess_width / 2, 0), Pnt(-x0, recess_width / 2, recess_depth))
shape = base + body - bore - cavity - channel
shape.faces[Z < base_thickness / 10].name = 'feet'  # the two faces at z = 0
shape.faces.Nearest(Pnt(x0 + bearing_length / 2, 0, axis_height + spindle_radius)).name = 'bearing_left'
shape.faces.Nearest(Pnt(-x0 - bearing_length / 2, 0, axis_height + spindle_radius)).name = 'bearing_right'
""",
    interfaces=("feet", "bearing_left", "bearing_right"),
    mesh_size=lambda v: v["base_thickness"],
    material=CAST_IRON,
)
