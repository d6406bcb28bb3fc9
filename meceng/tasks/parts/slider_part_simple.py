"""Part 69: the simple flexible slider, a rectangular block with a pin bore.

The slider of the flexible slider crank (assembly 83) carries the rod's second joint in its 'bore'
(axis = z-axis, through the block's centre) and runs on a prismatic guide along x that supports
its bottom face 'guide' (y = -slider_height / 2). Only pin_radius is a master parameter; the block
is the part's own (it is deeper along z than the crank and rod are thick). The smallest block
half-height (17.5 mm) leaves at least 9.5 mm of material below and above the largest bore.

maxh = (min(slider_height, slider_width) / 2 - pin_radius) / 1.5 resolves the ligament between
bore and block faces with about two elements; the bore is 1.7-11 % of the block volume.
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_slider_crank import masters

TASK = PartModel(
    id=69,
    name="slider part simple",
    description="""
A simple flexible slider made of a rectangular block with a circular through bore for the joint
pin. Coordinate frame: the block's centre is at the origin and the bore's axis is the z-axis. The
block has length slider_length = {slider_length} m along x (the sliding direction), height
slider_height = {slider_height} m along y and width slider_width = {slider_width} m along z, so it
occupies -{slider_length}/2 <= x <= {slider_length}/2, -{slider_height}/2 <= y <= {slider_height}/2
and -{slider_width}/2 <= z <= {slider_width}/2. The bore has the radius pin_radius = {pin_radius} m
and goes through the whole block along z; there are no other features (no chamfers, no fillets).
Define two interfaces: the cylindrical surface of the bore (the joint with the rod) named 'bore' and
the bottom face of the block (y = -{slider_height}/2, resting on the guide) named 'guide'.
""",
    params=(*masters("pin_radius"), Param("slider_length", 0.06, 0.09, "m"), Param("slider_height", 0.035, 0.05, "m"),
            Param("slider_width", 0.03, 0.045, "m")),
    master=("pin_radius",),
    components=("Box", "Cylinder", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
block = Box(Pnt(-slider_length / 2, -slider_height / 2, -slider_width / 2),
            Pnt(slider_length / 2, slider_height / 2, slider_width / 2))
shape = block - Cylinder(Pnt(0, 0, -slider_width / 2), Z, r=pin_radius, h=slider_width)
shape.faces.Nearest(Pnt(pin_radius, 0, 0)).name = 'bore'
shape.faces.Min(Y).name = 'guide'
""",
    interfaces=("bore", "guide"),
    mesh_size=lambda v: (min(v["slider_height"], v["slider_width"]) / 2 - v["pin_radius"]) / 1.5,
    material=STEEL,
)
