"""Assembly 77: a flexible beam clamped at its left end face, loaded by gravity and a tip force.

The beam is one of the parts 54-57, drawn per variation; all four share the frame (left end face
centre at the origin, axis along x) and the interfaces 'left' and 'right', so one text fits all.
Gravity and the tip force act along -z, across the beam's smaller dimension (height): the static
tip deflection is a millimetre or less, so the reduced linear model stays in its range.
"""

from __future__ import annotations

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_beam import BEAM_MASTERS

BEAMS = ("flexible_beam_part", "flexible_beam_fillets_part", "flexible_beam_hollow_part", "flexible_beam_drilled_part")

TASK = AssemblyModel(
    id=77,
    name="cantilever beam",
    description="""
A cantilever beam: the flexible beam part 'beam' (length beam_length = {beam_length} m) lies with its own
frame equal to the global frame, i.e. its left end face centre at the origin and its axis along the
global x-axis. Its left end face (interface 'left') is clamped to the ground: an InterfaceJoint (Exudyn's GenericJoint
object, all translations and rotations locked) between a ground marker at [0, 0, 0] (first in markerNumbers)
and the beam's 'left'. Gravity g = {g} m/s^2 acts on the beam in negative global
z-direction, and a force of magnitude tip_force = {tip_force} N acts at the right end face (interface
'right') in negative global z-direction. The beam starts at rest in its undeformed reference position.
""",
    params=(*BEAM_MASTERS, Param("g", 9.81, 9.81, "m/s^2"), Param("tip_force", 5.0, 50.0, "N")),
    parts=(PartSlot("beam", BEAMS),),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code="""
femBeam = FEMinterface()
femBeam.LoadFromFile('beam.npz')
beam = mbs.CreateFFRFReducedOrderObject('beam', femBeam, referencePosition=[0, 0, 0], gravity=[0, 0, -g])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mClamp = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mClamp, beam['beam:left']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddLoad(Force(markerNumber=beam['beam:right'], loadVector=[0, 0, -tip_force]))
""",
    sim=SimSettings(end_time=0.1, steps=200),
)
