"""Assembly 82: the mounting bracket (part 65) thrown and falling freely under gravity.

One flexible body, no joints, no ground: the bracket's own frame (outer bend edge on the y-axis,
base plate on z = 0, upright on x = 0) is placed at [0, 0, drop_height] with the identity rotation;
gravity acts along -z; the bracket starts undeformed with the initial velocity [vx0, 0, vz0] of its
reference point (the frame origin on the outer bend edge, not the centre of mass) and the initial
angular velocity [omega_x, omega_y, omega_z] (global). 7 + 12 = 19 coordinates, one Euler-parameter
constraint: 18 degrees of freedom. The interfaces are not used; the part's modes are still the
Hurty-Craig-Bampton modes of its two hole interfaces.

Ranges and end time: thrown upwards (vz0 = 1-3 m/s) and sideways (vx0 = 0.5-2 m/s), spinning about
a general, non-principal axis (|omega0| = 2.4-8.2 rad/s), so it tumbles: in 0.3 s it turns 40-140
degrees and moves by decimetres; 300 steps of 1 ms, at most ~0.008 rad per step. The aluminium
bracket is stiff (first free-free eigenfrequency ~5 kHz) and the centrifugal loads are tiny
(omega^2 r < 5 m/s^2): the motion is the rigid body's, the solve takes a fraction of a second.

Physics checks (tests/test_assemblies_hinge_bracket.py): the centre of mass of the reduced flexible
body (frame position + R (chi + M_t Psi q / m)) follows c0 + v_c0 t - g t^2/2 e_z with
v_c0 = v0 + omega0 x R chi from the part's FEM inertia, to a micrometre over the whole run (exact for
the free body: gravity is a mass-proportional load); its angular momentum about the centre of mass,
summed over all mesh nodes with the consistent mass matrix, stays I_c omega0 to ~1e-5.
"""

from __future__ import annotations

from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings

TASK = AssemblyModel(
    id=82,
    name="mounting bracket free falling",
    description="""
A flexible L-shaped mounting bracket 'bracket' is thrown and then falls freely under gravity. The system
consists of the bracket alone: no ground, no joints, no contact and no loads other than gravity. Place the
bracket's own frame (the frame of its description: the outer bend edge on the y-axis, base plate on z = 0,
upright on x = 0) with reference position [0, 0, drop_height] = [0, 0, {drop_height}] and the identity rotation
in the global frame (the global z-axis points up). Gravity g = {g} m/s^2 acts on the bracket in negative global
z-direction. The bracket starts undeformed with the initial velocity [vx0, 0, vz0] = [{vx0}, 0, {vz0}] m/s of
its reference point (the origin of its own frame, on the outer bend edge) and the initial angular velocity
[omega_x, omega_y, omega_z] = [{omega_x}, {omega_y}, {omega_z}] rad/s (global components).
""",
    params=(Param("drop_height", 0.5, 1.5, "m"), Param("vx0", 0.5, 2.0, "m/s"), Param("vz0", 1.0, 3.0, "m/s"),
            Param("omega_x", 1.0, 4.0, "rad/s"), Param("omega_y", 2.0, 6.0, "rad/s"),
            Param("omega_z", 1.0, 4.0, "rad/s"), Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("bracket", ("mounting_bracket_part",)),),
    components=("LoadFEMPart", "FlexibleBody"),
    model_code="""
femBracket = FEMinterface()
femBracket.LoadFromFile('bracket.npz')
bracket = mbs.CreateFFRFReducedOrderObject('bracket', femBracket, referencePosition=[0, 0, drop_height],
                                           gravity=[0, 0, -g], initialVelocity=[vx0, 0, vz0],
                                           initialAngularVelocity=[omega_x, omega_y, omega_z])
""",
    sim=SimSettings(end_time=0.3, steps=300),
)
