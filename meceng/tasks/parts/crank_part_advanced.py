"""Part 70: the advanced flexible crank, two chamfered cylindrical bosses joined by a thinner web.

The crank of the flexible slider crank (assembly 84) turns about a ground pin in 'hole_a' (axis =
z-axis, in the large hub) and carries the crank pin, which connects it to the rod, in 'hole_b'
(axis through (crank_length, 0, 0), in the smaller boss). The part is symmetric to its mid-plane
z = 0. crank_length, pin_radius and thickness (the bosses' length along the joint axes) are master
parameters. Own ranges keep the geometry valid for every master draw: hub and boss leave at least
5 mm of material around the largest hole, hub_radius + boss_radius <= 38 mm < 50 mm <= crank_length
(at least 12 mm of exposed web), the web (<= 22 mm wide) is narrower than the smaller boss
(>= 26 mm across), the web thickness is 35-45 % and the chamfer 15-20 % of the boss thickness, so the
chamfers end at least 7 % of the thickness (>= 0.7 mm) above and below the web.

The web and the chamfers are what make the crank "advanced": over the ranges the four boss chamfers
remove 2-11 % of the volume, a full-thickness web instead of the thin one would add 5-57 %. The mass
depends mostly on the bosses: a 5 % longer crank adds only 0.6-2.7 % mass, but it moves the boss by
2.5-4 mm, which the mesh metric sees.

maxh = web_thickness / 1.5 puts about two elements through the web (the thinnest wall).
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters


def _derive(v: dict) -> dict:
    t = v["thickness"]
    return {"web_thickness": round_significant(v["web_ratio"] * t, 3),
            "chamfer": round_significant(v["chamfer_ratio"] * t, 2)}


TASK = PartModel(
    id=70,
    name="crank part advanced",
    description="""
An advanced flexible crank made of two cylindrical bosses connected by a thinner web, with a circular
joint hole through each boss. Coordinate frame: the axis of the first hole is the z-axis, the axis of
the second hole is parallel to z through the point (crank_length, 0, 0) with crank length
crank_length = {crank_length} m, and the crank is symmetric to its mid-plane z = 0. The hub (the boss
around the first hole) is a solid circular cylinder of radius hub_radius = {hub_radius} m whose axis
is the z-axis; the second boss is a solid circular cylinder of radius boss_radius = {boss_radius} m
whose axis is the second hole's axis; both have the thickness thickness = {thickness} m along z
(-{thickness}/2 <= z <= {thickness}/2). The web is a rectangular bar from axis to axis,
0 <= x <= {crank_length}, -{web_width}/2 <= y <= {web_width}/2 and -{web_thickness}/2 <= z <=
{web_thickness}/2, with web width web_width = {web_width} m and web thickness web_thickness =
{web_thickness} m; hub, boss and web are fused into one solid. The outer circular edges of both
bosses, at the top (z = {thickness}/2) and at the bottom (z = -{thickness}/2), four edges in total,
are chamfered at 45 degrees with the chamfer distance chamfer = {chamfer} m on both adjacent faces.
Both holes have the radius pin_radius = {pin_radius} m and go through the whole thickness; the hole
edges are not chamfered and there are no other features (the web's edges are sharp). Define two
interfaces: the cylindrical surface of the hole at the origin (the crank's bearing on the ground pin)
named 'hole_a' and the cylindrical surface of the hole at x = {crank_length} (the crank pin connecting
to the rod) named 'hole_b'.
""",
    params=(*masters("crank_length", "pin_radius", "thickness"), Param("hub_radius", 0.017, 0.022, "m"),
            Param("boss_radius", 0.013, 0.016, "m"), Param("web_width", 0.016, 0.022, "m"),
            Param("web_ratio", 0.35, 0.45, digits=2), Param("chamfer_ratio", 0.15, 0.2, digits=2)),
    master=("crank_length", "pin_radius", "thickness"),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanFuse", "BooleanCut", "Chamfer", "NamedFaces", "GenerateMesh",
                "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
hub = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=hub_radius, h=thickness)
hub = hub.MakeChamfer([hub.edges.Max(Z), hub.edges.Min(Z)], chamfer)  # the two circular edges
boss = Cylinder(Pnt(crank_length, 0, -thickness / 2), Z, r=boss_radius, h=thickness)
boss = boss.MakeChamfer([boss.edges.Max(Z), boss.edges.Min(Z)], chamfer)
web = Box(Pnt(0, -web_width / 2, -web_thickness / 2), Pnt(crank_length, web_width / 2, web_thickness / 2))
hole_a = Cylinder(Pnt(0, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
hole_b = Cylinder(Pnt(crank_length, 0, -thickness / 2), Z, r=pin_radius, h=thickness)
shape = hub + boss + web - hole_a - hole_b
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'hole_a'
shape.faces.Nearest(Pnt(crank_length + pin_radius, 0, 0)).name = 'hole_b'
""",
    interfaces=("hole_a", "hole_b"),
    mesh_size=lambda v: v["web_thickness"] / 1.5,
    material=STEEL,
)
