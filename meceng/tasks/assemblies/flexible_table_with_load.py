"""Assembly 78: the flexible table (part 58) standing on the floor, feet clamped, a load pressing on its top.

The table's frame has its origin at the centre of the top plate, its feet at z = -(plate_thickness / 2
+ leg_height): it is placed with the identity rotation at [0, 0, lift], lift = plate_thickness / 2 +
leg_height, so that the feet stand on the floor z = 0 (the paper's reported LLM error is lifting it by
leg_height alone). Each foot ('foot1'..'foot4', at [-+foot_x, -+foot_y, 0]; foot_x, foot_y from the master
parameters as the part computes leg_x, leg_y) is clamped to a ground marker at its centre; gravity and a
constant force load_force along -z at the 'load' pad act on the table. The pad's top (load_z, stated in
the text) depends on the part's own pad_height: ``load_point`` adds it from the part's values.
7 + 30 coordinates (5 interfaces x 6 static modes - 6 rigid-body modes + 6 eigenmodes), one
Euler-parameter and 4 x 6 clamp constraints: 12 degrees of freedom, none redundant (the static modes
give every foot its own displacement). The feet are flat squares: their markers (weighted centres) lie
exactly on the ground points at t = 0 (offsets < 1e-15 m).

Ranges and end time: load_force = 200-1000 N (a person leaning on the table) against a weight of
250-720 N (aluminium, 25-73 kg; 356-584 N over seeds 0-19): static deflections of a few micrometres.
The force and gravity are applied suddenly, so the table vibrates about its static equilibrium; the
vertical mode that carries the load point is at ~250-600 Hz (constrained eigenfrequencies: seed 0 91,
93 Hz leg sway, 135 Hz torsion, 448 Hz vertical; seed 1 110, 113, 160, 567 Hz; the largest, thinnest
table 62, 65, 98, 247 Hz), resolved by 500 steps of 0.2 ms (>= 20 per period) over 0.1 s (>= 25
periods). GT run (load + simulate): 1.4 s for seeds 0 and 1 (2275 and 2372 nodes), 1.9-3.6 s for the
largest table (3901 nodes) on a loaded machine.

Physics checks (tests/test_assemblies_beam_table.py): statically (SolveStatic) the four clamps carry
the weight (FEM mass) plus the load (to 1e-9; measured 1e-15), each a quarter within 2 % (measured 0.4 %);
dynamically the load point's deflection and the total vertical reaction oscillate about the static values
(time means within 2 % and 1 %, measured 0.2 % and 0.15 %) with a peak of about twice the static
deflection (1.97-1.99; step response of the dominant mode). The table lifted by leg_height only fails
at graph content (node reference position) and solution.
"""

from __future__ import annotations

from typing import Any

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings, round_significant
from meceng.tasks.parts.masters_table import TABLE_MASTERS


def derive(v: dict[str, Any]) -> dict[str, Any]:
    """Lift of the table's frame above the floor and the foot centres (as the part computes them)."""
    return {
        "lift": round_significant(v["plate_thickness"] / 2 + v["leg_height"], 6),
        "foot_x": round_significant(v["table_length"] / 2 - v["leg_inset"] - v["leg_size"] / 2, 6),
        "foot_y": round_significant(v["table_width"] / 2 - v["leg_inset"] - v["leg_size"] / 2, 6),
    }


def load_point(values: dict[str, Any], parts: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """Height of the load pad's top face (the 'load' interface) above the floor: depends on the
    table's own pad height."""
    return {"load_z": round_significant(values["lift"] + parts["table"]["pad_top_z"], 6)}


TASK = AssemblyModel(
    id=78,
    name="flexible table with load",
    description="""
A flexible table 'table' stands on a horizontal floor (the plane z = 0, the global z-axis points up) with its
four feet fixed to the floor, and a load presses on its top. The table's own frame has its origin at the
centre of the top plate and the feet's bottom faces at z = -(plate_thickness/2 + leg_height) in that frame
(plate_thickness = {plate_thickness} m, leg_height = {leg_height} m). Place the table with the identity
rotation and reference position [0, 0, lift] with lift = plate_thickness/2 + leg_height = {lift} m, so that
the feet stand on the floor at z = 0. The foot centres are then at [-foot_x, -foot_y, 0] ('foot1'),
[foot_x, -foot_y, 0] ('foot2'), [foot_x, foot_y, 0] ('foot3') and [-foot_x, foot_y, 0] ('foot4') with
foot_x = table_length/2 - leg_inset - leg_size/2 = {foot_x} m and foot_y = table_width/2 - leg_inset -
leg_size/2 = {foot_y} m. Each foot is clamped to the ground (an InterfaceJoint: Exudyn's GenericJoint object, all translations and rotations locked, constrainedAxes = [1, 1, 1, 1, 1, 1]) between a ground marker at its foot centre (first in
markerNumbers) and the foot's interface. Gravity g = {g} m/s^2 acts on the table in negative global
z-direction. A constant force of load_force = {load_force} N acts in negative global z-direction (load
vector [0, 0, -load_force]) on the load pad's top face (interface 'load', centre at [0, 0, {load_z}]). The
table starts at rest in its undeformed reference position. Create the table, then the ground, then for
foot1, foot2, foot3 and foot4 (in this order) the ground marker and the clamp, then the force.
""",
    params=(*TABLE_MASTERS, Param("load_force", 200.0, 1000.0, "N"), Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("table", ("flexible_table_part",)),),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code="""
femTable = FEMinterface()
femTable.LoadFromFile('table.npz')
table = mbs.CreateFFRFReducedOrderObject('table', femTable, referencePosition=[0, 0, lift], gravity=[0, 0, -g])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
feet = [[-foot_x, -foot_y, 0], [foot_x, -foot_y, 0], [foot_x, foot_y, 0], [-foot_x, foot_y, 0]]
for i, footPoint in enumerate(feet):
    mFoot = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=footPoint))
    mbs.AddObject(GenericJoint(markerNumbers=[mFoot, table[f'table:foot{i + 1}']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddLoad(Force(markerNumber=table['table:load'], loadVector=[0, 0, -load_force]))
""",
    sim=SimSettings(end_time=0.1, steps=500),
    derive=derive,
    from_parts=load_point,
)
