"""Assembly 81: a door hinge (parts 64 pin-side leaf and 63 gap-side leaf), the gap-side leaf pushed open.

The two leaves are described in one common frame (hinge axis = z, leaves flat in y = 0, pin side on
-x, gap side on +x), so both are placed with the identity: the gap-side leaf's knuckles sit on the
pin. The pin-side leaf is clamped to the ground (the door frame) at its screw holes ('mount'); the
gap-side leaf turns on the pin: a revolute joint about the global z-axis between the pin-side leaf's
'pin' and the gap-side leaf's 'bore' (both centred on the axis at mid_z = 1.5 knuckle_length). The
hinge axis is vertical: gravity along -z has no moment about it (it loads the pin axially and bends
the leaves by micrometres); a constant door force F along +y at the gap-side leaf's 'door' (its screw
holes, x_door = 25-34 mm from the axis) pushes the leaf open. 2 x (7 + 12) = 38 coordinates,
2 Euler-parameter + 6 clamp + 5 revolute constraints: 25 degrees of freedom, none redundant.

The clamp's ground point is the centre of the pin-side leaf's 'mount', [-hole_x, 0, mid_z]; hole_x
depends on that leaf's own leaf_width, not on a master parameter, so ``mount_point`` adds it
(``mount_x``) to the instance's values, drawn from the leaf's own values for the same seed. The
interface markers sit at the weighted centres of the meshed surfaces: at t = 0 the joined 'pin' and
'bore' meet within ~10 micrometres and the 'mount' marker lies within ~25 micrometres of the stated
ground point (mesh asymmetry); the solver closes that misfit in the first step, a jump of ~1e-4 rad
in the leaf angle (checked: with the markers moved onto each other the angle is alpha0 t^2/2 from the
first step on).

Ranges and end time: F = 0.3-1.0 N and J_axis = 0.45-2.4e-4 kg*m^2 (steel leaf of 0.12-0.34 kg)
give alpha0 = F x_door / J_axis = 40-570 rad/s^2: in 0.1 s the leaf swings 0.4-1.4 rad over seeds
0-19 (0.2-2.3 rad at the corners of the ranges, never round to the other leaf at pi), with 200 steps
at most ~0.02 rad per step. The leaves are stiff (first free-free eigenfrequencies 3-4 kHz): the
motion is the rigid leaf's plus micrometre deformations. The simulation block adds a Jacobian update
per step: every Newton iteration evaluates the joint constraints over the interfaces' ~80-350 nodes
each, and modified Newton without it needed 5-7 iterations per step (2-3 with it: 2.5 times fewer).

Physics check (tests/test_assemblies_hinge_bracket.py): the leaf angle follows the rigid leaf's
J_axis theta'' = F (d_x cos(theta) - d_y sin(theta)) (J_axis about the hinge axis from the leaf's FEM
inertia, d the 'door' marker's position) to 0.1 %, and at the start theta'' = F x_door / J_axis to 1 %.
"""

from __future__ import annotations

from typing import Any

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_hinge import HINGE_MASTERS, exact


def mount_point(values: dict[str, Any], parts: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """The clamp's ground point: the centre of the pin-side leaf's 'mount' interface (its two screw
    holes at x = -hole_x); hole_x is the leaf's own value (it depends on its own leaf_width) and has
    three significant digits, so -hole_x is exact."""
    return {"mount_x": -parts["pin_leaf"]["hole_x"]}


#: a Jacobian per step: 2-3 Newton iterations per step instead of 5-7 (see the module docstring)
NEWTON = "simulationSettings.timeIntegration.newton.modifiedNewtonJacUpdatePerStep = True"


def derive(v: dict) -> dict:
    return {"mid_z": exact(1.5 * v["knuckle_length"])}


TASK = AssemblyModel(
    id=81,
    name="door hinge",
    description="""
A door hinge with a vertical hinge axis: the flexible pin-side leaf 'pin_leaf' is screwed to the door frame
(the ground) and the flexible gap-side leaf 'gap_leaf', which carries the door, turns on the pin-side leaf's
pin. Both parts are described in one common frame (hinge axis = z-axis, leaves fully opened and flat in the
plane y = 0, pin-side leaf on the -x side, gap-side leaf on the +x side, knuckle_length = {knuckle_length} m);
place both with reference position [0, 0, 0] and the identity rotation, so that their own frames coincide
with the global frame (the global z-axis points up) and the gap-side leaf's knuckles sit on the pin. The
centres of the pin-side leaf's 'pin' and of the gap-side leaf's 'bore' both lie on the hinge axis at
[0, 0, mid_z] = [0, 0, {mid_z}] (mid_z = 1.5 knuckle_length); the centre of the pin-side leaf's 'mount'
(its two screw holes) is [mount_x, 0, mid_z] = [{mount_x}, 0, {mid_z}].
Joints (each an InterfaceJoint: Exudyn's GenericJoint object between two markers,
constrained axes in global coordinates, the first-named marker first in markerNumbers):
(1) a clamp (all translations and rotations locked, constrainedAxes = [1, 1, 1, 1, 1, 1]) between a ground
marker at [{mount_x}, 0, {mid_z}] and the pin-side leaf's 'mount'; (2) a revolute joint about the global
z-axis (constrainedAxes = [1, 1, 1, 1, 1, 0]) between the pin-side leaf's 'pin' and the gap-side leaf's 'bore'.
Gravity g = {g} m/s^2 acts on both parts in negative global z-direction. Both parts start at rest and
undeformed. A constant force of door_force = {door_force} N in positive global y-direction (load vector
[0, door_force, 0], fixed in direction) acts on the gap-side leaf at its 'door' interface and pushes the leaf
open. Create the pin-side leaf and the gap-side leaf (in this order), then the ground and its marker, then
the joints in the order given, then the force.
""",
    params=(*HINGE_MASTERS, Param("door_force", 0.3, 1.0, "N"), Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("pin_leaf", ("hinge_leaf_pin_side_part",)), PartSlot("gap_leaf", ("hinge_leaf_gap_side_part",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code="""
femPin = FEMinterface()
femPin.LoadFromFile('pin_leaf.npz')
pinLeaf = mbs.CreateFFRFReducedOrderObject('pin_leaf', femPin, referencePosition=[0, 0, 0], gravity=[0, 0, -g])
femGap = FEMinterface()
femGap.LoadFromFile('gap_leaf.npz')
gapLeaf = mbs.CreateFFRFReducedOrderObject('gap_leaf', femGap, referencePosition=[0, 0, 0], gravity=[0, 0, -g])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mMount = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[mount_x, 0, mid_z]))
mbs.AddObject(GenericJoint(markerNumbers=[mMount, pinLeaf['pin_leaf:mount']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[pinLeaf['pin_leaf:pin'], gapLeaf['gap_leaf:bore']],
                           constrainedAxes=[1, 1, 1, 1, 1, 0]))
mbs.AddLoad(Force(markerNumber=gapLeaf['gap_leaf:door'], loadVector=[0, door_force, 0]))
""",
    sim=SimSettings(end_time=0.1, steps=200, extra=(NEWTON,)),
    derive=derive,
    from_parts=mount_point,
)
