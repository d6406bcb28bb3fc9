"""What real models found wrong in the inspector and the snapshot (issue 34), each on a task model's
ground truth: the contact's geometry, user-function loads as values, every body in the default
answer, orientation of spinning bodies, inertia in body axes, counts, rolling discs, the picture.

Every expected number comes from the task's own parameters and plain geometry or physics, never
from a run of the inspector.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.inspect.answer import num, vec
from meceng.inspect.scene import build_scene
from meceng.inspect.system import SystemView
from meceng.inspect.view import build_view
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

WALL = "pendulum_wall_impacting"
CAR = "non_steerable_four_wheeled_car"
SCARA = "2r_scara_robot"
DISC = "disc_rolling_on_ground"


def _instance(slug: str, seed: int = 0):
    return default_registry().get(slug).instance(seed)


async def _simulate(slug: str, program: str | None = None, **arguments) -> str:
    instance = _instance(slug)
    code = program or instance.reference_program
    return (await Toolbox(instance, rigid_catalog()).call("simulate", {"code": code, **arguments})).text


async def _view(slug: str, times: tuple[float, ...] | None = None, program: str | None = None) -> SystemView:
    """The view the agent's tools make (user-function loads called at the sampled states)."""
    instance = _instance(slug)
    run = await execute(program or instance.reference_program, instance.sim.block(),
                        ExecutionLimits(inspect_times=times or (instance.sim.end_time,), inspect_loads=True))
    return build_view(run.items, run.system, run.inspection, run.trajectory, run.times)


def _line(text: str, start: str) -> str:
    return next(x.strip() for x in text.splitlines() if x.strip().startswith(start))


async def test_a_sphere_triangle_contact_is_named_with_its_wall() -> None:
    p = _instance(WALL).params
    r, length = p["radius"], p["length"]
    text = await _simulate(WALL)
    line = _line(text, "#3 ")
    assert line.startswith("#3 SphereTriangleContact: #1 RigidBody — #0 Ground"), line
    assert "SphereSphereContact" not in text
    corners = [(r, -length, -2 * length), (r, length, -2 * length), (r, 0.0, 0.0)]
    assert "triangle corners " + ", ".join(vec(c) for c in corners) in line
    assert "normal x " in line and "on its - side" in line
    # the sphere's centre is L·sin(phi0) + r from the plane x = r, inside the triangle: gap L·sin(phi0)
    gap = float(re.search(r"gap ([-\d.e+]+)", line).group(1))
    assert gap == pytest.approx(length * np.sin(np.radians(p["angle_deg"])), rel=1e-3)
    # and the picture draws the wall (orange, the three corners) and the sphere's contact circle
    view = await _view(WALL)
    for t in view.times:
        contact = [s for s in build_scene(view, t) if s.role == "contact"]
        wall = [s for s in contact if s.kind == "box"]
        assert wall and np.allclose(wall[0].points, corners)
        assert any(s.kind == "circle" and s.radius == pytest.approx(r) for s in contact)


def _trajectory(t: float, start: float, end: float, duration: float) -> tuple[float, float]:
    """The SCARA description's cosine ramp: desired angle and rate."""
    if t >= duration:
        return end, 0.0
    return (start + (end - start) * (1 - np.cos(np.pi * t / duration)) / 2,
            (end - start) * np.pi / (2 * duration) * np.sin(np.pi * t / duration))


async def test_user_function_torques_show_as_values_the_control_law_gives() -> None:
    """The SCARA's PD torques, evaluated in the sandbox at the sampled states, are the description's
    law applied to the states the same answer reports."""
    p = _instance(SCARA).params
    view = await _view(SCARA, times=(0.5, 1.0))
    text = await _simulate(SCARA, times=[0.5, 1.0])
    assert "given by a user function" in text and "its values" in text
    for t in (0.5, 1.0):
        states = [view.body(b).state_at(t) for b in (1, 2)]
        phi = [float(np.arctan2(s.rotation[1, 0], s.rotation[0, 0])) for s in states]
        omega = [s.angular_velocity[2] for s in states]
        q1d, v1d = _trajectory(t, *np.radians([p["q1_start_deg"], p["q1_end_deg"]]), p["duration"])
        q2d, v2d = _trajectory(t, *np.radians([p["q2_start_deg"], p["q2_end_deg"]]), p["duration"])
        tau1 = p["kp"] * (q1d - phi[0]) + p["kd"] * (v1d - omega[0])
        tau2 = p["kp"] * (q2d - (phi[1] - phi[0])) + p["kd"] * (v2d - (omega[1] - omega[0]))
        for load, expected in zip([x for x in view.loads if x.vector is None], (tau1 - tau2, tau2), strict=True):
            value = dict(load.values)[states[0].t]
            assert value == pytest.approx((0, 0, expected), abs=1e-6 * max(1.0, abs(expected)))
            assert f"t={num(states[0].t)} {vec(value)}" in text


def _covered(section: str) -> set[int]:
    """Object numbers a section names, runs like #1–#25 unfolded."""
    out: set[int] = set()
    for low, high in re.findall(r"#(\d+)(?:–#(\d+))?", section):
        out.update(range(int(low), int(high or low) + 1))
    return out


async def test_the_default_answer_shows_every_body_of_the_car_and_of_the_largest_task() -> None:
    times = [0.5, 1.0, 1.5, 2.0]  # four times asked for: every body still at every time
    text = await _simulate(CAR, times=times)
    bodies = text.split("bodies at t = 0:")[1].split("connectors")[0]
    assert _covered(bodies) >= {0, 1, 2, 3, 4, 5}
    for t in times:
        for body in range(1, 6):
            assert f"t={num(t)} #{body} RigidBody: position (" in text, (t, body)
    grid = await _simulate("grid_mesh_and_large_sphere_impact")
    section = grid.split("bodies at t = 0:")[1].split("connectors")[0]
    assert _covered(section) >= set(range(1, 26)) | {86}
    assert "#86 MassPoint: mass 0.823" in section  # the impacting sphere is never cut
    motion = grid.split("motion (sampled):")[1].split("ranges")[0]
    assert _covered(motion) >= set(range(1, 26)) | {86} and len(grid) < 4000


async def test_a_rolling_wheel_reads_as_a_rotation_about_its_axle() -> None:
    """Rolling without slip: the disc turns by -(v/r)·t about its local x axis (the axle), whose
    direction stays (cos psi, sin psi, 0); the sampled states and the range say the same."""
    p = _instance(DISC).params
    rate = p["velocity"] / p["radius"]
    psi = np.radians(p["heading_deg"])
    text = await _simulate(DISC)
    assert "angles (" not in text and "Tait-Bryan" not in text
    for t in (1.0, 2.0):
        line = next(x for x in text.splitlines() if x.strip().startswith(f"t={num(t)} #1 RigidBody"))
        turned = float(re.search(r"turned ([-\d.e+]+) rad \([-\d.e+]+ turns\) about local x", line).group(1))
        assert turned == pytest.approx(-rate * t, rel=1e-3)
        assert f"x→{vec((np.cos(psi), np.sin(psi), 0.0))}" in line
    low, high = re.search(r"turned about local x \[([-\d.e+]+), ([-\d.e+]+)\]", text).groups()
    assert float(low) == pytest.approx(-rate * 2.0, rel=1e-3) and float(high) == 0.0
    # the car's wheels: turned by the distance rolled over the radius, about local y (the axle)
    car = _instance(CAR).params
    text = await _simulate(CAR)
    for wheel in (2, 5):
        start = re.search(rf"#{wheel} RigidBody: [^\n]*position \(([-\d.e+]+),", text).group(1)
        line = _line(text, f"t=2 #{wheel} RigidBody")
        end = re.search(r"position \(([-\d.e+]+),", line).group(1)
        turned = float(re.search(r"turned ([-\d.e+]+) rad .* about local y", line).group(1))
        assert turned == pytest.approx((float(end) - float(start)) / car["wheel_radius"], rel=2e-3)


ROBOT = "rrr_articulated_robot_with_3d_cubic_trajectory"
TILTED = '''
import exudyn as exu
from exudyn.utilities import *
import numpy as np
SC = exu.SystemContainer()
mbs = SC.AddSystem()
inertia = InertiaCuboid(density=1000.0, sideLengths=[0.6, 0.1, 0.2]).Rotated(RotationMatrixZ(np.pi / 6))
mbs.CreateRigidBody(referencePosition=[0, 0, 0], inertia=inertia)
mbs.Assemble()
'''


async def test_inertia_is_given_in_body_axes_with_the_principal_directions() -> None:
    """A link whose length lies along local y reads as a small Iyy (homogeneous cuboid:
    I_yy = m(w² + w²)/12); a tensor turned about z names its principal axes' directions."""
    instance = _instance(ROBOT)
    p = instance.params
    w, length = 0.05, p["length2"]
    draft = instance.reference_program.replace("sideLengths=[length2, w, w]", "sideLengths=[w, length2, w]")
    assert draft != instance.reference_program
    text = await _simulate(ROBOT, program=draft)
    mass = 2790.0 * w * w * length
    along_y = (mass * (length**2 + w**2) / 12, mass * 2 * w**2 / 12, mass * (length**2 + w**2) / 12)
    assert f"Ixx, Iyy, Izz {vec(along_y)}" in _line(text, "#2 RigidBody:")
    assert _line(text, "#2 RigidBody:") != _line(await _simulate(ROBOT), "#2 RigidBody:")
    tilted = await _simulate(ROBOT, program=TILTED)
    line = _line(tilted, "#0 RigidBody:")
    mass = 1000.0 * 0.6 * 0.1 * 0.2
    longest = (np.cos(np.pi / 6), np.sin(np.pi / 6), 0.0)  # the 0.6 m side: the smallest moment
    assert f"principal {num(mass * (0.1**2 + 0.2**2) / 12)} along {vec(longest)}" in line, line


async def test_load_counts_match_the_load_lines() -> None:
    """The car: gravity on each of the five bodies is five loads, and the two torques two; the
    count and the list agree and no line is cut."""
    text = await _simulate(CAR)
    assert "7 loads (5 Gravity, 2 Torque)" in _line(text, "system:")
    section = text.split("\nloads")[1].split("\nmotion")[0]
    counts = [int(n) for n in re.findall(r"^  (\d+) × ", section, flags=re.M)]
    singles = len(re.findall(r"^  (?!\d+ × )\S", section, flags=re.M))
    assert sum(counts) + singles == 7 and "more" not in section
    gravity = _line(section, "5 × Gravity")
    assert _covered(gravity.split("one on each of")[1]) == {1, 2, 3, 4, 5}
    assert _covered(_line(section, "2 × Torque").split("one on each of")[1]) == {4, 5}


async def test_a_rolling_disc_is_placed_at_its_contact_point_with_what_it_locks() -> None:
    """The car's wheels touch the plane z = 0 straight below their centres; the left ones lock all
    three directions, the front-right lateral slip is free, the rear-right only rolls (the
    description's constrainedAxes); the picture puts the contact there, at every time."""
    p = _instance(CAR).params
    text = await _simulate(CAR)
    half_length, half_track = p["wheelbase"] / 2, p["track"] / 2
    expected = {10: ((half_length, half_track, 0), "lateral y, longitudinal x, normal z", ""),
                11: ((half_length, -half_track, 0), "longitudinal x, normal z", "lateral y"),
                13: ((-half_length, -half_track, 0), "longitudinal x", "lateral y, normal z")}
    for number, (contact, locked, free) in expected.items():
        line = _line(text, f"#{number} RollingDisc:")
        assert f"contact point {vec(contact)} (height 0 above the plane through (0, 0, 0), normal z)" in line, line
        assert f"axle y, radius {num(p['wheel_radius'])}" in line
        assert f"locked there: {locked}," in line
        assert (f"translation {free}" in line) if free else "translation" not in line
    view = await _view(CAR)
    for t in view.times:
        wheel = view.body(2).state_at(t)
        below = (wheel.position[0], wheel.position[1], 0.0)
        joints = [s.points[0] for s in build_scene(view, t) if s.kind == "point" and s.role == "joint"]
        assert any(np.allclose(point, below, atol=1e-6) for point in joints), (t, joints)


async def test_the_snapshot_draws_bodies_by_their_inertia_and_joints_at_every_time() -> None:
    """The pendulum's bob is a sphere of its radius (I = 2/5 m r²), the car's wheels are discs of
    their radius, the joints' axes are drawn at the later time too (turned with the chassis), a
    spherical joint is drawn unlike a revolute one, and the tool says what its picture shows."""
    r = _instance(WALL).params["radius"]
    wall = await _view(WALL)
    for t in wall.times:
        bob = [s for s in build_scene(wall, t) if s.role == "body" and s.kind == "circle"]
        assert len(bob) == 1 and bob[0].radius == pytest.approx(r, rel=1e-6)
    car = await _view(CAR)
    radius = _instance(CAR).params["wheel_radius"]
    end = build_scene(car, car.times[-1])
    wheel = car.body(2).state_at(car.times[-1])
    outline = [s for s in end if s.kind == "box" and s.role == "body"
               and np.allclose(np.mean(s.points, axis=0), wheel.position, atol=1e-9)]
    assert outline and max(np.hypot(p[0] - wheel.position[0], p[2] - wheel.position[2])
                           for p in outline[0].points) == pytest.approx(radius, rel=1e-6)
    revolute_points = [c.points[0] for c in car.connectors if c.kind == "RevoluteJoint"]
    axes = [s for s in end if s.kind == "line" and s.role == "joint"]
    for point in revolute_points:  # at t = 2 the joints are 18 m further: their axes drawn there
        moved = np.asarray(point) + np.subtract(wheel.position, car.body(2).state_at(0.0).position) * (1, 0, 0)
        assert any(np.allclose(np.mean(s.points, axis=0), moved, atol=1e-3) for s in axes), point
    gyro = await _view("gyroscope_on_spherical_joint")
    roles = {s.role for s in build_scene(gyro, 0.0) if s.kind == "point"}
    assert "spherical" in roles
    from meceng.inspect.snapshot import spread_labels

    apart = spread_labels([(np.zeros(2), "#1"), (np.zeros(2), "#2")], np.ones(2))
    assert apart[0][0] != apart[1][0]
    instance = _instance(WALL)
    said = (await Toolbox(instance, rigid_catalog(), vision=True).call(
        "snapshot", {"code": instance.reference_program})).text
    assert "t = 0 s (top row) and t = 1.5 s" in said and "1 body (1 as sphere)" in said


async def test_self_check_answers_in_words() -> None:
    """Like every other tool: no JSON, each finding on a line, the energy balance said; a program
    with a NaN from the start is reported as such."""
    instance = _instance("single_pendulum")
    toolbox = Toolbox(instance, rigid_catalog())
    text = (await toolbox.call("self_check", {"code": instance.reference_program})).text
    assert text.startswith("stage: solved; degrees of freedom ") and "{" not in text
    assert "findings:\n  - no problem found" in text
    change = float(re.search(r"J, ([-\d.e+]+) % of the motion's energy", text).group(1))
    assert abs(change) < 1.0  # an undamped pendulum keeps its energy
    broken = instance.reference_program.replace("mbs.Assemble()", "mbs.Assemble()\nraise ValueError('late')")
    words = (await toolbox.call("self_check", {"code": broken})).text
    assert "findings:\n  - " in words and "{" not in words


async def test_a_graded_run_never_calls_a_user_function_outside_the_solver() -> None:
    """The values of user-function loads are the agent's tools' business: a graded execution (which
    records the inspector's states at t = 0 and the end) must move exactly as one without the
    inspector, even for a function that keeps state between calls."""
    instance = _instance("mass_oscillator_with_user_function")
    program = instance.reference_program.replace(
        "def UFforce(mbs, t, loadVector):\n",
        "calls = [0]\n\ndef UFforce(mbs, t, loadVector):\n    calls[0] += 1\n"
        "    return [force_amplitude * (2.0 if calls[0] == 1 else 1.0), 0, 0]\n")
    assert "calls[0] == 1" in program
    block = instance.sim.block()
    plain = await execute(program, block, ExecutionLimits())
    graded = await execute(program, block, ExecutionLimits(inspect_times=(instance.sim.end_time,)))
    assert plain.solved and graded.solved and graded.inspection is not None
    assert np.array_equal(plain.trajectory, graded.trajectory)
    # the agent's tool does call it, and says what it returned
    shown = await execute(program, block, ExecutionLimits(inspect_times=(instance.sim.end_time,), inspect_loads=True))
    assert any(state.get("loads") for state in shown.inspection["states"])
