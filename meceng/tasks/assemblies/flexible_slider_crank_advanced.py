"""Assembly 84: the advanced flexible slider crank (parts 70 crank, 71 rod, 72 slider), set spinning.

Same mechanism, placement and joints as assembly 83 (see flexible_slider_crank_simple): crank on a
ground revolute at its 'hole_a', rod pinned to the crank's 'hole_b' (revolute) and to the slider's
'bore' (in-plane translations only, so the closed loop is not over-constrained), the slider's 'guide'
(the three faces of its groove) in a prismatic joint along the global x-axis; 37 degrees of freedom,
no redundant constraint. The 'guide' centre is the area-weighted centre of the groove's floor and
side faces, y = -h/2 + (w d + d^2) / (w + 2 d) in the slider's frame (groove width w, depth d).

Instead of a torque, the mechanism is set spinning: the crank starts with omega0 = 20-40 rad/s at any
angle theta0, and rod and slider start with the velocities consistent with it (given in the text as
formulas), so the joints are satisfied in velocity too (the first step only closes the joints'
micrometre mesh offsets, as in 83). Gravity acts along -y. In 40 draws checked with the rigid model (OCC mass properties) the crank keeps turning
forward (5.6-93 rad/s) and turns 1-5.1 rad (less than a revolution) in 0.1 s; 200 steps of 0.5 ms.
The I-section rod is the softest part (first eigenfrequency 1.5-2.1 kHz in the draws run; cranks and
sliders 19-26 kHz).

Physics checks (tests/test_assemblies_slider_crank.py): the initial velocities are consistent (the
joined markers move together at t = 0), the slider's 'bore' follows the rigid slider-crank kinematics
for the crank angle reached, and the mechanical energy M(theta) omega^2 / 2 + V(theta) of the rigid
mechanism (FEM rigid-body inertias of the parts) stays constant.
"""

from __future__ import annotations

from meceng.tasks.assemblies.flexible_slider_crank_simple import (
    JOINTS_CODE,
    JOINTS_TEXT,
    PLACEMENT_CODE,
    PLACEMENT_TEXT,
    guide_point,
)
from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_slider_crank import SLIDER_CRANK_MASTERS


def _groove_centre(v: dict) -> float:
    """y of the area-weighted centre of the groove's floor (width w) and two side faces (depth d)."""
    w, d = v["groove_width"], v["groove_depth"]
    return -v["slider_height"] / 2 + (w * d + d * d) / (w + 2 * d)


TASK = AssemblyModel(
    id=84,
    name="flexible slider crank advanced",
    description=PLACEMENT_TEXT + """
All parts start undeformed, and the mechanism is set spinning: the crank starts with the angular
velocity omega0 = {omega0} rad/s about the global z-axis (initial angular velocity [0, 0, omega0], initial
velocity of its frame [0, 0, 0]); the rod starts with the angular velocity [0, 0, omegaRod] with
omegaRod = -omega0*crank_length*cos(theta0)/(rod_length*cos(beta0)) and its frame (at B) with the
velocity vB = [-omega0*crank_length*sin(theta0), omega0*crank_length*cos(theta0), 0]; the slider starts
without rotation and with the velocity [vC, 0, 0], vC = -omega0*crank_length*sin(theta0) -
rod_length*sin(beta0)*omegaRod. No torque or force acts besides gravity.
""" + JOINTS_TEXT + """
Create the crank, the rod and the slider (in this order, each with its initial velocities), then the
ground and its markers at [0, 0, 0] and at G, then the joints in the order given.
""",
    params=(*SLIDER_CRANK_MASTERS, Param("crank_angle_deg", 0.0, 360.0, "deg"), Param("omega0", 20.0, 40.0, "rad/s"),
            Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("crank", ("crank_part_advanced",)), PartSlot("rod", ("rod_part_advanced",)),
           PartSlot("slider", ("slider_part_advanced",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint"),
    model_code=PLACEMENT_CODE + """
omegaRod = -omega0 * crank_length * np.cos(theta0) / (rod_length * np.cos(beta0))
vB = [-omega0 * crank_length * np.sin(theta0), omega0 * crank_length * np.cos(theta0), 0]
vC = -omega0 * crank_length * np.sin(theta0) - rod_length * np.sin(beta0) * omegaRod

femCrank = FEMinterface()
femCrank.LoadFromFile('crank.npz')
crank = mbs.CreateFFRFReducedOrderObject('crank', femCrank, referencePosition=[0, 0, 0],
                                         referenceRotationMatrix=RotationMatrixZ(theta0), gravity=[0, -g, 0],
                                         initialVelocity=[0, 0, 0], initialAngularVelocity=[0, 0, omega0])
femRod = FEMinterface()
femRod.LoadFromFile('rod.npz')
rod = mbs.CreateFFRFReducedOrderObject('rod', femRod, referencePosition=pB,
                                       referenceRotationMatrix=RotationMatrixZ(beta0), gravity=[0, -g, 0],
                                       initialVelocity=vB, initialAngularVelocity=[0, 0, omegaRod])
femSlider = FEMinterface()
femSlider.LoadFromFile('slider.npz')
slider = mbs.CreateFFRFReducedOrderObject('slider', femSlider, referencePosition=[xC, 0, 0], gravity=[0, -g, 0],
                                          initialVelocity=[vC, 0, 0], initialAngularVelocity=[0, 0, 0])
""" + JOINTS_CODE,
    sim=SimSettings(end_time=0.1, steps=200),
    from_parts=guide_point(_groove_centre),
)
