"""Level 3b: the door hinge (81) and the free-falling mounting bracket (82) against closed forms.

Door hinge: the gap-side leaf turns about the hinge axis under the door force; its angle follows the
rigid leaf's J theta'' = F (d_x cos(theta) - d_y sin(theta)) (J about the axis from the leaf's FEM
inertia, d the 'door' marker's position), in particular theta'' = moment / J at the start.
Bracket: the centre of mass of the free flexible body moves exactly as a thrown point,
c(t) = c0 + v_c0 t - g t^2/2 e_z (c0, v_c0 from the part's FEM inertia and the initial rigid motion),
and its angular momentum about the centre of mass stays I_c omega0.
A wrong assembly (load at the wrong interface, part misplaced) fails the verdict; GT vs GT passes.
"""

from __future__ import annotations

import asyncio
from pathlib import Path
from typing import Any

import exudyn as exu
import numpy as np
import pytest
from assemblies import build, run_assembly, saved_parts
from exudyn.rigidBodyUtilities import EulerParameters2RotationMatrix
from scipy.integrate import solve_ivp

from meceng.eval.chain import evaluate_rigid
from meceng.tasks.registry import default_registry

POSITION = exu.OutputVariableType.Position
Case = tuple[Any, dict[str, Path], Any]  # instance, saved parts, ground-truth run


@pytest.fixture(scope="module")
def hinge(tmp_path_factory: pytest.TempPathFactory) -> Case:
    """Seed 0 of the door hinge: instance, saved parts, ground-truth run (shared by the tests)."""
    instance = default_registry().get("door_hinge").instance(0)
    files = asyncio.run(saved_parts(instance, tmp_path_factory.mktemp("hinge")))
    return instance, files, asyncio.run(run_assembly(instance, files))


@pytest.fixture(scope="module", params=[0, 1])
def bracket(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Case:
    instance = default_registry().get("mounting_bracket_free_falling").instance(request.param)
    files = asyncio.run(saved_parts(instance, tmp_path_factory.mktemp(f"bracket{request.param}")))
    return instance, files, asyncio.run(run_assembly(instance, files))


def verdict(candidate, reference, instance):
    return evaluate_rigid(candidate, reference, end_time=instance.sim.end_time, steps=instance.sim.steps,
                          selected=None, required=(), dependencies={})


def marker(namespace: dict[str, Any], body: str, key: str) -> np.ndarray:
    return np.array(namespace["mbs"].GetMarkerOutput(namespace[body][key], POSITION))


def test_door_hinge_leaf_turns_with_moment_over_inertia(hinge) -> None:
    instance, files, run = hinge
    assert run.solved, run.error
    # 2 x (7 rigid + 12 modal) coordinates; 2 Euler-parameter, 6 clamp, 5 revolute constraints
    assert run.system["nODE2"] == 38 and run.system["degreeOfFreedom"] == 25
    assert run.system["redundantConstraints"] == 0
    p = instance.params

    namespace = build(instance, files)
    mbs = namespace["mbs"]
    mbs.Assemble()
    # the joined interfaces coincide at t = 0 (weighted centres of meshed surfaces: micrometres)
    mount_ground = np.array([p["mount_x"], 0, p["mid_z"]])
    assert np.linalg.norm(marker(namespace, "pinLeaf", "pin_leaf:mount") - mount_ground) < 5e-5
    pin, bore = marker(namespace, "pinLeaf", "pin_leaf:pin"), marker(namespace, "gapLeaf", "gap_leaf:bore")
    assert np.linalg.norm(pin - bore) < 5e-5 and np.linalg.norm(bore - [0, 0, p["mid_z"]]) < 5e-5
    door = marker(namespace, "gapLeaf", "gap_leaf:door")

    # the rigid leaf about the hinge axis (the z-axis through its frame origin)
    inertia = namespace["femGap"].GetRigidBodyInertia()
    j_axis = inertia.Inertia()[2, 2]
    alpha0 = p["door_force"] * door[0] / j_axis

    def rigid(_t: float, y: list[float]) -> list[float]:
        return [y[1], p["door_force"] * (door[0] * np.cos(y[0]) - door[1] * np.sin(y[0])) / j_axis]

    node = mbs.GetNodeODE2Index(namespace["gapLeaf"]["FFRFReducedOrderObjectDict"]["nRigidBody"])
    rotations = [EulerParameters2RotationMatrix(q[node + 3:node + 7]) for q in run.trajectory]
    theta = np.array([np.arctan2(r[1, 0], r[0, 0]) for r in rotations])
    assert max(abs(r[2, 2] - 1) for r in rotations) < 1e-6  # the leaf turns about z only
    t = run.times
    exact = solve_ivp(rigid, (0, t[-1]), [0, 0], t_eval=t, rtol=1e-10, atol=1e-12).y[0]
    assert 0.2 < theta[-1] < 2.5  # a real swing, not a huge one
    assert np.max(np.abs(theta - exact)) < 1e-3 * exact[-1]
    # at the start: theta = theta_1 + alpha0 t^2 / 2 over the first 10 ms; theta_1 is the first step's
    # jump (~1e-4 rad), where the solver closes the micrometre misfit of the joined interface centres
    early = (t > 0) & (t <= 0.01)
    jump, alpha = np.linalg.lstsq(np.c_[np.ones(early.sum()), t[early] ** 2 / 2], theta[early], rcond=None)[0]
    assert abs(jump) < 1e-3 and alpha == pytest.approx(alpha0, rel=0.01)


def test_door_force_at_the_wrong_interface_fails(hinge) -> None:
    instance, files, reference = hinge
    wrong = instance.reference_program.replace("markerNumber=gapLeaf['gap_leaf:door']",
                                               "markerNumber=gapLeaf['gap_leaf:bore']")
    assert wrong != instance.reference_program
    candidate = asyncio.run(run_assembly(instance, files, wrong))
    result = verdict(candidate, reference, instance)
    assert candidate.solved and result.overall is False
    assert result.first_failure in ("graph_content_match", "solution_match", "topology_match")
    assert verdict(reference, reference, instance).overall


def test_bracket_centre_of_mass_falls_freely(bracket) -> None:
    instance, files, run = bracket
    assert run.solved, run.error
    assert run.system["nODE2"] == 19 and run.system["degreeOfFreedom"] == 18  # one Euler-parameter constraint
    p = instance.params
    namespace = build(instance, files)
    mbs, fem = namespace["mbs"], namespace["femBracket"]
    body = namespace["bracket"]["FFRFReducedOrderObjectDict"]
    mbs.Assemble()

    inertia = fem.GetRigidBodyInertia()
    mass, com = inertia.Mass(), np.array(inertia.COM())
    omega0 = np.array([p["omega_x"], p["omega_y"], p["omega_z"]])
    c0 = np.array([0, 0, p["drop_height"]]) + com  # identity rotation
    v0 = np.array([p["vx0"], 0, p["vz0"]]) + np.cross(omega0, com)
    g = np.array([0, 0, -p["g"]])

    # centre of mass of the reduced body from the trajectory: frame position + R (chi + M_tPsi q / m)
    o = body["oFFRFreducedOrder"]
    chi = np.array(mbs.GetObjectParameter(o, "centerOfMass"))
    shift = np.array(mbs.GetObjectParameter(o, "mPhitTPsi")) / mass
    assert chi == pytest.approx(com, abs=1e-12)
    rigid = mbs.GetNodeODE2Index(body["nRigidBody"])
    modal = mbs.GetNodeODE2Index(body["nGenericODE2"])
    for t, q in zip(run.times, run.trajectory, strict=True):
        centre = q[rigid:rigid + 3] + EulerParameters2RotationMatrix(q[rigid + 3:rigid + 7]) @ (chi + shift @ q[modal:])
        assert np.linalg.norm(centre - (c0 + v0 * t + g * t**2 / 2)) < 5e-6, t
    turned = EulerParameters2RotationMatrix(run.trajectory[-1][rigid + 3:rigid + 7])
    assert np.degrees(np.arccos((np.trace(turned) - 1) / 2)) > 30  # it tumbles


def test_bracket_angular_momentum_is_conserved(bracket) -> None:
    """L about the centre of mass from all mesh nodes with the consistent mass matrix, sum x_i x (M v)_i."""
    instance, files, _ = bracket
    p = instance.params
    namespace = build(instance, files)
    mbs, fem = namespace["mbs"], namespace["femBracket"]
    o = namespace["bracket"]["FFRFReducedOrderObjectDict"]["oFFRFreducedOrder"]
    mbs.Assemble()
    mass_matrix, n, mass = fem.GetMassMatrix(), fem.NumberOfNodes(), fem.GetRigidBodyInertia().Mass()

    def momentum() -> np.ndarray:
        x = np.array([mbs.GetObjectOutputSuperElement(o, POSITION, i) for i in range(n)])
        v = np.array([mbs.GetObjectOutputSuperElement(o, exu.OutputVariableType.Velocity, i) for i in range(n)])
        mv = (mass_matrix @ v.ravel()).reshape(n, 3)
        centre = (mass_matrix @ x.ravel()).reshape(n, 3).sum(0) / mass
        return np.cross(x - centre, mv).sum(0)

    omega0 = np.array([p["omega_x"], p["omega_y"], p["omega_z"]])
    expected = fem.GetRigidBodyInertia().InertiaCOM() @ omega0
    assert momentum() == pytest.approx(expected, rel=1e-9)
    exec(instance.sim.block(), namespace)  # the ground truth's own solver settings
    after = momentum()
    assert np.linalg.norm(after - expected) < 5e-5 * np.linalg.norm(expected)


def test_wrong_bracket_fails(bracket) -> None:
    """Seed 0: the bracket placed upside down; seed 1: the initial angular velocity left out."""
    instance, files, reference = bracket
    if instance.seed == 0:
        wrong = instance.reference_program.replace(
            "referencePosition=[0, 0, drop_height],",
            "referencePosition=[0, 0, drop_height], referenceRotationMatrix=RotationMatrixX(np.pi),")
    else:
        wrong = instance.reference_program.replace("initialAngularVelocity=[omega_x, omega_y, omega_z]",
                                                   "initialAngularVelocity=[0, 0, 0]")
    assert wrong != instance.reference_program
    candidate = asyncio.run(run_assembly(instance, files, wrong))
    result = verdict(candidate, reference, instance)
    assert candidate.solved and result.overall is False
    assert verdict(reference, reference, instance).overall
