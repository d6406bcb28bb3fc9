"""Assembly 73: the unbalanced rotor (part 52) in a flexible bearing block (part 51) and a rigid
floating bearing, spinning and driven by a torque under gravity.

One block, two seats: the block's bore holds the rotor's left seat as the locating bearing (a
revolute joint about the shaft axis, the global x-axis); the right seat runs in a rigid floating
bearing fixed to the ground at the right seat's centre, a joint that locks only the two radial
translations (y, z). This is the usual locating / floating bearing arrangement (as the rigid rotor
of task 34): the shaft's axial position is fixed once, so the axial misfit of the interface centres
(the weighted centres of faceted cylinder surfaces are off their nominal points by 5-25 micrometres)
does not prestress the shaft; a second revolute joint at the right seat gave a constant axial force
of ~1 kN between the bearings (5 kN in 75). The left bearing fixes the rotor's rigid motion up to the spin,
the floating bearing then holds the right seat's deflection, which the rotor's Hurty-Craig-Bampton
static modes carry (6 per two-interface part: the seats' relative motion), so no constraint is
redundant: 2 x (7 + 12) = 38 coordinates, 2 Euler-parameter + 6 clamp + 5 + 2 joint constraints,
23 degrees of freedom (the rigid system has one, the spin).

The block stands with its own frame equal to the global frame (bottom on z = 0, bore axis on the line
y = 0, z = axis_height); the rotor's frame is shifted by [-bearing_width/2, 0, axis_height], so its
left seat centre meets the bore centre [0, 0, axis_height] and its right seat centre is
[bearing_span, 0, axis_height]. At t = 0 the joined markers are 6-27 micrometres apart (the weighted
interface centres of the two meshes), the clamp's exactly coincide (planar faces).

The rotor starts with omega0 = 40-80 rad/s about +x and a drive torque of 1-3 N*m accelerates it
(closed forms over the ranges: m ~ 9-14 kg, J_x ~ 0.018-0.039 kg*m^2, alpha ~ 28-155 rad/s^2).
Gravity acts along -z on both parts; the unbalance hole on the disc's +z side puts the rotor's centre
of mass e ~ 1.3-2.6 mm below the axis, so the rotating force m e omega^2 (~ 26-245 N) is of the order
of the weight (~ 88-137 N): the unbalance shows in the bearing forces. In 0.2 s the rotor turns 9-19
rad, <= 0.11 rad per step of 1 ms (200 steps; 400 steps change the final spin by < 1e-4). The parts
are stiff: the motion is the rigid rotor's plus micrometre vibrations (the joints pull the interface
centres together in the first step and gravity sets in on undeformed parts).

Physics checks (tests/test_assemblies_rotor.py): the spin follows J theta'' = T - m g e sin(theta)
(J about the axis, m and e from the rotor's FEM inertia), and the bearing forces on the rotor are
m g + m a_COM: a constant equal to the weight plus the rotating unbalance term m e omega^2.
"""

from __future__ import annotations

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_rotor import ROTOR_MASTERS

#: the assembly's own parameters, shared with 74
DRIVE_PARAMS = (Param("omega0", 40.0, 80.0, "rad/s"), Param("torque", 1.0, 3.0, "N*m"), Param("g", 9.81, 9.81, "m/s^2"))


def derive(v: dict) -> dict:
    return {"rotor_x": round(-v["bearing_width"] / 2, 7)}


def description(block_text: str) -> str:
    """The text of 73 and 74: the same placement, joints and loads, only the block differs."""
    return """
An unbalanced rotor in a bearing block: the flexible bearing block 'block' (""" + block_text + """) stands
on the ground and carries the left bearing seat of the flexible unbalanced rotor 'rotor'; the rotor's right
bearing seat runs in a rigid floating bearing fixed to the ground. Placement of the parts' own frames in the
global frame (the global z-axis points up): the block with reference position [0, 0, 0] and the identity
rotation, so its bottom lies on the plane z = 0 and its bore axis is the line y = 0, z = axis_height =
{axis_height} m; the rotor with reference position [rotor_x, 0, axis_height] = [{rotor_x}, 0, {axis_height}]
(rotor_x = -bearing_width/2, bearing_width = {bearing_width} m) and the identity rotation, so that its axis
lies on the bore axis, its left seat (interface 'left') sits in the block's bore with the seat's centre at
the bore's centre [0, 0, {axis_height}], its right seat (interface 'right') has its centre at [bearing_span,
0, axis_height] = [{bearing_span}, 0, {axis_height}] and its unbalance hole is on the +z side. Joints (each an InterfaceJoint: Exudyn's GenericJoint object between two markers,
constrained axes in global coordinates, the first-named marker first in markerNumbers):
(1) a clamp (all translations and rotations locked) between a ground marker at [0, 0, 0] and the block's
bottom (interface 'bottom'); (2) the locating bearing: a revolute joint about the global x-axis
(constrainedAxes = [1, 1, 1, 0, 1, 1]) between the block's 'bore' and the rotor's 'left'; (3) the rigid
floating bearing: a joint between a ground marker at the right seat's centre [{bearing_span}, 0,
{axis_height}] and the rotor's 'right' that locks only the translations along the global y- and z-axes
(constrainedAxes = [0, 1, 1, 0, 0, 0]; the seat may shift along the axis and tilt, so the block's bearing
alone locates the rotor axially). Gravity g = {g} m/s^2 acts on both parts in negative global z-direction.
The rotor starts with the initial angular velocity [omega0, 0, 0] with omega0 = {omega0} rad/s (zero initial
velocity of its reference point, which lies on the axis); the block starts at rest; both parts start
undeformed. A constant drive torque of torque = {torque} N*m about the global x-axis (load vector [torque,
0, 0]) acts on the rotor at its 'left' interface. Create the block and the rotor (in this order), then the
ground and its markers at [0, 0, 0] and at [{bearing_span}, 0, {axis_height}], then the joints in the order
given, then the torque.
"""


#: Placement, joints and loads of 73 and 74 (the block's slot is 'block', the rotor's 'rotor').
MODEL_CODE = """
femBlock = FEMinterface()
femBlock.LoadFromFile('block.npz')
block = mbs.CreateFFRFReducedOrderObject('block', femBlock, referencePosition=[0, 0, 0], gravity=[0, 0, -g])
femRotor = FEMinterface()
femRotor.LoadFromFile('rotor.npz')
rotor = mbs.CreateFFRFReducedOrderObject('rotor', femRotor, referencePosition=[rotor_x, 0, axis_height],
                                         gravity=[0, 0, -g], initialAngularVelocity=[omega0, 0, 0])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mBearing = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[bearing_span, 0, axis_height]))
mbs.AddObject(GenericJoint(markerNumbers=[mGround, block['block:bottom']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[block['block:bore'], rotor['rotor:left']], constrainedAxes=[1, 1, 1, 0, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[mBearing, rotor['rotor:right']], constrainedAxes=[0, 1, 1, 0, 0, 0]))
mbs.AddLoad(Torque(markerNumber=rotor['rotor:left'], loadVector=[torque, 0, 0]))
"""

TASK = AssemblyModel(
    id=73,
    name="rotor in bearing block",
    description=description("a rectangular block with a bore and a relief groove"),
    params=(*ROTOR_MASTERS, *DRIVE_PARAMS),
    parts=(PartSlot("block", ("bearing_block_part",)), PartSlot("rotor", ("unbalanced_rotor_part",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code=MODEL_CODE,
    sim=SimSettings(end_time=0.2, steps=200),
    derive=derive,
)
