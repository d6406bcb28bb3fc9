"""Assembly 74: the unbalanced rotor (part 52) in a flexible bearing block with pedestal (part 66) and
a rigid floating bearing, spinning and driven by a torque under gravity.

The same system as 73 (see rotor_in_bearing_block.py for the choices, ranges and checks), with the
pedestal block instead of the plain block: its frame has the same meaning (bottom-face centre at the
origin, bore axis along x at the master axis_height), so placement, joints, loads, ranges, end time
and checks are 73's. One block, two seats: the left seat is located in the block's bore (revolute
about the shaft axis), the right seat runs in a rigid floating bearing to the ground at its centre
(radial translations locked only). 2 x 19 coordinates, 23 degrees of freedom, no redundant constraint.
"""

from __future__ import annotations

from meceng.tasks.assemblies.rotor_in_bearing_block import DRIVE_PARAMS, MODEL_CODE, derive, description
from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import SimSettings
from meceng.tasks.parts.masters_rotor import ROTOR_MASTERS

TASK = AssemblyModel(
    id=74,
    name="rotor in bearing block with pedestal",
    description=description("a bearing housing with a bore on a wider pedestal plate"),
    params=(*ROTOR_MASTERS, *DRIVE_PARAMS),
    parts=(PartSlot("block", ("bearing_block_with_pedestal_part",)), PartSlot("rotor", ("unbalanced_rotor_part",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code=MODEL_CODE,
    sim=SimSettings(end_time=0.2, steps=200),
    derive=derive,
)
