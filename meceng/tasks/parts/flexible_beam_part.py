"""Part 54: the plain flexible beam, a cuboid with one interface at each end face.

The beam's outer dimensions are master parameters (flexible pendulum, cantilever beam). The
frame is fixed by the text (left end face centre at the origin, axis along x), so the surfaces of
two correct answers coincide without any alignment.
"""

from __future__ import annotations

from meceng.tasks.part_base import STEEL, PartModel
from meceng.tasks.parts.masters_beam import BEAM_MASTERS

TASK = PartModel(
    id=54,
    name="flexible beam part",
    description="""
A straight flexible beam with rectangular cross section: length beam_length = {beam_length} m along
the x-axis, width beam_width = {beam_width} m along y and height beam_height = {beam_height} m along z.
The centre of the left end face lies at the origin, so the beam occupies 0 <= x <= {beam_length},
-{beam_width}/2 <= y <= {beam_width}/2 and -{beam_height}/2 <= z <= {beam_height}/2.
Define two interfaces: the left end face (x = 0) named 'left' and the right end face
(x = {beam_length}) named 'right'.
""",
    params=BEAM_MASTERS,
    master=("beam_length", "beam_width", "beam_height"),
    components=("Box", "NamedFaces", "GenerateMesh", "ImportMeshToFEM", "HCBModes"),
    geometry_code="""
shape = Box(Pnt(0, -beam_width / 2, -beam_height / 2), Pnt(beam_length, beam_width / 2, beam_height / 2))
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
""",
    interfaces=("left", "right"),
    mesh_size=lambda v: v["beam_height"] / 2,
    material=STEEL,
)
