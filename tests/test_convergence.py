"""Converged comparisons (issue 43) on made-up motions: how R is found from the ground truth's
self-error, the cost bound, what a failed run falls back to, the record, the store's facts; and the
velocity scale taken from the centres of mass, not the rims."""

from __future__ import annotations

import numpy as np
import pytest

from meceng.eval.behaviour import BehaviourTolerance, compare_behaviour
from meceng.eval.chain import evaluate_rigid
from meceng.eval.convergence import CONVERGE_CAP, STEP_BUDGET, ConvergedRuns, largest_factor, settled, step_check
from meceng.pipeline.converged import candidate_runs, find_convergence, from_fact
from meceng.pipeline.store import ReferenceStore, reference_key
from meceng.tools.execution import Execution, ExecutionLimits

T = np.linspace(0.0, 1.0, 101)


def point_motion(amplitude: float, error: float = 0.0) -> dict:
    """One mass point on a line, x = amplitude sin(2 pi t) + error t (a step error growing with time)."""
    p = np.zeros((len(T), 3))
    p[:, 0] = amplitude * np.sin(2 * np.pi * T) + error * T
    v = np.gradient(p, T, axis=0)
    rows = np.full((len(T), 1, 18), np.nan)
    rows[:, 0, 0:3], rows[:, 0, 3:6] = p, v
    return {"bodies": [{"index": 0, "type": "MassPoint", "mass": 1.0, "inertia": None, "com": [0, 0, 0]}],
            "t": T, "states": rows}


def spinning_motion(precession: float, spin: float, com_speed_error: float = 0.0) -> dict:
    """A disc of inertia radius ~0.2 m spinning at ``spin`` about z while its centre circles slowly
    (radius 0.1 m at ``precession`` rad/s); ``com_speed_error`` adds to the centre's velocity only."""
    angle = precession * T
    p = np.column_stack([0.1 * np.cos(angle), 0.1 * np.sin(angle), 0 * T])
    v = np.gradient(p, T, axis=0) + np.array([com_speed_error, 0.0, 0.0])
    c, s = np.cos(spin * T), np.sin(spin * T)
    rotation = np.zeros((len(T), 3, 3))
    rotation[:, 0, 0], rotation[:, 0, 1], rotation[:, 1, 0], rotation[:, 1, 1], rotation[:, 2, 2] = c, -s, s, c, 1.0
    rows = np.zeros((len(T), 1, 18))
    rows[:, 0, 0:3], rows[:, 0, 3:6], rows[:, 0, 6:9] = p, v, np.array([0.0, 0.0, spin])
    rows[:, 0, 9:18] = rotation.reshape(-1, 9)
    body = {"index": 0, "type": "RigidBody", "mass": 2.0, "inertia": [0.02, 0.02, 0.04, 0, 0, 0], "com": [0, 0, 0]}
    return {"bodies": [body], "t": T, "states": rows}


def test_the_velocity_tolerance_comes_from_the_centres_of_mass_not_the_rims() -> None:
    """A spinning disc (rim 61 m/s) whose centre moves at 0.5 m/s: a centre velocity off by 0.7 %
    of its range fails on the velocity (at the rim's scale it had 43 x more room); the angular
    velocity keeps the rim's scale, so 0.05 % of the spin passes."""
    truth = spinning_motion(5.0, 250.0)
    verdict = compare_behaviour(spinning_motion(5.0, 250.0, com_speed_error=0.01), truth)
    assert verdict.scales is not None and verdict.scales.turning > 40 * verdict.scales.speed
    assert verdict.passed is False and verdict.first_divergence.quantity == "velocity"
    assert compare_behaviour(spinning_motion(5.0, 250.0 * 1.0005), truth).passed
    assert compare_behaviour(spinning_motion(5.0, 250.0 * 1.005), truth).passed is False
    assert verdict.to_json()["scales"]["rim_speed_m_s"] == pytest.approx(verdict.scales.turning)


def test_the_step_check_is_three_times_the_self_error_over_the_base_tolerance() -> None:
    # travel 2 m: position tolerance 2e-3 m; an error of 1e-3 m at the end: ratio 3 x 0.5 = 1.5 (position)
    check = step_check(point_motion(1.0), point_motion(1.0, error=1e-3), 4)
    assert check is not None and check.factor == 4 and check.quantity.endswith("of body 0")
    position = 3 * 1e-3 / (1e-3 * float(np.ptp(point_motion(1.0, error=1e-3)["states"][:, 0, 0])))
    assert check.ratio >= position * 0.99 and not settled(check)
    assert settled(step_check(point_motion(1.0), point_motion(1.0, error=1e-5), 1))
    assert step_check(point_motion(1.0), None, 1) is None  # a failed finer run: no check
    # a horizon compares the first part only: the error there is a fifth of the end's
    half = step_check(point_motion(1.0), point_motion(1.0, error=1e-3), 1, BehaviourTolerance(horizon=0.2))
    assert half is not None and half.ratio < check.ratio


def test_the_cost_bound_is_r_16_and_32000_steps() -> None:
    assert (CONVERGE_CAP, STEP_BUDGET) == (16, 32_000)
    assert [largest_factor(n) for n in (1000, 2000, 4000, 6000, 10000, 15000, 20000)] == [16, 16, 8, 4, 2, 2, 1]


def _series(errors: dict[int, float], failed: tuple[int, ...] = ()):
    """A fake ground truth whose run at R differs from the exact motion by errors[R] (metres at t = 1)."""
    asked: list[int] = []

    async def run_at(factor: int) -> Execution:
        asked.append(factor)
        if factor in failed:
            return Execution(stage="solver_started", error="timeout", error_kind="timeout")
        return Execution(stage="solved", motion=point_motion(1.0, error=errors[factor]))

    return run_at, asked


@pytest.mark.parametrize(("errors", "steps", "factor", "converged", "asked"), [
    # the floor does not bind at the nominal steps: R = 1, nothing beyond today's two runs
    ({1: 1e-5, 2: 0.25e-5}, 2000, 1, True, [1, 2]),
    # second order: the self-error falls 4 x a doubling, settled at R = 4 (checked against 8)
    ({1: 1e-2, 2: 2.5e-3, 4: 6.25e-4, 8: 1.6e-4, 16: 4e-5}, 2000, 4, True, [1, 2, 4, 8]),
    # first order and far off: stops at the cost bound (4000 steps: R = 8), not converged
    ({1: 0.0, 2: 1.0, 4: 1.5, 8: 1.75, 16: 1.875}, 4000, 8, False, [1, 2, 4, 8, 16]),
    # a doubling that does not cut the self-error (0.1 m, then 0.1 m again): the steps do not decide it,
    # R = 1 is kept with its floor, at the cost of one more ground-truth run
    ({1: 0.0, 2: 0.1, 4: 0.0}, 2000, 1, False, [1, 2, 4]),
])
async def test_r_is_found_by_doubling_until_the_self_error_settles(errors, steps, factor, converged, asked) -> None:
    run_at, called = _series(errors)
    found = await find_convergence(run_at, steps, BehaviourTolerance())
    assert (found.convergence.factor, found.convergence.converged, sorted(called)) == (factor, converged, asked)
    assert found.truth.motion is not None and found.complete
    assert found.convergence.steps == factor * steps and len(found.convergence.checks) == len(asked) - 1
    record = found.convergence.to_json()
    assert record["factor"] == factor and record["converged"] is converged and record["cap"] == largest_factor(steps)
    assert ("note" in record) is (factor == 1 and not converged)  # a stalled doubling says so


async def test_a_failed_finer_run_ends_the_search_at_the_last_pair_that_ran() -> None:
    run_at, _ = _series({1: 1e-2, 2: 2.5e-3, 4: 6.25e-4}, failed=(8,))
    found = await find_convergence(run_at, 2000, BehaviourTolerance())
    assert found.convergence.factor == 2 and not found.convergence.converged and not found.complete
    assert "failed" in found.convergence.note


async def test_a_stored_r_loads_its_two_runs_and_the_nominal_pair() -> None:
    run_at, called = _series({1: 1e-2, 2: 2.5e-3, 4: 6.25e-4, 8: 1.6e-4})
    found = await from_fact(run_at, {"factor": 4, "converged": True, "checks": [], "cap": 16}, 2000)
    assert sorted(called) == [1, 2, 4, 8] and found.convergence.factor == 4 and found.convergence.converged


async def test_the_candidate_runs_again_at_r_only_when_r_is_above_one_and_its_run_finished() -> None:
    run_at, _ = _series({1: 1e-2, 2: 2.5e-3, 4: 6.25e-4, 8: 1.6e-4})
    truth = await find_convergence(run_at, 2000, BehaviourTolerance())
    again: list[int] = []

    async def candidate_at(factor: int) -> Execution:
        again.append(factor)
        return Execution(stage="solved", motion=point_motion(1.0, error=7e-4))

    graded = Execution(stage="solved", motion=point_motion(1.0, error=1e-2))
    runs = await candidate_runs(candidate_at, graded, truth)
    assert again == [4] and runs.candidate is not None and runs.convergence.factor == 4
    unfinished = Execution(stage="solver_started", error="diverged", motion=point_motion(1.0, error=0.3))
    as_it_ran = await candidate_runs(candidate_at, unfinished, truth)
    assert again == [4] and "did not finish" in as_it_ran.convergence.note and as_it_ran.candidate is unfinished.motion

    async def timeout(factor: int) -> Execution:
        return Execution(stage="solver_started", error="timed out", error_kind="timeout")

    fallback = await candidate_runs(timeout, graded, truth)
    assert fallback.convergence.factor == 1 and not fallback.convergence.converged
    assert "timeout" in fallback.convergence.note and fallback.candidate is graded.motion


def test_the_paper_s_stages_ignore_the_converged_runs_and_behaviour_records_its_steps() -> None:
    items = {"objects": [], "nodes": [], "markers": [], "loads": [], "sensors": []}
    times, trajectory = np.linspace(0, 1, 11), np.zeros((11, 1))
    reference = Execution(stage="solved", items=items, times=times, trajectory=trajectory, motion=point_motion(1.0))
    candidate = Execution(stage="solved", items=items, times=times, trajectory=trajectory + 1e-9,
                          motion=point_motion(1.0))
    kwargs = dict(end_time=1.0, steps=10, selected=None, required=(), dependencies={})
    plain = evaluate_rigid(candidate, reference, **kwargs)
    from meceng.eval.convergence import Convergence

    converged = ConvergedRuns(Convergence(8, 10, True), point_motion(1.0, error=0.5), point_motion(1.0),
                              point_motion(1.0))
    moved = evaluate_rigid(candidate, reference, **kwargs, converged=converged)
    assert [s.to_json() for s in moved.stages] == [s.to_json() for s in plain.stages]
    assert moved.solution_norm == plain.solution_norm and moved.overall == plain.overall
    assert plain.behaviour["passed"] and "steps" not in plain.behaviour
    assert moved.behaviour["passed"] is False and moved.behaviour["steps"]["factor"] == 8


def test_the_store_keeps_facts_and_a_variant_key_leaves_the_execution_s_key_alone(tmp_path) -> None:
    limits = ExecutionLimits()
    plain = reference_key("p", "s", limits)
    assert reference_key("p", "s", limits, "") == plain and reference_key("p", "s", limits, "motion-only") != plain
    store = ReferenceStore(tmp_path)
    assert store.fact(plain) is None
    store.put_fact(plain, {"factor": 8, "converged": False})
    assert ReferenceStore(tmp_path).fact(plain) == {"factor": 8, "converged": False}
    store.path(plain).with_suffix(".json").write_text("{not json")
    assert store.fact(plain) is None
