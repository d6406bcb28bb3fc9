"""Assembly 80: the grinding bench, the spindle with its two grinding disks (part 62) turning in the
two bearing bores of the motor housing (part 61), driven by a torque.

The housing stands with its own frame equal to the global frame (feet on z = 0, spindle axis on the
line y = 0, z = axis_height, along x); the spindle's frame is shifted by [0, 0, axis_height]
(masters_grinding_bench.py), so each journal fills the bore of the same name: both 'bearing_left'
interfaces are centred at [-seat_x, 0, axis_height], both 'bearing_right' at [seat_x, 0, axis_height],
seat_x = (housing_length - bearing_length)/2. The housing's 'feet' (both foot faces, weighted centre
[0, 0, 0]) are clamped to the ground at [0, 0, 0].

Bearings: the usual locating / floating arrangement of the rotor family (73-75): a revolute joint
about the global x-axis at the left journal and, at the right one, a joint that locks only the radial
translations (y, z). Two revolute joints fight over the axial misfit of the interface centres: at
seed 0 they prestressed the spindle axially with 4.0 kN (its weight is 134 N). The arrangement still
overconstrains the spindle's tilt by the radial misfit (the left joint also locks the tilt): the
spindle's flexibility takes it up, as a slightly bent shaft would, with a radial force pair in the
two bearings that turns with the spindle (~500-700 N at seed 0) and cancels in their sum. A
statically determinate support (locating bearing locking the translations only) removed that force
pair but was numerically less robust (it blew up at seed 3 at the top of the ranges even with the
damping below). Coordinates: housing 7 + 18 (three interfaces), spindle 7 + 12; 2 Euler-parameter +
6 clamp + 5 + 2 bearing constraints: 29 degrees of freedom, no redundant constraint. At t = 0 the
clamp's markers coincide exactly (planar faces), the left journal's and bore's are 14-52 and the
right ones 6-36 micrometres apart (seeds 0-4; faceted small cylinders: the housing meshes its bore
of radius 10-13 mm with maxh = base_thickness, 12-18 mm).

Loads: gravity on both parts and a drive torque of 0.5-1.5 N*m about +x on the spindle at its
'bearing_left' interface (the spindle has no interface at the armature), on a spindle that already
turns at omega0 = 40-80 rad/s. Over seeds 0-4 the steel spindle has m = 13.3-16.0 kg and
J_x = 0.031-0.049 kg*m^2 (FEM inertia; the disks carry most of it), alpha = T / J_x ~ 10-48 rad/s^2:
in 0.2 s it reaches <= 90 rad/s, <= 0.09 rad of spin per step of 1 ms (as 73-75). Its centre of mass
lies on the axis (mesh asymmetry only), so gravity has no torque about the axis. The spindle's first
fixed-interface modes (94-173 Hz, the disks on the thin shaft ends) are resolved with 6-10 steps per
period, the cast-iron housing's (3-4 kHz) are not and need not be.

Numerical damping: generalized-alpha with spectralRadius = 0.8 (simplified_wind_turbine.py). With the
default 0.9 and 1 ms steps the spinning spindle's transverse wobble grew ~10x per 0.1 s at seed 0
(omega0 = 63 rad/s) and blew up: a numerical instability (stable at 20 rad/s, unstable from ~40 rad/s
at 1 ms and from ~80 rad/s at 0.5 ms, stable at 80 rad/s with 0.25 ms or with more damping). With 0.8
it is stable and the vibrations of the initial jolt decay over seeds 0-4 up to omega0 = 100 rad/s and
T = 1.5 N*m.

GT run (load + simulate) 3.5-8.3 s wall on a heavily loaded 2-core machine (solve 3.0-7.2 s; the
solve's CPU time 2.0 s at seed 0, 3.0 s at seed 1; housing 1550-3060 and spindle 2290-3850 nodes).
Physics checks (tests/test_assemblies_machines.py): the spin-up alpha = T / J_x with J_x from the
spindle's FEM mass matrix; the bearings together carry the spindle's weight and the clamp the
machine's (time averages).
"""

from __future__ import annotations

from meceng.tasks.assemblies.simplified_wind_turbine import NUMERICAL_DAMPING
from meceng.tasks.assembly_base import AssemblyModel, PartSlot
from meceng.tasks.base import Param, SimSettings
from meceng.tasks.parts.masters_grinding_bench import GRINDING_BENCH_MASTERS


def derive(v: dict) -> dict:
    return {"seat_x": round((v["housing_length"] - v["bearing_length"]) / 2, 7)}


TASK = AssemblyModel(
    id=80,
    name="grinding bench",
    description="""
A grinding bench: the flexible motor housing 'housing' stands on the ground with its feet and carries the
flexible spindle with a grinding disk at each end, 'spindle', in the two bearing bores of its end walls.
Placement of the parts' own frames in the global frame (the global z-axis points up): the housing with
reference position [0, 0, 0] and the identity rotation, so its feet lie on the plane z = 0 and its spindle
axis is the line y = 0, z = axis_height = {axis_height} m, parallel to the global x-axis; the spindle with
reference position [0, 0, axis_height] = [0, 0, {axis_height}] and the identity rotation, so that its axis
lies on the housing's spindle axis and its journals sit in the housing's bearing bores: the left journal
(spindle interface 'bearing_left') in the left bore (housing interface 'bearing_left'), both centred at
[-{seat_x}, 0, {axis_height}], and the right journal ('bearing_right') in the right bore ('bearing_right'),
both centred at [{seat_x}, 0, {axis_height}], with seat_x = (housing_length - bearing_length)/2 = {seat_x} m
(housing_length = {housing_length} m, bearing_length = {bearing_length} m).
Joints (each an InterfaceJoint: Exudyn's GenericJoint object between two markers,
constrained axes in global coordinates, the first-named marker first in markerNumbers):
(1) a clamp (all translations and rotations locked) between a ground marker at [0, 0, 0] and the
housing's feet (interface 'feet'); (2) the locating bearing: a revolute joint about the global x-axis
(constrainedAxes = [1, 1, 1, 0, 1, 1]) between the housing's 'bearing_left' and the spindle's
'bearing_left'; (3) the floating bearing: a joint between the housing's 'bearing_right' and the spindle's
'bearing_right' that locks only the translations along the global y- and z-axes
(constrainedAxes = [0, 1, 1, 0, 0, 0]; the right journal may shift along the axis and tilt, so the left
bearing alone locates the spindle axially).
Gravity g = {g} m/s^2 acts on both parts in negative global z-direction. The spindle starts with the initial
angular velocity [omega0, 0, 0] with omega0 = {omega0} rad/s (zero initial velocity of its reference point,
which lies on the axis); the housing starts at rest; both parts start undeformed. A constant drive torque of
torque = {torque} N*m about the global x-axis (load vector [torque, 0, 0]) acts on the spindle at its
'bearing_left' interface. Create the housing and the spindle (in this order), then the ground and its marker
at [0, 0, 0], then the joints in the order given, then the torque.
""",
    params=(*GRINDING_BENCH_MASTERS, Param("omega0", 40.0, 80.0, "rad/s"), Param("torque", 0.5, 1.5, "N*m"),
            Param("g", 9.81, 9.81, "m/s^2")),
    parts=(PartSlot("housing", ("grinding_bench_housing_part",)),
           PartSlot("spindle", ("grinding_bench_spindle_with_disks_part",))),
    components=("Ground", "LoadFEMPart", "FlexibleBody", "InterfaceJoint", "InterfaceLoad"),
    model_code="""
femHousing = FEMinterface()
femHousing.LoadFromFile('housing.npz')
housing = mbs.CreateFFRFReducedOrderObject('housing', femHousing, referencePosition=[0, 0, 0],
                                           gravity=[0, 0, -g])
femSpindle = FEMinterface()
femSpindle.LoadFromFile('spindle.npz')
spindle = mbs.CreateFFRFReducedOrderObject('spindle', femSpindle, referencePosition=[0, 0, axis_height],
                                           gravity=[0, 0, -g], initialAngularVelocity=[omega0, 0, 0])
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
mbs.AddObject(GenericJoint(markerNumbers=[mGround, housing['housing:feet']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[housing['housing:bearing_left'], spindle['spindle:bearing_left']],
                           constrainedAxes=[1, 1, 1, 0, 1, 1]))
mbs.AddObject(GenericJoint(markerNumbers=[housing['housing:bearing_right'], spindle['spindle:bearing_right']],
                           constrainedAxes=[0, 1, 1, 0, 0, 0]))
mbs.AddLoad(Torque(markerNumber=spindle['spindle:bearing_left'], loadVector=[torque, 0, 0]))
""",
    sim=SimSettings(end_time=0.2, steps=200, extra=(NUMERICAL_DAMPING,)),
    derive=derive,
)
