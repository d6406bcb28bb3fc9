"""Level 3b machines family (79 simplified wind turbine, 80 grinding bench): a rotor / spindle driven by
a torque in the bore(s) of a flexible, ground-clamped tower / housing.

For each assembly (seed 0, and seed 1 of the grinding bench): the ground truth runs with the expected
degrees of freedom and the joined interface markers coincide at t = 0 (the clamps exactly, the bores
and shafts to micrometres: weighted centres of faceted cylinder surfaces); the spin-up follows the
rigid rotor's J theta'' = T (J about the axis from the rotating part's FEM mass matrix,
FEMinterface.GetRigidBodyInertia; the centre of mass lies on the axis, so gravity has no torque and
the frictionless bearings none either); the bearings carry the rotating part's weight and the
ground clamp the weight of the whole machine (time averages: the centre of mass does not move on
average); and a wrong assembly fails against the ground truth while the ground truth passes against
itself.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass
from pathlib import Path

import exudyn as exu
import numpy as np
import pytest
from assemblies import build, joint_offsets, joints, run_assembly, saved_parts
from exudyn.FEM import FEMinterface
from exudyn.utilities import SensorNode, SensorObject

from meceng.eval.chain import evaluate_rigid
from meceng.tasks.base import TaskInstance
from meceng.tasks.registry import default_registry
from meceng.tools.execution import Execution

TURBINE, BENCH = "simplified_wind_turbine", "grinding_bench"
#: (fixed part's slot, rotating part's slot) per assembly
SLOTS = {TURBINE: ("tower", "rotor"), BENCH: ("housing", "spindle")}
#: degrees of freedom: 7 rigid (Euler parameters) + 6 static modes per interface beyond the first + 6
#: eigenmodes per part, minus one Euler-parameter constraint per part, 6 for the clamp, 5 for the
#: revolute joint (and 2 for the bench's floating bearing)
DOF = {TURBINE: (7 + 12) + (7 + 12) - 2 - 6 - 5, BENCH: (7 + 18) + (7 + 12) - 2 - 6 - 5 - 2}


@dataclass
class Case:
    instance: TaskInstance
    files: dict[str, Path]
    reference: Execution


_CASES: dict[tuple[str, int], Case] = {}


@pytest.fixture(scope="module")
def case_of(tmp_path_factory: pytest.TempPathFactory):
    """Parts and ground-truth run of an assembly instance, made once per module."""

    def get(slug: str, seed: int) -> Case:
        if (slug, seed) not in _CASES:
            instance = default_registry().get(slug).instance(seed)
            files = asyncio.run(saved_parts(instance, tmp_path_factory.mktemp(f"{slug}_{seed}")))
            _CASES[slug, seed] = Case(instance, files, asyncio.run(run_assembly(instance, files)))
        return _CASES[slug, seed]

    return get


#: a second seed of the bench in the slow suite (the default suite keeps one seed of each machine)
CASES = [(TURBINE, 0), (BENCH, 0), pytest.param(BENCH, 1, marks=pytest.mark.slow)]


@pytest.mark.parametrize(("slug", "seed"), CASES)
def test_ground_truth_runs_and_the_joined_interfaces_coincide(case_of, slug: str, seed: int) -> None:
    case = case_of(slug, seed)
    run = case.reference
    assert run.solved and run.error is None, run.error
    assert run.system["degreeOfFreedom"] == DOF[slug] and run.system["redundantConstraints"] == 0
    assert run.times is not None and run.times[-1] == pytest.approx(case.instance.sim.end_time)

    namespace = build(case.instance, case.files)
    mbs = namespace["mbs"]
    mbs.Assemble()
    offsets = joint_offsets(mbs)
    print(slug, seed, "offsets", offsets)
    assert offsets[0] < 1e-12  # the clamp: planar faces, the weighted centre is exact
    assert max(offsets[1:]) < 1e-4  # bore / shaft: faceted cylinders, micrometres off (0.45 mm was harmful)


def _inertia(path: Path) -> tuple[float, np.ndarray, float]:
    """Mass, centre of mass (part frame) and moment of inertia about the part frame's x-axis, the
    rotation axis (the frame's origin lies on it), from the FEM mass matrix."""
    fem = FEMinterface()
    fem.LoadFromFile(str(path))
    inertia = fem.GetRigidBodyInertia()
    return inertia.Mass(), np.asarray(inertia.COM()), float(np.asarray(inertia.Inertia())[0, 0])


@pytest.mark.parametrize(("slug", "seed"), CASES)
def test_spin_up_and_support_forces_follow_the_rigid_machine(case_of, slug: str, seed: int) -> None:
    case = case_of(slug, seed)
    p, sim = case.instance.params, case.instance.sim
    fixed, rotating = SLOTS[slug]
    mass, com, inertia_x = _inertia(case.files[f"{rotating}.npz"])
    fixed_mass, *_ = _inertia(case.files[f"{fixed}.npz"])
    assert np.hypot(com[1], com[2]) < 1e-4  # on the axis (mesh asymmetry only): no gravity torque

    namespace = build(case.instance, case.files)
    mbs, body = namespace["mbs"], namespace[rotating]
    generic = joints(mbs)  # the clamp first, then the bearing(s), as the description orders them
    node = body["FFRFReducedOrderObjectDict"]["nRigidBody"]
    spin = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=exu.OutputVariableType.AngularVelocity,
                                    storeInternal=True))
    forces = [mbs.AddSensor(SensorObject(objectNumber=j, outputVariableType=exu.OutputVariableType.ForceLocal,
                                         storeInternal=True)) for j in generic]
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.endTime = sim.end_time
    settings.timeIntegration.numberOfSteps = sim.steps
    settings.timeIntegration.generalizedAlpha.spectralRadius = 0.8  # as the task's settings
    assert "spectralRadius = 0.8" in sim.block()
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = 0
    mbs.SolveDynamic(settings)
    omega = mbs.GetSensorStoredData(spin)
    t, omega_x = omega[:, 0], omega[:, 1]
    theta = np.concatenate(([0.0], np.cumsum(np.diff(t) * (omega_x[1:] + omega_x[:-1]) / 2)))

    # the spin-up: alpha = T / J, the turned angle omega0 t + alpha t^2 / 2; the frame (the shaft /
    # journal interface) carries small torsional vibrations of the flexible part on top
    alpha = p["torque"] / inertia_x
    slope = np.polyfit(t, omega_x, 1)[0]
    gain = theta[-1] - p["omega0"] * t[-1]
    print(slug, seed, "alpha", slope, alpha, "angle", theta[-1], "gain", gain, alpha * t[-1] ** 2 / 2,
          "wobble", np.max(np.abs(omega[:, 2:])))
    assert slope == pytest.approx(alpha, rel=0.01)
    assert theta[-1] == pytest.approx(p["omega0"] * t[-1] + alpha * t[-1] ** 2 / 2, rel=1e-3)
    assert gain == pytest.approx(alpha * t[-1] ** 2 / 2, rel=0.02)  # the torque's share of the angle
    assert np.max(np.abs(omega[-len(t) // 2:, 2:])) < 0.01 * omega_x[-1]  # it spins about x, no whirl

    # support forces, averaged over the run: the bearings carry the rotating part's weight, the clamp
    # the whole machine's (Exudyn's joint force acts on the first marker's body with the opposite sign:
    # the ground / the fixed part; the joint frames are the global frame up to micro-rotations)
    mean = [np.mean(mbs.GetSensorStoredData(f)[:, 1:4], axis=0) for f in forces]
    g = p["g"]
    bearings = -sum(mean[1:])
    clamp = -mean[0]
    print("bearings", bearings, mass * g, "clamp", clamp, (mass + fixed_mass) * g)
    assert bearings[2] == pytest.approx(mass * g, rel=0.02) and np.hypot(*bearings[:2]) < 0.02 * mass * g
    assert clamp[2] == pytest.approx((mass + fixed_mass) * g, rel=0.02)
    assert np.hypot(*clamp[:2]) < 0.02 * (mass + fixed_mass) * g


def _wrong(instance: TaskInstance) -> tuple[str, str]:
    """A plausible assembly error per assembly: (description, wrong program)."""
    program = instance.reference_program
    if instance.slug == TURBINE:  # the rotor turned around: shaft in the bore, but the hub at the back (-x)
        return "rotor turned around", program.replace(
            "referencePosition=[rotor_x, 0, hub_height],",
            "referencePosition=[-rotor_x, 0, hub_height], referenceRotationMatrix=RotationMatrixZ(np.pi),")
    # the grinding bench: locating and floating bearing swapped (the spindle located at the right seat)
    wrong = program.replace("constrainedAxes=[1, 1, 1, 0, 1, 1]", "constrainedAxes=[LOCATING]")
    wrong = wrong.replace("constrainedAxes=[0, 1, 1, 0, 0, 0]", "constrainedAxes=[1, 1, 1, 0, 1, 1]")
    return "bearings swapped", wrong.replace("constrainedAxes=[LOCATING]", "constrainedAxes=[0, 1, 1, 0, 0, 0]")


@pytest.mark.parametrize("slug", (TURBINE, BENCH))
def test_a_wrong_assembly_fails(case_of, slug: str) -> None:
    case = case_of(slug, 0)
    what, wrong = _wrong(case.instance)
    assert wrong != case.instance.reference_program, what
    candidate = asyncio.run(run_assembly(case.instance, case.files, wrong))
    sim = case.instance.sim
    verdict = evaluate_rigid(candidate, case.reference, end_time=sim.end_time, steps=sim.steps, selected=None,
                             required=(), dependencies={})
    print(slug, what, verdict.first_failure, verdict.solution_norm)
    assert verdict.overall is False, what
    assert verdict.first_failure in ("graph_content_match", "solution_match", "solver_success", "topology_match")
    same = evaluate_rigid(case.reference, case.reference, end_time=sim.end_time, steps=sim.steps, selected=None,
                          required=(), dependencies={})
    assert same.overall
