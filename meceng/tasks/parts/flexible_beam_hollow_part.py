"""Part 56: the flexible hollow beam, a thin-walled rectangular tube (the paper's "thin-walled
profile").

Same outer dimensions (master parameters), frame and interfaces as the plain beam (part 54): left
end face centre at the origin, axis along x; the interfaces are the two end faces, here the
rectangular rings 'left' (x = 0) and 'right' (x = beam_length), so the flexible pendulum and the
cantilever beam (assemblies 76, 77) can use it in place of the plain beam.

The wall thickness of 2.5-4 mm is at most a fifth of the smallest height (20 mm), so the cavity
is at least 12 mm x 22 mm; a 5 % thicker wall changes the mass by ~5 %. Two elements across the
wall would need ~10^5 nodes for a 0.8 m tube: the ground truth meshes with maxh =
min(beam_height / 2, 3 wall_thickness), one tetrahedron across the wall, <= ~4500 nodes. All faces
are planar, so the surfaces of two correct answers coincide exactly; at this maxh two correct
constructions (a box cut by a box, an extruded ring) gave first three eigenfrequencies within
0.7 % of each other (at maxh = beam_height / 2: up to 2.3 %).
"""

from __future__ import annotations

from meceng.tasks.base import Param
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_beam import BEAM_MASTERS

TASK = PartModel(
    id=56,
    name="flexible beam hollow part",
    description="""
A straight, thin-walled flexible hollow beam: a rectangular tube with length beam_length = {beam_length} m
along the x-axis, outer width beam_width = {beam_width} m along y, outer height beam_height =
{beam_height} m along z and the same wall thickness wall_thickness = {wall_thickness} m on all four
sides. The centre of the left end face lies at the origin, so the outer surface bounds 0 <= x <=
{beam_length}, -{beam_width}/2 <= y <= {beam_width}/2 and -{beam_height}/2 <= z <= {beam_height}/2, and
the rectangular cavity, centred on the x-axis, occupies -({beam_width}/2 - {wall_thickness}) <= y <=
{beam_width}/2 - {wall_thickness} and -({beam_height}/2 - {wall_thickness}) <= z <= {beam_height}/2 -
{wall_thickness} over the full length 0 <= x <= {beam_length} (the tube is open at both ends). All
inner and outer edges are sharp (no fillets). Define two interfaces: the left end face (the
rectangular ring at x = 0) named 'left' and the right end face (the rectangular ring at x =
{beam_length}) named 'right'.
""",
    params=(*BEAM_MASTERS, Param("wall_thickness", 0.0025, 0.004, "m")),
    master=("beam_length", "beam_width", "beam_height"),
    components=("Box", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
outer = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))
inner = Box(Pnt(0, -beam_width / 2 + wall_thickness, -beam_height / 2 + wall_thickness),
            Pnt(beam_length, beam_width / 2 - wall_thickness, beam_height / 2 - wall_thickness))
shape = outer - inner
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
""",
    interfaces=("left", "right"),
    mesh_size=lambda v: min(v["beam_height"] / 2, 3 * v["wall_thickness"]),
    material=STEEL,
)
