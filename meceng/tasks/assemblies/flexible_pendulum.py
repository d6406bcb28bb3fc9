"""Assembly 76: a flexible beam hinged at its left end face, released from an angle, swings under gravity.

The beam is one of the parts 54-57, drawn per variation (as for the cantilever beam, 77); all four
share the frame (left end face centre at the origin, axis along x) and the interfaces 'left' and
'right', so one text fits all. The hinge is the origin: the beam's frame is placed there with
RotationMatrixY(pi/2 - theta0), its axis at theta0 from the downward vertical, and a revolute joint
about the global y-axis (GenericJoint [1, 1, 1, 1, 0, 1], ground marker first) holds its 'left'; gravity
along -z swings it in the x-z plane, bending it across its thin direction (the height). The joint
locks the rotations about x and z relative to the ground marker's frame: an initial rotation about y is
free, a hinge about another axis makes the solver fail at once. 7 + 12 = 19 coordinates, one
Euler-parameter and 5 joint constraints: 13 degrees of freedom, none redundant.

The 'left' marker sits at the weighted centre of the end face: exactly at the origin for the flat
rectangular (54, 57) and ring (56) faces, ~7 micrometres off for the faceted rounded corners of the
fillet beam (55; seed 3: [0, -0.9, 7.4] um); the solver closes that in the first step, invisibly in the
swing (below).

Ranges and end time: theta0 = 30-90 degrees (90 = released horizontally). The rigid pendulum reaches
the vertical after the quarter period sqrt(J / (m g d)) K(sin^2(theta0 / 2)) = 0.26-0.43 s (J / (m d)
~ 2 L / 3 for every beam, L = 0.4-0.8 m), so in 0.5 s every draw swings through the bottom; 250
steps of 2 ms, at most 0.017 rad per step (L = 0.4 m from the horizontal, 8.6 rad/s at the bottom).
The beams are stiff: their fixed-interface eigenfrequencies start at 250-380 Hz against a ~1 Hz swing,
the modal coordinates stay at ~1e-4 or less: the motion is the rigid pendulum's. GT run (load + simulate):
0.5-1.1 s on a loaded machine for 221-5501 nodes (0.8 m fillet beam).

Physics check (tests/test_assemblies_beam_table.py): the beam's rotation angle follows the rigid
physical pendulum J phi'' = m g (c_x cos(phi) + c_z sin(phi)) (m, c, J about the hinge from the beam's
FEM inertia) to within 2e-4 rad (measured 2-9e-5 rad over swings of 1-1.9 rad), and it passes the
vertical after the closed-form quarter period to 2e-4 (measured 1-3e-5).
"""

from __future__ import annotations

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_beam import BEAM_MASTERS

BEAMS = ("flexible_beam_part", "flexible_beam_fillets_part", "flexible_beam_hollow_part", "flexible_beam_drilled_part")

TASK = AssemblyModel(
    id=76,
    name="flexible pendulum",
    description="""
A flexible pendulum: the flexible beam part 'beam' (length beam_length = {beam_length} m) hangs from a hinge
at its left end face and swings under gravity in the global x-z plane (the global z-axis points up).
The hinge point is the origin: place the beam's own frame (left end face centre at its origin, beam axis
along its x-axis) with reference position [0, 0, 0] and reference rotation matrix RotationMatrixY(pi/2 - theta0),
where theta0 = {theta0_deg} degrees (convert it to radians) is the initial angle between the beam axis and
the downward vertical: the beam axis then points along [sin(theta0), 0, -cos(theta0)], the right end face
on the +x side of the hinge, below it. The left end face (interface 'left') is connected to the ground by
a revolute joint about the global y-axis (an InterfaceJoint: Exudyn's GenericJoint object with
constrainedAxes = [1, 1, 1, 1, 0, 1]) between a
ground marker at [0, 0, 0] (first in markerNumbers) and the beam's 'left'. Gravity g = {g} m/s^2 acts on the
beam in negative global z-direction. The beam is released from rest in its undeformed reference position.
Create the beam, then the ground and its marker, then the joint.
""",
    params=(*BEAM_MASTERS, Param("theta0_deg", 30.0, 90.0, "deg"), Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("beam", BEAMS),),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint"),
    model_code="""
theta0 = theta0_deg * np.pi / 180
femBeam = FEMinterface()
femBeam.LoadFromFile('beam.npz')
beam = mbs.CreateFFRFReducedOrderObject('beam', femBeam, referencePosition=[0, 0, 0],
                                        referenceRotationMatrix=RotationMatrixY(np.pi / 2 - theta0),
                                        gravity=[0, 0, -g])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mHinge = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mHinge, beam['beam:left']], constrainedAxes=[1, 1, 1, 1, 0, 1]))
""",
    sim=SimSettings(end_time=0.5, steps=250),
)
