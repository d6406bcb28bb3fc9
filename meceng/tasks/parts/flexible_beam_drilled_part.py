"""Part 57: the flexible drilled beam, a cuboid beam with a row of holes drilled through its
height (the paper's "beam with a hole").

Same outer dimensions (master parameters), frame and interfaces as the plain beam (part 54): left
end face centre at the origin, axis along x, 'left' end face at x = 0 and 'right' end face at
x = beam_length, so the flexible pendulum and the cantilever beam (assemblies 76, 77) can use it in
place of the plain beam. The end faces stay untouched by the holes.

4-6 holes of diameter 0.45-0.6 times the beam width are drilled along z through the full height,
centred on the beam axis (y = 0) and equally spaced (hole i at (i - 1/2) beam_length / n_holes),
so that every ligament beside a hole is at least 0.2 beam_width = 6 mm wide, the holes never touch
each other or the end faces, and leaving them out changes the volume by at least
4 pi 0.45^2 0.03 / (4 * 0.8) = 2.4 %. A single hole in a 0.8 m beam would hide below the 1 %
mass tolerance. maxh = beam_height / 2 as for the plain beam; Netgen refines the holes by their
curvature.
"""

from __future__ import annotations

from meceng.tasks.base import Param, round_significant
from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_beam import BEAM_MASTERS


def _derive(v: dict) -> dict:
    n, length = int(v["n_holes"]), float(v["beam_length"])
    return {"hole_diameter": round_significant(v["hole_ratio"] * v["beam_width"], 3),
            "hole_x": tuple(round_significant((i + 0.5) * length / n, 4) for i in range(n))}


TASK = PartModel(
    id=57,
    name="flexible beam drilled part",
    description="""
A straight flexible beam with rectangular cross section and a row of drilled through holes: length
beam_length = {beam_length} m along the x-axis, width beam_width = {beam_width} m along y and height
beam_height = {beam_height} m along z. The centre of the left end face lies at the origin, so the beam
occupies 0 <= x <= {beam_length}, -{beam_width}/2 <= y <= {beam_width}/2 and -{beam_height}/2 <= z <=
{beam_height}/2. n_holes = {n_holes} cylindrical holes of diameter hole_diameter = {hole_diameter} m are
drilled through the beam along the z-axis, each through the full height from the bottom face
(z = -{beam_height}/2) to the top face (z = {beam_height}/2). The hole axes lie in the plane y = 0 and
are equally spaced along the beam, hole i at x = (i - 1/2) * beam_length / n_holes (i = 1..{n_holes}),
i.e. (rounded to 4 significant digits) at the x-positions hole_x = {hole_x} m. Define two interfaces: the left end face (x = 0) named
'left' and the right end face (x = {beam_length}) named 'right'.
""",
    params=(*BEAM_MASTERS, Param("n_holes", 4, 6, integer=True), Param("hole_ratio", 0.45, 0.6)),
    master=("beam_length", "beam_width", "beam_height"),
    derive=_derive,
    components=("Box", "Cylinder", "BooleanCut", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
shape = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))
for x in hole_x:
    shape = shape - Cylinder(Pnt(x, 0, -beam_height / 2), Z, r=hole_diameter / 2, h=beam_height)
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
""",
    interfaces=("left", "right"),
    mesh_size=lambda v: v["beam_height"] / 2,
    material=STEEL,
)
