"""Tools that tell the whole truth (issue 44): what a strong model found misleading, said too little
or left it to work out in the answers of ``simulate``, ``compare`` and ``self_check``, each point on
the task model it was seen on, through the tools as the agent calls them."""

from __future__ import annotations

import math
from typing import Any

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.tasks.registry import default_registry


def instance(slug: str, seed: int = 1) -> Any:
    return default_registry().get(slug).instance(seed)


async def tool(task: Any, name: str, **arguments: Any) -> str:
    return (await Toolbox(task, rigid_catalog()).call(name, arguments)).text


def lines_of(text: str, what: str) -> list[str]:
    return [line.strip() for line in text.splitlines() if what in line]


# ----------------------------------------------------------------------------- 1: where compare's scales come from


def number_after(text: str, words: str) -> float:
    import re

    match = re.search(re.escape(words) + r" (-?[0-9.e+-]+)", text)
    assert match, (words, text)
    return float(match.group(1))


async def test_compare_names_the_source_of_each_scale_and_the_fastest_centre_of_mass() -> None:
    """The gyroscope: its disc's rim (|ω|·r, a point at its inertia radius) moves some 250 times faster
    than its centre of mass ever does; the centres' velocities are checked at their own scale and the
    angular velocity at the rim's, and the answer says which is which, with the numbers."""
    from meceng.tasks.alternatives import alternatives_of

    task = instance("gyroscope_on_spherical_joint")
    other = alternatives_of("gyroscope_on_spherical_joint")[0].program(task)
    answer = await tool(task, "compare", code_a=task.reference_program, code_b=other)
    line = lines_of(answer, "tolerances")[0]
    velocities, rotations = line.split("angular velocities and axes")
    assert "the spread of A's centre-of-mass velocities" in velocities, line
    assert "A's #1 RigidBody's |ω|·r: its largest angular speed" in rotations, line
    assert "a point there, not its centre of mass, moves that fast" in rotations, line
    speed = number_after(line, "centre-of-mass velocities within")
    rim = number_after(rotations, "as much: within")
    fastest = number_after(line, "the fastest centre of mass, A's #1 RigidBody, moves at")
    assert speed < 0.01 * fastest and rim > 100 * speed, line  # the centres checked at their own scale, not the rim's
    assert "positions within" in line and "the farthest a centre of mass travels: A's #1 RigidBody" in line, line


async def test_a_mass_point_systems_speed_scale_is_named_too() -> None:
    """No rotation: the speed scale is the spread of the centres' velocities (the pendulum's swing),
    and the fastest centre of mass is said beside it."""
    task = instance("single_pendulum")
    answer = await tool(task, "compare", code_a=task.reference_program, code_b=task.reference_program)
    line = lines_of(answer, "tolerances")[0]
    assert "the spread of A's centre-of-mass velocities" in line, line
    assert "the fastest centre of mass, A's #1 MassPoint, moves at" in line, line


# ----------------------------------------------------------------------------- 2: the energy against the motion's own


async def test_self_check_reads_a_contact_loss_against_the_motions_energy_and_names_the_contact() -> None:
    """The wall pendulum (e = 0.76, two impacts): it loses 1 - e⁴ ≈ 67 % of its swing's energy, which
    the total (about -3.5 J: gravity's zero at the support) showed as -18.7 %."""
    task, code = wall()
    toolbox = Toolbox(task, rigid_catalog())
    report = (await toolbox.self_check(code))["energy"]
    e = task.params["restitution"]
    assert abs(report["relative_change"] - (e ** 4 - 1)) < 0.05, report  # two impacts, each keeps e²
    assert report["explained"] is True
    p = task.params  # the swing's energy: from the start height to the lowest point
    drop = p["mass"] * p["gravity"] * p["length"] * (1 - math.cos(math.radians(p["angle_deg"])))
    assert abs(report["gravity_swing"] - drop) < 1e-3 * drop and report["motion_energy"] >= report["kinetic_max"]
    text = (await toolbox.call("self_check", {"code": code})).text
    assert "% of the motion's energy" in text and "(the larger of its largest kinetic energy" in text, text
    assert "and the swing of gravity's potential" in text, text
    assert f"#3 SphereTriangleContact dissipates: restitution {e:.4g} (impact model 2)" in text, text
    assert "so: a loss the elements above can explain" in text and "no problem found" in text, text


async def test_self_check_says_a_loss_no_element_explains() -> None:
    """A pendulum given a velocity along its rod: the constraint takes it at once, a loss of energy
    that nothing in the system explains, and a finding; the same pendulum at rest keeps its energy."""
    task = instance("single_pendulum")
    code = task.reference_program.replace("mass=mass, gravity", "mass=mass, initialVelocity=[p0[0], p0[1], 0], gravity")
    assert code != task.reference_program
    text = await tool(task, "self_check", code=code)
    assert "what dissipates or feeds energy: nothing" in text, text
    assert "so: a loss no element of the system explains" in text, text
    assert "no element of the system explains it" in text.split("energy (")[0], text  # among the findings
    kept = await tool(task, "self_check", code=task.reference_program)
    assert "so: the energy is kept" in kept and "no problem found" in kept, kept


async def test_self_check_names_dampers_and_drives() -> None:
    """The RRR robot: its joints are driven by spring-damper user functions (a drive feeds energy)."""
    task = instance("rrr_articulated_robot_with_3d_cubic_trajectory")
    text = await tool(task, "self_check", code=task.reference_program)
    assert "3 × TorsionalSpringDamper (#7–#9) feed or take energy: its springTorqueUserFunction" in text, text
    assert "no element of the system explains" not in text, text


# ----------------------------------------------------------------------------- 3: which coordinate a constraint locks

#: The elliptic trammel as the model wrote it: each slider guided by two CoordinateConstraints
#: (slider 1 keeps y and z, slider 2 keeps x and y), written by hand on one ground node.
TRAMMEL = """
import exudyn as exu
from exudyn.utilities import *
import numpy as np
SC = exu.SystemContainer()
mbs = SC.AddSystem()
m1, m2, x0, z0, k, d, g = {mass1}, {mass2}, {x0}, {z0}, {stiffness}, {damping}, {gravity}
oGround = mbs.CreateGround(referencePosition=[0, 0, 0])
oS1 = mbs.CreateMassPoint(referencePosition=[x0, 0, 0], mass=m1, gravity=[0, 0, -g])
oS2 = mbs.CreateMassPoint(referencePosition=[0, 0, z0], mass=m2, gravity=[0, 0, -g])
nG = mbs.AddNode(NodePointGround(referenceCoordinates=[0, 0, 0]))
mG = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nG, coordinate=0))
n1 = mbs.GetObject(oS1)['nodeNumber']
n2 = mbs.GetObject(oS2)['nodeNumber']
for node, coordinate in ((n1, 1), (n1, 2), (n2, 0), (n2, 1)):
    mc = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=coordinate))
    mbs.AddObject(CoordinateConstraint(markerNumbers=[mG, mc]))
mbs.CreateDistanceConstraint(itemNumbers=[oS1, oS2])
mbs.CreateSpringDamper(itemNumbers=[oGround, oS1], stiffness=k, damping=d)
mbs.Assemble()
"""


def trammel() -> tuple[Any, str]:
    task = instance("link_on_two_prismatic_joints")
    return task, TRAMMEL.format(**task.params)


async def test_each_coordinate_constraint_says_which_coordinate_it_locks_and_where() -> None:
    task, code = trammel()
    text = await tool(task, "simulate", code=code)
    said = lines_of(text, "CoordinateConstraint:")
    assert len(said) == 4 and len(set(said)) == 4, said  # four constraints, four different lines
    z0 = task.params["z0"]
    assert "#3 CoordinateConstraint: ground — #1 MassPoint's y: holds it at y = 0" in said[0], said[0]
    assert "#4 CoordinateConstraint: ground — #1 MassPoint's z: holds it at z = 0" in said[1], said[1]
    assert "#5 CoordinateConstraint: ground — #2 MassPoint's x: holds it at x = 0" in said[2], said[2]
    assert "#6 CoordinateConstraint: ground — #2 MassPoint's y: holds it at y = 0" in said[3], said[3]
    assert "a node coordinate" not in text and str(z0) not in said[1]


async def test_a_coordinate_constraint_with_offset_factor_and_two_bodies_says_its_equation() -> None:
    """factor1*q1 - q0 = offset, q displacements: ground first holds q1 at offset/factor1, ground second
    holds q0 at -offset; two bodies are coupled (Exudyn's own equation, seen in its solution)."""
    task, code = trammel()
    code = code.replace("    mbs.AddObject(CoordinateConstraint(markerNumbers=[mG, mc]))\n", """\
    if (node, coordinate) == (n1, 1):
        mbs.AddObject(CoordinateConstraint(markerNumbers=[mG, mc], offset=0.1, factor1=2))
    elif (node, coordinate) == (n2, 1):
        mbs.AddObject(CoordinateConstraint(markerNumbers=[mc, mG], offset=0.1))
    else:
        mbs.AddObject(CoordinateConstraint(markerNumbers=[mG, mc]))
""")
    code = code.replace("mbs.CreateDistanceConstraint", """\
mx = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=n1, coordinate=0))
mz = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=n2, coordinate=2))
mbs.AddObject(CoordinateSpringDamper(markerNumbers=[mx, mz], stiffness=10.0))
mbs.CreateDistanceConstraint""")
    text = await tool(task, "simulate", code=code)
    said = lines_of(text, "CoordinateConstraint:")
    assert "#1 MassPoint's y: holds it at y = 0.05 (its reference 0 plus offset/factor1 = 0.1/2)" in said[0], said
    assert "#2 MassPoint's y — ground: holds it at y = -0.1 (its reference 0 minus offset 0.1)" in said[3], said
    motion = text.split("motion (sampled):")[1]
    assert ", 0.05, 0)" in motion and "position (0, -0.1, " in motion  # Exudyn's solution agrees with the words
    spring = lines_of(text, "CoordinateSpringDamper:")[0]
    assert "#1 MassPoint's x — #2 MassPoint's z" in spring, spring


# ----------------------------------------------------------------------------- 4, 5: what a contact sets and what acts


def wall(seed: int = 1) -> tuple[Any, str]:
    task = instance("pendulum_wall_impacting", seed)
    return task, task.reference_program


async def test_a_contact_line_shows_what_was_set_and_what_acts_not_idle_defaults() -> None:
    task, code = wall()
    line = lines_of(await tool(task, "simulate", code=code), "SphereTriangleContact:")[0]
    for idle in ("frictionProportionalZone", "contactStiffnessExponent", "adhesionExponent", "includeEdges 7"):
        assert idle not in line, line  # Exudyn's defaults, which change nothing here
    for acting in ("contactStiffness 4.3e+04", "contactDamping 0", "restitutionCoefficient 0.76", "impactModel 2"):
        assert acting in line, line
    assert "its face and all three edges" in line, line
    # set, but without effect: a friction zone without friction, a restitution the linear model does not use
    idle = code.replace("impactModel=2, restitutionCoefficient=restitution)",
                        "impactModel=0, restitutionCoefficient=restitution, frictionProportionalZone=0.01)")
    line = lines_of(await tool(task, "simulate", code=idle), "SphereTriangleContact:")[0]
    assert ("set but without effect here: frictionProportionalZone 0.01 (no friction: dynamicFriction 0), "
            "restitutionCoefficient 0.76 (impactModel 0 uses contactDamping only)") in line, line
    # with friction, its proportional zone acts, default or not
    rough = code.replace("impactModel=2,", "impactModel=2, dynamicFriction=0.3,")
    line = lines_of(await tool(task, "simulate", code=rough), "SphereTriangleContact:")[0]
    assert "dynamicFriction 0.3" in line and "frictionProportionalZone 0.001" in line, line


async def test_the_sphere_sphere_contact_leaves_out_its_idle_adhesion_model() -> None:
    task = instance("sphere_sphere_and_sphere_ground_impact")
    line = lines_of(await tool(task, "simulate", code=task.reference_program), "SphereSphereContact:")[0]
    assert "adhesionExponent" not in line and "frictionProportionalZone" not in line, line
    assert "restitutionCoefficient" in line and "spheresRadii" in line, line


async def test_a_sphere_triangle_contact_says_that_its_side_does_not_matter() -> None:
    task, code = wall()
    line = lines_of(await tool(task, "simulate", code=code), "SphereTriangleContact:")[0]
    assert ("the sphere's centre is on its - side; either side acts alike: the contact pushes the sphere away "
            "from the triangle on the side its centre is on") in line, line


async def test_the_side_of_a_sphere_triangle_contact_does_not_change_the_motion() -> None:
    """What the words above say, seen in Exudyn: the wall's corners in the other order (its normal
    turned over, the sphere on its + side) move the pendulum alike, impacts included."""
    task, code = wall()
    turned = code.replace("[radius, length, -2 * length],\n", "[radius, 0, 0],\n", 1)
    turned = turned.replace("[radius, 0, 0]]),", "[radius, length, -2 * length]]),", 1)
    assert turned != code and turned.count("[radius, 0, 0]") == 1
    answer = await tool(task, "compare", code_a=code, code_b=turned)
    assert answer.startswith("compare: A and B move alike"), answer
    line = lines_of(await tool(task, "simulate", code=turned), "SphereTriangleContact:")[0]
    assert "on its + side" in line, line


def test_the_inspectors_contact_defaults_are_the_installed_exudyns() -> None:
    """The defaults ``inspect/acting.py`` hides are Exudyn's own: a new Exudyn that changes one fails here."""
    import exudyn.itemInterface as items

    from meceng.inspect.acting import DEFAULTS

    for exudyn_type, defaults in DEFAULTS.items():
        made = dict(getattr(items, "Object" + exudyn_type)())
        for key, value in defaults.items():
            assert key in made and made[key] == value, (exudyn_type, key, made.get(key), value)


# ----------------------------------------------------------------------------- 6: a state at the time asked


async def test_a_state_asked_for_is_reported_at_the_time_asked() -> None:
    """Seed 5 of the wall pendulum: its impacts shorten steps, and the grid no longer meets t = 0.5;
    the state is the step nearest to it (0.499998, said as 0.5), not the first one after (0.5001)."""
    task, code = wall(5)
    text = await tool(task, "simulate", code=code, times=[0.5])
    motion = text.split("motion (sampled):")[1]
    assert "t=0.5 #1 RigidBody" in motion and "t=0.5001" not in motion, motion
    # only t = 0.5 was asked for: the run itself went on to its end time, and the answer must not say otherwise
    assert "the run ended" not in text, motion


async def test_a_time_between_two_steps_is_said_with_the_step_it_was_read_at() -> None:
    task = instance("single_pendulum")
    text = await tool(task, "simulate", code=task.reference_program, times=[0.5004, 1.0])
    motion = text.split("motion (sampled):")[1]
    assert ("t=0.5 (the solver step nearest to the asked t = 0.5004; steps of 0.001 s there) #1 MassPoint"
            in motion), motion
    assert "t=1 #1 MassPoint" in motion, motion


async def test_a_run_that_stops_early_still_says_so() -> None:
    task = instance("single_pendulum")
    code = task.reference_program.replace("mbs.Assemble()", """\
def stop(mbs, t):
    return t < 0.7
mbs.SetPostStepUserFunction(stop)
mbs.Assemble()""")
    text = await tool(task, "simulate", code=code, times=[0.5])
    assert "the run ended at t=0.7" in text and "before the end time 2" in text, text


# ----------------------------------------------------------------------------- 7: the documentation


def test_a_component_the_documentation_tells_the_model_to_use_comes_with_its_signature() -> None:
    """'Close the loop with a SphericalJoint', 'combine it with a RevoluteJoint', 'use DistanceConstraint':
    a component named in such an instruction, and not documented beside the one that names it, is
    shown with its call there (the model may not have chosen it)."""
    import re

    from meceng.catalog.catalogs import assembly_catalog, part_catalog

    told = r"\b(?:use|combine it with an?|close the loop\s+with an?)\s+"
    missing = []
    for catalog in (rigid_catalog(), part_catalog(), assembly_catalog()):
        for component in catalog:
            beside = {c.name for c in catalog.resolve([component.name])}
            for other in catalog:
                if other.name in beside or not re.search(told + rf"{other.name}\b", component.context):
                    continue
                call = re.search(rf"(mbs\.Create\w+|\b{other.name})\(", other.context)
                if call is None or call.group(1) + "(" not in component.context:
                    missing.append(f"{component.name} -> {other.name}")
    assert not missing, missing


def test_the_pd_control_text_says_which_sign_the_driven_body_gets_and_exudyn_agrees() -> None:
    import exudyn as exu
    from exudyn.utilities import InertiaCuboid

    text = rigid_catalog().get("JointPDControl").context
    assert "itemNumbers[1] receives minus the returned value" in text, text
    assert "so that itemNumbers[1] is driven by tau = kP*(qd - q) + kD*(vd - q')" in text, text
    # Exudyn: a function that returns +1 N*m turns the body of itemNumbers[1] the negative way
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.CreateGround()
    body = mbs.CreateRigidBody(referencePosition=[0, 0, 0], inertia=InertiaCuboid(1000, [0.1, 0.1, 0.1]))
    mbs.CreateRevoluteJoint(itemNumbers=[ground, body], position=[0, 0, 0], axis=[0, 0, 1])
    mbs.CreateTorsionalSpringDamper(itemNumbers=[ground, body], position=[0, 0, 0], axis=[0, 0, 1],
                                    springTorqueUserFunction=lambda mbs, t, i, q, w, k, d, o: 1.0)
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = 0.1
    settings.timeIntegration.numberOfSteps = 100
    settings.timeIntegration.verboseMode = 0
    settings.solution.file.write = False
    mbs.SolveDynamic(settings)
    assert mbs.GetObjectOutputBody(body, exu.OutputVariableType.AngularVelocity, [0, 0, 0])[2] < -1.0


# ------------------------------------------------------------ still open: a connector's user function


async def test_a_connectors_user_function_is_shown_with_its_values_at_the_sampled_states() -> None:
    """The RRR robot's joints are driven by torsional spring-dampers whose torque a user function
    gives: each line says so, with the torque Exudyn applied (and the rotation it was given) at every
    sampled time, so a model can check a drive's sign and size."""
    import re

    task = instance("rrr_articulated_robot_with_3d_cubic_trajectory")
    text = await tool(task, "simulate", code=task.reference_program)
    lines = lines_of(text, "TorsionalSpringDamper:")
    assert len(lines) == 3
    for line in lines:
        assert "springTorqueUserFunction: its torque at the sampled states (itemNumbers[1] receives minus it):" in line
        values = re.findall(r"t=([0-9.]+): (-?[0-9.e+-]+) N·m at rotation (-?[0-9.e+-]+) rad", line)
        assert [t for t, _, _ in values] == ["0", "1", "2"], line
    assert any(float(torque) != 0.0 for line in lines for torque in re.findall(r"t=[0-9.]+: (-?[0-9.e+-]+) N·m", line))


# ----------------------------------------------------------------------------- still open: a program that fails early


async def test_a_program_that_fails_before_assemble_is_answered_in_words_not_json() -> None:
    task = instance("single_pendulum")
    for code, stage, error in (("import exudyn as exu\nraise ValueError('no')", "started", "ValueError"),
                               ("x = (\n", "refused", "syntax error")):
        for name, arguments in (("simulate", {"code": code}), ("snapshot", {"code": code})):
            text = await tool(task, name, **arguments)
            assert text.startswith(f"stage: {stage}; error: ") and error in text, (name, text)
            assert "{" not in text.splitlines()[-1] and not text.lstrip().startswith("{"), text
            assert "no system to show: the program stopped before its system was assembled" in text, text
