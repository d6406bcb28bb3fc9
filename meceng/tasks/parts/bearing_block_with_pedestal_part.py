"""Part 66: the bearing block with pedestal, a bearing housing standing on a wider foot plate.

A rectangular housing with the shaft bore stands centred on a larger rectangular pedestal (foot)
plate. Two sets of 45-degree chamfers sit on precisely named edges (the paper reports that models
struggle with exactly these): the two upper edges of the housing that run parallel to the bore
axis, and the four upper outer edges of the pedestal plate. Both chamfer sets are large enough to be
seen by the metrics: over the ranges the housing chamfers remove >= 2 % of the volume, the pedestal
chamfers >= 2 % (checked in tests/test_parts_rotor.py), so chamfering the wrong edges or none fails
the mass and mesh metrics.

Frame: origin at the centre of the pedestal's bottom face, bore axis parallel to x at
(y, z) = (0, axis_height), z up. Interfaces: 'bore' (the bore's cylindrical surface: the joint to
the rotor's seat in assemblies 74 and 75) and 'bottom' (the pedestal's bottom face: bolted to the
ground).

Ranges: the housing top chamfer leaves >= 13 mm of material between the bore and the chamfer face
and >= 24 mm of flat top face; the pedestal chamfer stays >= 5 mm away from the housing's side faces;
the bore stays >= 57 mm above the pedestal plate. maxh = bearing_width / 4 (10-15 mm) gives ~2
elements through the pedestal plate (20-25 mm); the GT has ~900-1300 nodes.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import CAST_IRON, PartModel
from meceng.tasks.parts.masters_rotor import BLOCK_MASTERS, names


def _derive(v: dict) -> dict:
    return {"block_height": round(v["axis_height"] + v["shaft_radius"] + v["top_wall"], 7)}


TASK = PartModel(
    id=66,
    name="bearing block with pedestal part",
    description="""
A bearing block with pedestal: a rectangular bearing housing with a cylindrical through bore for a
shaft stands centred on a wider rectangular pedestal plate; both are one solid. Coordinate frame: the
origin is the centre of the pedestal plate's bottom face, the x-axis is parallel to the bore axis and
the z-axis points up. The pedestal plate has width foot_width = {foot_width} m along x, length
foot_length = {foot_length} m along y and thickness foot_thickness = {foot_thickness} m, so it occupies
-{foot_width}/2 <= x <= {foot_width}/2, -{foot_length}/2 <= y <= {foot_length}/2 and
0 <= z <= {foot_thickness}. The housing has width bearing_width = {bearing_width} m along x and length
housing_length = {housing_length} m along y and reaches from the top of the plate up to block_height =
axis_height + shaft_radius + top_wall = {block_height} m (axis height axis_height = {axis_height} m, bore
radius shaft_radius = {shaft_radius} m, wall thickness above the bore top_wall = {top_wall} m), so it
occupies -{bearing_width}/2 <= x <= {bearing_width}/2, -{housing_length}/2 <= y <= {housing_length}/2
and {foot_thickness} <= z <= {block_height}. The bore is a cylindrical hole of radius shaft_radius =
{shaft_radius} m through the whole housing along x; its axis is the line y = 0, z = {axis_height}.
Chamfers (all 45 degrees, the given length measured along both adjacent faces): (1) the two upper
edges of the housing that are parallel to the bore axis, i.e. the edges where the housing's top face
z = {block_height} meets its side faces y = -{housing_length}/2 and y = +{housing_length}/2, get a
chamfer of top_chamfer = {top_chamfer} m; the edges of the top face that are parallel to y are not
chamfered. (2) The four upper outer edges of the pedestal plate, where the plate's top face
z = {foot_thickness} meets its four side faces x = -{foot_width}/2, x = +{foot_width}/2, y = -{foot_length}/2
and y = +{foot_length}/2, get a
chamfer of foot_chamfer = {foot_chamfer} m (the chamfers meet in mitred corners); the vertical edges and
the bottom edges of the plate and the edges where the housing meets the plate are not chamfered. There
are no other chamfers, fillets or holes. Define two interfaces: the cylindrical surface of the bore
named 'bore' and the bottom face of the pedestal plate (z = 0) named 'bottom'.
""",
    params=(
        *BLOCK_MASTERS,
        Param("foot_width", 0.1, 0.12, "m"),
        Param("foot_length", 0.22, 0.26, "m"),
        Param("foot_thickness", 0.02, 0.025, "m"),
        Param("housing_length", 0.1, 0.13, "m"),
        Param("top_wall", 0.015, 0.025, "m"),
        Param("top_chamfer", 0.028, 0.038, "m"),
        Param("foot_chamfer", 0.01, 0.014, "m"),
    ),
    master=names(BLOCK_MASTERS),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "Chamfer", "NamedFaces", "GenerateMesh",
                "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
foot = Box(Pnt(-foot_width / 2, -foot_length / 2, 0), Pnt(foot_width / 2, foot_length / 2, foot_thickness))
housing = Box(Pnt(-bearing_width / 2, -housing_length / 2, foot_thickness),
              Pnt(bearing_width / 2, housing_length / 2, block_height))
shape = foot + housing
# (1) the housing's two upper edges parallel to x
top_edges = [shape.edges.Nearest(Pnt(0, s * housing_length / 2, block_height)) for s in (-1, 1)]
shape = shape.MakeChamfer(top_edges, top_chamfer)
# (2) the pedestal plate's four upper outer edges
foot_edges = [shape.edges.Nearest(Pnt(0, s * foot_length / 2, foot_thickness)) for s in (-1, 1)]
foot_edges += [shape.edges.Nearest(Pnt(s * foot_width / 2, 0, foot_thickness)) for s in (-1, 1)]
shape = shape.MakeChamfer(foot_edges, foot_chamfer)
# the cutting tool reaches beyond the housing, so that no boolean works on coincident faces
shape = shape - Cylinder(Pnt(-bearing_width, 0, axis_height), X, r=shaft_radius, h=2 * bearing_width)
shape.faces.Nearest(Pnt(0, 0, axis_height + shaft_radius)).name = 'bore'
shape.faces.Min(Z).name = 'bottom'
""",
    interfaces=("bore", "bottom"),
    mesh_size=lambda v: v["bearing_width"] / 4,
    material=CAST_IRON,
)
