"""Part 55: the flexible beam with fillets, a cuboid beam whose four long edges are rounded.

Same outer dimensions (master parameters), frame and interfaces as the plain beam (part 54): left
end face centre at the origin, axis along x, 'left' end face at x = 0 and 'right' end face at
x = beam_length, so the flexible pendulum and the cantilever beam (assemblies 76, 77) can use it in
place of the plain beam. The end faces are rectangles with rounded corners.

The fillet radius is 0.42-0.47 times the beam height (the height is never larger than the width):
below half the height, so a flat strip remains on the side faces for every combination of the
master parameters, and large enough that (1) leaving the fillets out changes the volume by at
least (4 - pi) 0.42^2 * 0.02 / 0.05 = 6 % and (2) Netgen's curvature refinement, which sizes the
fillet faces by their radius whatever maxh says, keeps a 0.8 m beam below ~6000 nodes.
maxh = beam_height / 2 (two elements over the height), as for the plain beam.
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_beam import BEAM_MASTERS


def _derive(v: dict) -> dict:
    return {"fillet_radius": round_significant(v["fillet_ratio"] * v["beam_height"], 3)}


TASK = PartModel(
    id=55,
    name="flexible beam fillets part",
    description="""
A straight flexible beam with rectangular cross section and rounded long edges: length beam_length =
{beam_length} m along the x-axis, width beam_width = {beam_width} m along y and height beam_height =
{beam_height} m along z. The centre of the left end face lies at the origin, so the beam occupies
0 <= x <= {beam_length}, -{beam_width}/2 <= y <= {beam_width}/2 and -{beam_height}/2 <= z <= {beam_height}/2.
The four long edges of the beam (the edges parallel to the x-axis, at y = +-{beam_width}/2, z =
+-{beam_height}/2) are rounded over the full length with fillet radius fillet_radius = {fillet_radius} m;
no other edge is rounded, so each end face is a {beam_width} m x {beam_height} m rectangle with corners
rounded by {fillet_radius} m.
Define two interfaces: the left end face (x = 0) named 'left' and the right end face
(x = {beam_length}) named 'right'.
""",
    params=(*BEAM_MASTERS, Param("fillet_ratio", 0.42, 0.47)),
    master=("beam_length", "beam_width", "beam_height"),
    derive=_derive,
    components=("Box", "Fillet", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
shape = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))
longEdges = [shape.edges.Nearest(Pnt(beam_length / 2, sy * beam_width / 2, sz * beam_height / 2))
             for sy in (-1, 1) for sz in (-1, 1)]
shape = shape.MakeFillet(longEdges, fillet_radius)
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
""",
    interfaces=("left", "right"),
    mesh_size=lambda v: v["beam_height"] / 2,
    material=STEEL,
)
