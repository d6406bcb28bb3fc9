"""Assembly 83: the simple flexible slider crank (parts 67 crank, 68 rod, 69 slider), driven by a torque.

The three flexible parts move in the global x-y plane (their mid-planes z = 0): the crank turns about
a ground revolute at its 'hole_a', the rod is pinned to the crank at the crank's 'hole_b' and to the
slider's 'bore', and the slider's 'guide' (its bottom face) runs in a prismatic joint along the global
x-axis. Revolute joints everywhere would over-constrain the closed planar loop in 3D (three
redundant constraints with rigid bodies; with these flexible bodies a full revolute at the slider
is not redundant but locks interface deformation: 34 degrees of freedom, a solution 6e-4 off), so the rod-slider pin locks only the in-plane translations: 3 x 19 coordinates (7 rigid
with Euler parameters, 12 Hurty-Craig-Bampton modes each), 3 Euler-parameter and 17 joint
constraints, 37 degrees of freedom, no redundant constraint; the rigid mechanism has one.

The crank starts at rest at any angle theta0 (0-360 deg; driven by the crank, a slider crank with
rod_length >= 2 crank_length has no singular position) and is driven by a constant torque of
0.5-2 N*m against gravity along -y. In 40 draws checked with the rigid model (OCC mass properties)
the crank always turns forward, 0.4-5 rad (less than a revolution) in 0.1 s, at up to 140 rad/s;
200 steps of 0.5 ms. The parts are stiff (first eigenfrequencies: rods 2.4-3.2 kHz, cranks and
sliders 16-25 kHz in the draws run; the steps do not resolve them and generalized-alpha damps them):
the motion is the rigid slider crank's plus micrometre deformations. The joined interface markers
coincide at t = 0 only up to the faceting of the coarse hole meshes (2-30 um in 8 draws of 83 and
84); the first step closes these offsets and excites micrometre vibrations. At the fastest draws
(140 rad/s, 0.07 rad per step) the 200 steps put omega 0.4 % off a converged run; the check seeds
reach 50 and 37 rad/s. GT run (load + simulate): 2.5-5.5 s on a loaded machine.

The prismatic joint's ground point is the weighted centre of the slider's 'guide' interface, which
depends on the slider's own height, not on a master parameter: ``guide_point`` adds that
centre (``guide_y``, in the slider's frame) to the instance's values, drawn from the slider part's
own values for the same seed, so text and ground truth name the point.

Physics checks (tests/test_assemblies_slider_crank.py): the slider's 'bore' follows the rigid
slider-crank kinematics x_C(theta) for the crank angle reached (micrometres), and the crank's angular
velocity follows the energy balance T (theta - theta0) = M(theta) omega^2 / 2 + V(theta) - V(theta0)
with the generalized mass M and potential V from the parts' FEM rigid-body inertias.
"""

from __future__ import annotations

from typing import Any

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings, round_significant
from meceng.tasks.parts.masters_slider_crank import SLIDER_CRANK_MASTERS


def guide_point(guide_centre: Any) -> Any:
    """``from_parts`` hook giving ``guide_y``: the y-coordinate, in the slider's own frame, of the
    weighted centre of the slider's 'guide' interface (the prismatic joint's point), from the
    slider's own values through ``guide_centre``. Rounded to 6 significant digits (< 1e-8 m off the
    exact centre), so text and program use the same number."""

    def hook(values: dict[str, Any], parts: dict[str, dict[str, Any]]) -> dict[str, Any]:
        return {"guide_y": round_significant(float(guide_centre(parts["slider"])), 6)}

    return hook


PARTS = ("crank", "rod", "slider")

#: Where the parts sit and how they are joined: the same for the simple and the advanced slider crank.
PLACEMENT_TEXT = """
A flexible slider-crank mechanism moving in the global x-y plane, made of three flexible parts: the crank
'crank', the connecting rod 'rod' and the slider 'slider'. The crank length (distance between the crank's
two hole axes) is crank_length = {crank_length} m and the rod length (distance between the rod's two hole
axes) is rod_length = {rod_length} m. Initially the crank is at the angle theta0 = {crank_angle_deg}
degrees (convert it to radians), measured counter-clockwise about the global z-axis from the positive
global x-axis; the crank pin is then at B = [crank_length*cos(theta0), crank_length*sin(theta0), 0] and
the slider pin at C = [xC, 0, 0] with xC = crank_length*cos(theta0) + sqrt(rod_length^2 -
(crank_length*sin(theta0))^2). Placement of the parts' own frames in the global frame: the crank with
reference position [0, 0, 0] and reference rotation matrix RotationMatrixZ(theta0) (its 'hole_a' on the
global z-axis, its 'hole_b' at B); the rod with reference position B and reference rotation matrix
RotationMatrixZ(beta0) with beta0 = -arcsin(crank_length*sin(theta0)/rod_length) (its 'hole_a' at B, its
'hole_b' at C); the slider with reference position C and the identity rotation (its 'bore' at C, its
sliding direction along the global x-axis). The centre of the slider's 'guide' interface (where its marker
sits) is the point
(0, {guide_y}, 0) of the slider's frame, i.e. the global point G = [xC, {guide_y}, 0]. Gravity
g = {g} m/s^2 acts on all three parts in negative global y-direction.
"""

JOINTS_TEXT = """
Joints (each an InterfaceJoint: Exudyn's GenericJoint object between two markers, constrained axes in
global coordinates), each acting at the interfaces named, with
the first-named marker first in markerNumbers: (1) a revolute joint about the global z-axis between a
ground marker at [0, 0, 0] and the crank's 'hole_a'; (2) a revolute joint about the global z-axis between
the crank's 'hole_b' and the rod's 'hole_a'; (3) a pin joint between the rod's 'hole_b' and the slider's
'bore' that locks only the translations along the global x- and y-axes (constrainedAxes = [1, 1, 0, 0, 0,
0]; locking more would over-constrain the closed loop); (4) a prismatic joint along the global x-axis
between a ground marker at G and the slider's 'guide'.
"""

PLACEMENT_CODE = """
theta0 = crank_angle_deg * np.pi / 180
pB = [crank_length * np.cos(theta0), crank_length * np.sin(theta0), 0]
xC = crank_length * np.cos(theta0) + np.sqrt(rod_length**2 - (crank_length * np.sin(theta0))**2)
beta0 = -np.arcsin(crank_length * np.sin(theta0) / rod_length)
"""

JOINTS_CODE = """
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mGroundO = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mGroundG = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[xC, guide_y, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mGroundO, crank['crank:hole_a']], constrainedAxes=[1, 1, 1, 1, 1, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[crank['crank:hole_b'], rod['rod:hole_a']],
                           constrainedAxes=[1, 1, 1, 1, 1, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[rod['rod:hole_b'], slider['slider:bore']],
                           constrainedAxes=[1, 1, 0, 0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mGroundG, slider['slider:guide']], constrainedAxes=[0, 1, 1, 1, 1, 1]))
"""

TASK = AssemblyModel(
    id=83,
    name="flexible slider crank simple",
    description=PLACEMENT_TEXT + """
All parts start at rest and undeformed. A constant torque of torque = {torque} N*m about the global
z-axis (load vector [0, 0, torque]) acts on the crank at its 'hole_a' and drives the mechanism.
""" + JOINTS_TEXT + """
Create the crank, the rod and the slider (in this order), then the ground and its markers at [0, 0, 0]
and at G, then the joints in the order given, then the torque.
""",
    params=(*SLIDER_CRANK_MASTERS, Param("crank_angle_deg", 0.0, 360.0, "deg"), Param("torque", 0.5, 2.0, "N*m"),
            Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("crank", ("crank_part_simple",)), PartSlot("rod", ("rod_part_simple",)),
           PartSlot("slider", ("slider_part_simple",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code=PLACEMENT_CODE + """
femCrank = FEMinterface()
femCrank.LoadFromFile('crank.npz')
crank = mbs.CreateFFRFReducedOrderObject('crank', femCrank, referencePosition=[0, 0, 0],
                                         referenceRotationMatrix=RotationMatrixZ(theta0), gravity=[0, -g, 0])
femRod = FEMinterface()
femRod.LoadFromFile('rod.npz')
rod = mbs.CreateFFRFReducedOrderObject('rod', femRod, referencePosition=pB,
                                       referenceRotationMatrix=RotationMatrixZ(beta0), gravity=[0, -g, 0])
femSlider = FEMinterface()
femSlider.LoadFromFile('slider.npz')
slider = mbs.CreateFFRFReducedOrderObject('slider', femSlider, referencePosition=[xC, 0, 0], gravity=[0, -g, 0])
""" + JOINTS_CODE + """
mbs.AddLoad(Torque(markerNumber=crank['crank:hole_a'], loadVector=[0, 0, torque]))
""",
    sim=SimSettings(end_time=0.1, steps=200),
    from_parts=guide_point(lambda v: -v["slider_height"] / 2),  # the bottom face's centre
)
