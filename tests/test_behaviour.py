"""The behaviour verdict: the comparison on made-up motions (what it ignores, what it sees), and on
programs: gold, the same systems built another way (``tasks/alternatives.py``), the repair drafts."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from meceng.eval.behaviour import BehaviourTolerance, compare_behaviour
from meceng.eval.bodies import principal_inertia
from meceng.eval.chain import Tolerances
from meceng.eval.solution import resample
from meceng.pipeline import evaluate_program
from meceng.pipeline.evaluation import Evaluator, refined
from meceng.tasks.alternatives import ALTERNATIVES
from meceng.tasks.drafts import candidate_drafts
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.motion import MOTION_BUDGET

T = np.linspace(0.0, 2.0, 101)


def body(index: int, mass: float, inertia: list[float] | None, p: np.ndarray, w: np.ndarray | None = None,
         rotation: np.ndarray | None = None, com: list[float] | None = None) -> tuple[dict, np.ndarray]:
    """One body's record entry and its (n, 18) states; v from p by differences."""
    v = np.gradient(p, T, axis=0)
    rows = np.full((len(T), 18), np.nan)
    rows[:, 0:3], rows[:, 3:6] = p, v
    if w is not None:
        rows[:, 6:9] = w
        rows[:, 9:18] = (rotation if rotation is not None else np.tile(np.eye(3), (len(T), 1, 1))).reshape(-1, 9)
    return {"index": index, "type": "RigidBody" if w is not None else "MassPoint", "mass": mass, "inertia": inertia,
            "com": com or [0.0, 0.0, 0.0]}, rows


def motion(*bodies: tuple[dict, np.ndarray], t: np.ndarray = T) -> dict:
    return {"bodies": [b for b, _ in bodies], "t": t, "states": np.stack([r for _, r in bodies], axis=1)}


def circle(radius: float, phase: float = 0.0) -> np.ndarray:
    return np.column_stack([radius * np.cos(3 * T + phase), radius * np.sin(3 * T + phase), 0 * T])


def spin(axis: np.ndarray, rate: float, start: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Angular velocity and rotation matrices of a steady spin about a global axis."""
    turn = Rotation.from_rotvec(np.outer(rate * T, axis)).as_matrix()
    return np.tile(rate * axis, (len(T), 1)), turn @ (np.eye(3) if start is None else start)


def test_order_and_identical_bodies_are_matched_by_where_they_start_and_move() -> None:
    a, b = body(0, 1.0, None, circle(1.0)), body(1, 1.0, None, circle(1.0, np.pi))
    verdict = compare_behaviour(motion(b, a), motion(a, b))
    assert verdict.passed and {(c, g) for c, g in verdict.matching} == {(1, 1), (0, 0)}
    # the same two bodies, the second one moved: matched by start, it fails and says which, when
    moved = body(1, 1.0, None, circle(1.0, np.pi) + np.array([0.0, 0.01, 0.0]))
    wrong = compare_behaviour(motion(a, moved), motion(a, b))
    assert wrong.passed is False and wrong.first_divergence is not None
    assert wrong.first_divergence.body == 1 and wrong.first_divergence.quantity == "position"
    assert wrong.first_divergence.time == 0.0 and wrong.largest is not None and wrong.largest.ratio > 1


def test_a_late_divergence_is_found_when_it_happens_and_a_horizon_ends_the_comparison() -> None:
    truth = body(0, 1.0, None, circle(1.0))
    late = circle(1.0)
    late[T > 1.5] += np.array([0.0, 0.05, 0.0])
    verdict = compare_behaviour(motion(body(0, 1.0, None, late)), motion(truth))
    # the finite-difference velocity jumps a sample early
    assert verdict.passed is False and abs(verdict.first_divergence.time - 1.5) <= 0.021
    assert compare_behaviour(motion(body(0, 1.0, None, late)), motion(truth),
                             BehaviourTolerance(horizon=0.7)).passed


def test_reference_point_and_local_axes_do_not_matter_but_the_axes_do() -> None:
    """A cuboid spinning about global z: the candidate keeps its inertia about a point off the centre
    of mass and its local axes permuted (rotation turned to match); then a cuboid turned about z."""
    inertia = [1.0, 2.0, 3.0, 0.0, 0.0, 0.0]
    w, rotation = spin(np.array([0.0, 0.0, 1.0]), 4.0)
    truth = motion(body(0, 2.0, inertia, circle(0.5), w, rotation))
    offset = np.array([0.1, 0.0, 0.0])
    about_point = list(np.array([1.0, 2.0 + 2.0 * 0.01, 3.0 + 2.0 * 0.01]))
    permute = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])  # local x -> global y, ...
    rotated = rotation @ permute
    moved_inertia = [about_point[1], about_point[2], about_point[0], 0.0, 0.0, 0.0]
    same = motion(body(0, 2.0, moved_inertia, circle(0.5), w, rotated, com=list(permute.T @ offset)))
    assert compare_behaviour(same, truth).passed
    turned = motion(body(0, 2.0, inertia, circle(0.5), w, rotation @ Rotation.from_rotvec([0, 0, 0.3]).as_matrix()))
    verdict = compare_behaviour(turned, truth)
    assert verdict.passed is False and verdict.largest.quantity == "axis"


def test_a_symmetric_body_s_axes_in_its_symmetry_plane_are_not_compared() -> None:
    disc = [1.0, 1.0, 2.0, 0.0, 0.0, 0.0]  # axisymmetric about z
    w, rotation = spin(np.array([0.0, 0.0, 1.0]), 10.0)
    truth = motion(body(0, 1.0, disc, circle(0.2), w, rotation))
    other_start = rotation @ Rotation.from_rotvec([0, 0, 1.0]).as_matrix()  # turned about its own axis
    assert compare_behaviour(motion(body(0, 1.0, disc, circle(0.2), w, other_start)), truth).passed
    tilted = rotation @ Rotation.from_rotvec([0.2, 0, 0]).as_matrix()
    assert compare_behaviour(motion(body(0, 1.0, disc, circle(0.2), w, tilted)), truth).passed is False


def test_missing_bodies_and_motions_fail_and_no_ground_truth_motion_is_not_evaluated() -> None:
    a, b = body(0, 1.0, None, circle(1.0)), body(1, 1.0, None, circle(2.0))
    assert compare_behaviour(motion(a), motion(a, b)).passed is False
    assert compare_behaviour(None, motion(a)).passed is False
    assert compare_behaviour(motion(a), None).passed is None
    short = {"bodies": [a[0]], "t": T[:50], "states": a[1][None, :50].transpose(1, 0, 2)}
    assert "ends at" in compare_behaviour(short, motion(a)).detail


def test_principal_inertia_moves_exudyns_reference_point_inertia_to_the_centre_of_mass() -> None:
    # a point mass 2 kg at local (0, 0.5, 0): about the reference point Ixx = Izz = 0.5; about its centre 0
    values, axes = principal_inertia([0.5, 0.0, 0.5, 0.0, 0.0, 0.0], 2.0, [0.0, 0.5, 0.0])
    assert np.allclose(values, 0.0) and axes is not None


#: every level 1-2 task model runs in the slow suite; the default suite takes a sample of the kinds
#: of system (particles, pendulums, rigid mechanisms, rolling, contact, springs). Gold passes
#: behaviour on every model in the default suite anyway: test_gold's sweep asserts it per record.
SAMPLE = frozenset({"single_pendulum", "two_mass_points_with_springs", "double_pendulum_rigid_bodies",
                    "slider_crank_rigid_bodies", "disc_rolling_on_ground", "spinning_disc", "newtons_cradle",
                    "pendulum_wall_impacting"})


def _rigid_models() -> list:
    """Level 1-2 slugs, those outside ``SAMPLE`` marked slow."""
    return [pytest.param(m.slug, marks=[] if m.slug in SAMPLE else [pytest.mark.slow])
            for m in default_registry().select(["1", "2"])]


@pytest.mark.parametrize("slug", _rigid_models())
async def test_gold_passes_behaviour_and_its_record_stays_bounded(slug: str) -> None:
    instance = default_registry().get(slug).instance(3)
    verdict, candidate, _ = await evaluate_program(instance, instance.reference_program)
    assert verdict.behaviour is not None and verdict.behaviour["passed"], verdict.behaviour
    assert verdict.overall  # the paper's verdict is untouched
    assert candidate.motion is not None and candidate.motion["states"].size <= MOTION_BUDGET
    assert len(verdict.behaviour["matching"]) == len(candidate.motion["bodies"]) >= 1


RIGID_ALTERNATIVES = [a for a in ALTERNATIVES if default_registry().get(a.slug).level in ("1", "2")]


@pytest.mark.parametrize("alternative", RIGID_ALTERNATIVES, ids=[a.id for a in RIGID_ALTERNATIVES])
async def test_the_same_system_built_another_way_passes_behaviour(alternative) -> None:
    instance = default_registry().get(alternative.slug).instance(0)
    program = alternative.program(instance)
    assert program != instance.reference_program
    verdict, candidate, _ = await evaluate_program(instance, program)
    assert candidate.solved, candidate.error
    assert verdict.behaviour["passed"], verdict.behaviour


def test_the_alternatives_cover_the_issue_s_kinds_and_levels() -> None:
    kinds = {a.kind for a in ALTERNATIVES}
    assert kinds == {"order", "markers", "reference point", "joint", "frame", "user function"}
    levels = {default_registry().get(a.slug).level for a in ALTERNATIVES}
    assert levels == {"1", "2", "3b"} and len({a.slug for a in ALTERNATIVES}) >= 10


def _coordinate_change(candidate, reference) -> float | None:
    """Independent of the behaviour comparison: a draft keeps the ground truth's coordinates, so
    its trajectory, resampled, tells how far anything moves otherwise (None: not comparable)."""
    if not candidate.solved or candidate.trajectory is None or candidate.trajectory.shape[1] != \
            reference.trajectory.shape[1]:
        return None
    grid = np.linspace(0.0, float(reference.times[-1]), 401)
    difference = resample(candidate.times, candidate.trajectory, grid) - \
        resample(reference.times, reference.trajectory, grid)
    return float(np.max(np.abs(difference)))


@pytest.mark.parametrize("slug", _rigid_models())
async def test_every_draft_that_moves_otherwise_fails_behaviour(slug: str) -> None:
    """A draft behaviour passes either moves as the ground truth (its coordinates within 1e-6 of their
    range) or differs by no more than the ground truth's own step error at the paper's steps (3x what
    twice the steps change; behaviour compares at converged steps where that floor binds)."""
    instance = default_registry().get(slug).instance(0)
    evaluator = Evaluator(2, ExecutionLimits(), Tolerances())
    finer = await evaluator.execute(instance.reference_program, refined(instance), check=False)
    for draft in candidate_drafts(instance):
        verdict, candidate, reference = await evaluator.evaluate(instance, draft.program, None, None)
        if verdict.behaviour["passed"]:
            change = _coordinate_change(candidate, reference)
            spread = float(np.max(np.ptp(reference.trajectory, axis=0))) or 1.0
            step_error = _coordinate_change(finer, reference)
            assert change is not None and (change < 1e-6 * spread or change <= 3 * step_error), \
                (draft.id, change, step_error, verdict.behaviour)


def test_meceng_evaluate_prints_behaviour_beside_the_paper_s_verdict(tmp_path) -> None:
    """A program that builds the same system another way: the paper's verdict fails it (the contact's
    radii in the other order), behaviour passes; the exit status stays the paper's."""
    import json
    import subprocess
    import sys

    alternative = next(a for a in ALTERNATIVES if a.slug == "sphere_sphere_impact")
    path = tmp_path / "program.py"
    path.write_text(alternative.program(default_registry().get(alternative.slug).instance(2)))
    command = [sys.executable, "-m", "meceng", "evaluate", alternative.slug, "--seed", "2", "--code", str(path)]
    proc = subprocess.run([*command, "--json"], capture_output=True, text=True, timeout=120)
    data = json.loads(proc.stdout)
    assert proc.returncode == 1 and data["overall"] is False
    assert data["behaviour"]["passed"] is True and data["behaviour"]["matching"]
    text = subprocess.run(command, capture_output=True, text=True, timeout=120).stdout
    assert "behaviour: [pass]" in text


def test_the_summary_counts_behaviour_and_names_the_disagreements() -> None:
    from meceng.eval.aggregate import summarize

    def record(slug: str, level: str, overall: bool, behaviour: bool | None) -> dict:
        return {"slug": slug, "level": level, "seed": 0, "overall": overall, "first_failure": None if overall else
                "graph_content_match", "stages": [], **({} if behaviour is None else
                                                        {"behaviour": {"passed": behaviour, "detail": "d"}})}

    summary = summarize([record("a", "1", True, True), record("b", "1", False, True), record("c", "2", False, False),
                         record("d", "3a", True, None)])["behaviour"]
    assert (summary["graded"], summary["passed"], summary["both_fail"], summary["behaviour_only"]) == (3, 2, 1, 1)
    assert summary["levels"] == {"1": 1.0, "2": 0.0}
    assert [d["slug"] for d in summary["disagreements"]] == ["b"]


def test_the_report_has_a_behaviour_column_and_names_the_disagreements(tmp_path) -> None:
    import json

    from meceng.report import build_report

    def record(slug: str, level: str, overall: bool, behaviour: bool | None) -> dict:
        return {"level": level, "slug": slug, "seed": 0, "overall": overall,
                "first_failure": None if overall else "graph_content_match",
                "stages": [{"name": "choose_components", "passed": True}], "error_categories": [],
                **({} if behaviour is None else {"behaviour": {"passed": behaviour, "detail": f"{slug} moves"}})}

    settings = {"llm": {"model": "m", "temperature": 0, "think": False},
                "prompt": {"select_template": "CI1", "code_template": "MBS1"}}
    tasks = [record("a", "1", True, True), record("b", "2", False, True), record("c", "3b", False, False),
             record("d", "3a", False, None)]
    (tmp_path / "run").mkdir()
    (tmp_path / "run" / "run.json").write_text(json.dumps({"settings": settings, "summary": {}, "tasks": tasks}))
    build_report([tmp_path / "run"], tmp_path / "report")
    text = (tmp_path / "report" / "report.md").read_text()
    section = text.split("## Behaviour beside the paper's verdict")[1].split("## ")[0]
    assert "| 3 |" in section and "66.7" in section  # levels 1, 2, 3b: 2 of 3 pass behaviour
    differ = text.split("## Where the two verdicts differ")[1].split("## ")[0]
    assert "b@0" in differ and "b moves" in differ and "a@0" not in differ and "c@0" not in differ


ASSEMBLY_ALTERNATIVES = [a for a in ALTERNATIVES if default_registry().get(a.slug).level == "3b"]
#: one assembly in the default suite (its part takes ~10 s to make), the others in the slow one
CHEAP_ASSEMBLIES = ("flexible_pendulum",)


async def _assembly_verdicts(slug: str, programs: list[str], tmp_path) -> list:
    instance = default_registry().get(slug).instance(0)
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=300), Tolerances())
    files = await evaluator.ground_truth_parts(instance, tmp_path)
    return [(await evaluator.evaluate(instance, program(instance), None, None, files=files))[0]
            for program in programs]


@pytest.mark.parametrize("slug", [pytest.param(m.slug, marks=[] if m.slug in CHEAP_ASSEMBLIES else [pytest.mark.slow])
                                  for m in default_registry().select(["3b"])])
@pytest.mark.timeout(900)
async def test_assembly_gold_and_its_alternatives_pass_behaviour(slug: str, tmp_path) -> None:
    programs = [lambda i: i.reference_program, *[a.program for a in ASSEMBLY_ALTERNATIVES if a.slug == slug]]
    verdicts = await _assembly_verdicts(slug, programs, tmp_path)
    assert verdicts[0].overall, verdicts[0].first_failure
    assert all(v.behaviour["passed"] for v in verdicts), [v.behaviour for v in verdicts]


def test_the_viewer_shows_the_matched_bodies_and_where_the_motions_part(tmp_path) -> None:
    from test_viewer import _record, _run_folder, _trajectory

    from meceng.pipeline.traces import save_traces
    from meceng.tools.execution import Execution
    from meceng.viewer.site import build_site

    parted = {"body": 1, "candidate_body": 2, "quantity": "position", "value": 0.02, "tolerance": 0.001,
              "ratio": 20.0, "time": 0.75}
    behaviour = {"passed": False, "detail": "motions part at t = 0.75 s", "matching": [{"candidate": 2, "truth": 1}],
                 "largest": parted, "first_divergence": parted, "scales": {"length_m": 1.0}, "relative": 0.001,
                 "compared_until": 2.0, "widened_by_step_error": []}
    run = _run_folder(tmp_path / "runs" / "m", [_record("single_pendulum", 1, failure="solution_match",
                                                        behaviour=behaviour)])
    t, q = _trajectory(300, 4)
    save_traces(run, "single_pendulum@1", Execution("solved", times=t, trajectory=q + 0.1),
                Execution("solved", times=t, trajectory=q))
    build_site([tmp_path / "runs"], tmp_path / "site", workers=1)
    page = (tmp_path / "site" / "tasks" / "r0" / "single_pendulum-1.html").read_text()
    section = page.split("id='behaviour'")[1].split("<h2")[0]
    assert "program #2 ↔ ground truth #1" in section and "at t = 0.75 s" in section and "fails" in section
    assert "Other fields" not in page or "behaviour" not in page.split("Other fields")[1]
