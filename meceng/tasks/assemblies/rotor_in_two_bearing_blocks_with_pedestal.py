"""Assembly 75: the balanced rotor (part 53) in two flexible bearing blocks with pedestal (part 66
twice), spinning and driven by a torque.

The two blocks are two slots, 'block1' and 'block2', each its own part instance drawn with the same
seed and master values (so the same block twice), standing bearing_span apart: block1's frame at the
origin, block2's at [bearing_span, 0, 0]. The rotor's frame is shifted by [-(end_length +
bearing_width/2), 0, axis_height], so its left seat centre meets block1's bore centre [0, 0,
axis_height] and its right seat centre block2's [bearing_span, 0, axis_height]. ``end_length`` (the
length of the rotor's drive ends) is the rotor's own parameter, not a master: ``rotor_placement``
adds it to the instance's values, drawn from the rotor part's own values for the same seed (exactly as
the rotor's part instance draws it), so text and ground truth name the placement.

The left seat is located in block1's bore (a revolute joint about the global x-axis, the shaft
axis), the right seat runs in block2's bore as a floating bearing (only the radial translations y, z
locked), both blocks are clamped to the ground at their 'bottom'. Two revolute joints (both seats
located axially) would fight over the axial misfit of the interface centres (the weighted centres of
faceted cylinder surfaces lie 5-25 micrometres off their nominal points; one seat's was 18 micrometres
off axially): they prestressed the shaft with a constant axial force of 0.4-5.3 kN and bent the mean
bearing force 2 % away from the weight. The locating bearing fixes the rotor's rigid motion up to the
spin; the floating bearing holds the other seat's deflection, which the rotor's Hurty-Craig-Bampton
static modes carry: no redundant constraint. 3 x 19 coordinates, 3 Euler-parameter + 12 clamp + 5 + 2
joint constraints, 35 degrees of freedom. At t = 0 the joined bore and seat markers are 4-25
micrometres apart, the clamps' exactly coincide.

The balanced rotor is light (closed forms over the ranges: m ~ 4-8 kg, J_x ~ 1.0-2.9e-3 kg*m^2, a
tenth of 52's), so the drive torque is 0.05-0.15 N*m (alpha ~ 18-127 rad/s^2) on an initial spin of
40-80 rad/s: in 0.2 s it turns 9-18 rad, <= 0.1 rad per step of 1 ms. The keyway on the +z side leaves
a residual unbalance: the centre of mass lies e ~ 0.8-1.3 mm below the axis, m e omega^2 ~ 7-58 N
against a weight of ~ 40-80 N; its gravity torque (m g e / J <= 45 rad/s^2) never stalls the spin
(0.5 J omega0^2 >= 10 x 2 m g e). Physics checks
(tests/test_assemblies_rotor.py): the spin follows J theta'' = T - m g e sin(theta), and the bearing
forces on the rotor are the weight plus the rotating unbalance term m e omega^2.
"""

from __future__ import annotations

from typing import Any

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_rotor import ROTOR_MASTERS


def rotor_placement(values: dict[str, Any], parts: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """The balanced rotor's own ``end_length`` and its placement ``rotor_x`` = -(end_length + bearing_width/2)."""
    end_length = parts["rotor"]["end_length"]
    return {"end_length": end_length, "rotor_x": round(-(end_length + values["bearing_width"] / 2), 7)}


TASK = AssemblyModel(
    id=75,
    name="rotor in two bearing blocks with pedestal",
    description="""
A balanced rotor in two bearing blocks with pedestal: two identical flexible bearing blocks with pedestal,
'block1' and 'block2', stand on the ground bearing_span = {bearing_span} m apart and carry the two bearing
seats of the flexible balanced rotor 'rotor'. Placement of the parts' own frames in the global frame (the
global z-axis points up): block1 with reference position [0, 0, 0] and block2 with reference position
[bearing_span, 0, 0] = [{bearing_span}, 0, 0], both with the identity rotation, so their bottoms lie on the
plane z = 0 and their bore axes on the line y = 0, z = axis_height = {axis_height} m; the rotor with reference
position [rotor_x, 0, axis_height] = [{rotor_x}, 0, {axis_height}] (rotor_x = -(end_length + bearing_width/2)
with the rotor's drive end length end_length = {end_length} m and bearing_width = {bearing_width} m) and the
identity rotation, so that its axis lies on the bore axes, its left seat (interface 'left') sits in block1's
bore with the seat's centre at the bore's centre [0, 0, {axis_height}], its right seat (interface 'right')
sits in block2's bore with the seat's centre at [{bearing_span}, 0, {axis_height}], and its keyway is on the
+z side. Joints (each an InterfaceJoint: Exudyn's GenericJoint object between two markers,
constrained axes in global coordinates, the first-named marker first in markerNumbers): (1) a clamp (all translations and rotations locked) between a ground marker at [0, 0, 0] and
block1's bottom (interface 'bottom'); (2) a clamp between a ground marker at [{bearing_span}, 0, 0] and
block2's 'bottom'; (3) the locating bearing: a revolute joint about the global x-axis
(constrainedAxes = [1, 1, 1, 0, 1, 1]) between block1's 'bore' and the rotor's 'left'; (4) the floating
bearing: a joint between block2's 'bore' and the rotor's 'right' that locks only the translations along the
global y- and z-axes (constrainedAxes = [0, 1, 1, 0, 0, 0]; the right seat may shift along the axis and
tilt, so block1's bearing alone locates the rotor axially). Gravity g = {g} m/s^2 acts on all three parts in
negative global z-direction. The rotor starts with the initial angular velocity [omega0, 0, 0] with omega0 =
{omega0} rad/s (zero initial velocity of its reference point, which lies on the axis); the blocks start at
rest; all parts start undeformed. A constant drive torque of torque = {torque} N*m about the global x-axis
(load vector [torque, 0, 0]) acts on the rotor at its 'left' interface. Create block1, block2 and the rotor
(in this order), then the ground and its markers at [0, 0, 0] and at [{bearing_span}, 0, 0], then the joints
in the order given, then the torque.
""",
    params=(*ROTOR_MASTERS, Param("omega0", 40.0, 80.0, "rad/s"), Param("torque", 0.05, 0.15, "N*m"),
            Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("block1", ("bearing_block_with_pedestal_part",)),
           PartSlot("block2", ("bearing_block_with_pedestal_part",)),
           PartSlot("rotor", ("balanced_rotor_part",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code="""
femBlock1 = FEMinterface()
femBlock1.LoadFromFile('block1.npz')
block1 = mbs.CreateFFRFReducedOrderObject('block1', femBlock1, referencePosition=[0, 0, 0], gravity=[0, 0, -g])
femBlock2 = FEMinterface()
femBlock2.LoadFromFile('block2.npz')
block2 = mbs.CreateFFRFReducedOrderObject('block2', femBlock2, referencePosition=[bearing_span, 0, 0],
                                          gravity=[0, 0, -g])
femRotor = FEMinterface()
femRotor.LoadFromFile('rotor.npz')
rotor = mbs.CreateFFRFReducedOrderObject('rotor', femRotor, referencePosition=[rotor_x, 0, axis_height],
                                         gravity=[0, 0, -g], initialAngularVelocity=[omega0, 0, 0])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mGround1 = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mGround2 = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[bearing_span, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mGround1, block1['block1:bottom']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[mGround2, block2['block2:bottom']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[block1['block1:bore'], rotor['rotor:left']],
                           constrainedAxes=[1, 1, 1, 0, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[block2['block2:bore'], rotor['rotor:right']],
                           constrainedAxes=[0, 1, 1, 0, 0, 0]))
mbs.AddLoad(Torque(markerNumber=rotor['rotor:left'], loadVector=[torque, 0, 0]))
""",
    sim=SimSettings(end_time=0.2, steps=200),
    from_parts=rotor_placement,
)
