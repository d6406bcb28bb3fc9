"""Part 72: the advanced flexible slider, a block with chamfered long edges, a guide groove and a pin bore.

The slider of the flexible slider crank (assembly 84) carries the rod's small end in its 'bore'
(axis = z-axis, through the block's centre) and runs on a rail along x that engages the rectangular
groove in its bottom face; the three groove faces are the interface 'guide' (the prismatic joint of
the assembly acts there). Only pin_radius is a master parameter. Own ranges keep the geometry valid
for every draw: the groove floor stays at least 12 mm below the bore axis (>= 4 mm of material
between groove and the largest bore), the chamfers (<= 7 mm) leave at least 3.5 mm of flat bottom
face beside the groove and end at least 5 mm above and below the bore, and the groove is narrower
than the block by at least 21 mm.

Over the ranges the four chamfers remove 2.1-9 % of the volume, the groove 2.1-10 %. maxh = min(groove_depth, slider_height / 2 - groove_depth - pin_radius) / 1.5 gives about two elements
across the groove flanks and the ligament between groove floor and bore, whichever is thinner.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters

TASK = PartModel(
    id=72,
    name="slider part advanced",
    description="""
An advanced flexible slider made of a rectangular block with chamfered long edges, a rectangular guide
groove in its bottom face and a circular through bore for the joint pin. Coordinate frame: the centre
of the (unchamfered) block is at the origin and the bore's axis is the z-axis. The block has length
slider_length = {slider_length} m along x (the sliding direction), height slider_height =
{slider_height} m along y and width slider_width = {slider_width} m along z, so it occupies
-{slider_length}/2 <= x <= {slider_length}/2, -{slider_height}/2 <= y <= {slider_height}/2 and
-{slider_width}/2 <= z <= {slider_width}/2. The four edges of the block parallel to x (at
y = +-{slider_height}/2, z = +-{slider_width}/2) are chamfered at 45 degrees with the chamfer distance
chamfer = {chamfer} m on both adjacent faces; all other edges are sharp. The guide groove runs along
the whole length of the bottom face (y = -{slider_height}/2), centred in z: it has the width
groove_width = {groove_width} m along z and the depth groove_depth = {groove_depth} m along y, so the
material removed is -{slider_length}/2 <= x <= {slider_length}/2,
-{slider_height}/2 <= y <= -{slider_height}/2 + {groove_depth} and
-{groove_width}/2 <= z <= {groove_width}/2; its edges are sharp. The bore has the radius
pin_radius = {pin_radius} m and goes through the whole block along z; it is not chamfered. Define two
interfaces: the cylindrical surface of the bore (the joint with the rod) named 'bore', and the three
faces of the groove (its floor at y = -{slider_height}/2 + {groove_depth} and its two side faces at
z = +-{groove_width}/2), which run on the guide rail, together named 'guide'.
""",
    params=(*masters("pin_radius"), Param("slider_length", 0.06, 0.09, "m"), Param("slider_height", 0.04, 0.055, "m"),
            Param("slider_width", 0.035, 0.045, "m"), Param("groove_width", 0.01, 0.014, "m"),
            Param("groove_depth", 0.005, 0.008, "m", digits=2), Param("chamfer", 0.005, 0.007, "m", digits=2)),
    master=("pin_radius",),
    components=("Box", "Cylinder", "BooleanCut", "Chamfer", "NamedFaces", "GenerateMesh", "ImportMeshToFEM",
                "HCBModes"),
    geometry_code="""
block = Box(Pnt(-slider_length / 2, -slider_height / 2, -slider_width / 2),
            Pnt(slider_length / 2, slider_height / 2, slider_width / 2))
long_edges = [block.edges.Nearest(Pnt(0, sy * slider_height / 2, sz * slider_width / 2))
              for sy in (-1, 1) for sz in (-1, 1)]
block = block.MakeChamfer(long_edges, chamfer)
groove = Box(Pnt(-slider_length / 2, -slider_height / 2, -groove_width / 2),
             Pnt(slider_length / 2, -slider_height / 2 + groove_depth, groove_width / 2))
shape = block - groove - Cylinder(Pnt(0, 0, -slider_width / 2), Z, r=pin_radius, h=slider_width)
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'bore'
shape.faces.Nearest(Pnt(0, -slider_height / 2 + groove_depth, 0)).name = 'guide'
shape.faces.Nearest(Pnt(0, -slider_height / 2 + groove_depth / 2, groove_width / 2)).name = 'guide'
shape.faces.Nearest(Pnt(0, -slider_height / 2 + groove_depth / 2, -groove_width / 2)).name = 'guide'
""",
    interfaces=("bore", "guide"),
    mesh_size=lambda v: min(v["groove_depth"], v["slider_height"] / 2 - v["groove_depth"] - v["pin_radius"]) / 1.5,
    material=STEEL,
)
