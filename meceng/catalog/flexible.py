"""Level 3b components: flexible parts in a multibody system (paper section 2.3, Flexible MBS Assembly).

A saved part is loaded into a ``FEMinterface`` and added with ``mbs.CreateFFRFReducedOrderObject``,
which returns one SuperElementRigid marker per named interface (``'name:interface'``); joints and
loads act on those markers as on rigid bodies. Every example loads the same saved beam,
``beam.npz``, as a task's program loads its parts.
"""

from __future__ import annotations

from meceng.catalog.component import Component, text_block
from meceng.tasks.base import PREAMBLE, SimSettings
from meceng.tasks.part_base import STEEL, fem_block

#: Every example loads the same saved beam (0.5 x 0.04 x 0.02 m steel, interfaces 'left' and 'right');
#: the catalog test makes it with the part pipeline first.
_LOAD_BEAM = """\
from exudyn.FEM import FEMinterface
fem = FEMinterface()
fem.LoadFromFile('beam.npz')
"""

#: The beam the examples load, as a part program.
BEAM_PART = f"""\
from netgen.occ import *
import ngsolve as ngs
from exudyn.FEM import FEMinterface, HCBstaticModeSelection
shape = Box(Pnt(0, -0.02, -0.01), Pnt(0.5, 0.02, 0.01))
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
{fem_block(0.02, STEEL, ('left', 'right'))}"""


def _example(model: str, end_time: float = 0.05, steps: int = 50) -> str:
    sim = SimSettings(end_time=end_time, steps=steps)
    return f"{PREAMBLE}\n{_LOAD_BEAM}\n{text_block(model)}\n\nmbs.Assemble()\n\n{sim.block()}"


LOAD_FEM_PART = Component(
    name="LoadFEMPart",
    description="load a saved flexible machine part (meshed, reduced FEM model) from its .npz file",
    context=text_block("""
        from exudyn.FEM import FEMinterface
        femArm = FEMinterface()
        femArm.LoadFromFile('arm.npz')      # the part's name as given in the Part Loading Info
        - One FEMinterface per part instance; a part used twice (two bearing blocks) is loaded twice.
        - The part keeps its mesh, material, interfaces (boundary names) and Hurty-Craig-Bampton modes; do
          not mesh or reduce it again.
    """),
    example=_example("""
        beam = mbs.CreateFFRFReducedOrderObject('beam', fem, referencePosition=[0, 0, 0])
    """),
    group="flexible",
)

FLEXIBLE_BODY = Component(
    name="FlexibleBody",
    description=(
        "add a loaded flexible part to the system as a reduced-order flexible body (floating frame of "
        "reference); creates one marker per named interface"
    ),
    context=text_block("""
        arm = mbs.CreateFFRFReducedOrderObject('arm', femArm, referencePosition=[x, y, z],
                                               referenceRotationMatrix=np.eye(3), gravity=[0, 0, -9.81],
                                               initialVelocity=[0, 0, 0], initialAngularVelocity=[0, 0, 0])
        mLeft = arm['arm:left']            # SuperElementRigid marker at the interface 'left'
        - The first argument is the body's name; the markers are named 'name:interface' for every interface of
          the part. The marker sits at the weighted centre of the interface's nodes.
        - referencePosition / referenceRotationMatrix place the part's own frame (the frame of its description)
          in the global frame: a part point p appears at referencePosition + R p. Rotation matrices:
          RotationMatrixX/Y/Z(angle) from exudyn.utilities.
        - gravity is given per flexible body (there is no global gravity).
    """),
    example=_example("""
        beam = mbs.CreateFFRFReducedOrderObject('beam', fem, referencePosition=[0, 0, 0], gravity=[0, 0, -9.81])
        mLeft, mRight = beam['beam:left'], beam['beam:right']
    """),
    dependencies=("LoadFEMPart",),
    group="flexible",
)

INTERFACE_JOINT = Component(
    name="InterfaceJoint",
    description=(
        "joint at a flexible part's interface, made with Exudyn's GenericJoint object between two markers: clamp "
        "it to ground, or a revolute / prismatic / partly locked joint to the ground or to another part's interface"
    ),
    context=text_block("""
        oGround = mbs.CreateGround()
        mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[x, y, z]))  # joint point
        mbs.AddObject(GenericJoint(markerNumbers=[mGround, arm['arm:left']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
        - constrainedAxes = [x, y, z, rotation x, rotation y, rotation z] in the global frame (1 = locked,
          0 = free): clamped [1,1,1,1,1,1]; revolute about z [1,1,1,1,1,0]; revolute about x [1,1,1,0,1,1];
          prismatic along x [0,1,1,1,1,1].
        - Between two parts: markerNumbers=[partA['a:bore'], partB['b:pin']]; both interfaces must be at the
          same point initially (place the parts accordingly).
        - markerNumbers in the order the description names the two sides (the ground marker first when the
          description names the ground first).
        - The ground marker goes at the interface's centre (the joint point of the description).
    """),
    example=_example("""
        beam = mbs.CreateFFRFReducedOrderObject('beam', fem, referencePosition=[0, 0, 0], gravity=[0, 0, -9.81])
        oGround = mbs.CreateGround()
        mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
        mbs.AddObject(GenericJoint(markerNumbers=[mGround, beam['beam:left']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
    """),
    dependencies=("FlexibleBody", "Ground"),
    group="flexible",
)

INTERFACE_LOAD = Component(
    name="InterfaceLoad",
    description=("force or torque acting on a flexible part at one of its interfaces (Exudyn's Force / Torque load "
                 "on the interface marker)"),
    context=text_block("""
        mbs.AddLoad(Force(markerNumber=arm['arm:right'], loadVector=[0, 0, -F]))    # force in N, global frame
        mbs.AddLoad(Torque(markerNumber=rotor['rotor:hub'], loadVector=[T, 0, 0]))  # torque in Nm
        - The load acts on the interface marker (spread over the interface's nodes).
    """),
    example=_example("""
        beam = mbs.CreateFFRFReducedOrderObject('beam', fem, referencePosition=[0, 0, 0])
        oGround = mbs.CreateGround()
        mGround = mbs.AddMarker(MarkerBodyRigid(bodyNumber=oGround, localPosition=[0, 0, 0]))
        mbs.AddObject(GenericJoint(markerNumbers=[mGround, beam['beam:left']], constrainedAxes=[1, 1, 1, 1, 1, 1]))
        mbs.AddLoad(Force(markerNumber=beam['beam:right'], loadVector=[0, 0, -50]))
    """),
    dependencies=("FlexibleBody",),
    group="flexible",
)

COMPONENTS = (LOAD_FEM_PART, FLEXIBLE_BODY, INTERFACE_JOINT, INTERFACE_LOAD)
