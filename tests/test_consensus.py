"""``--agent consensus``: the grouping of samples by behaviour (no ground truth), the chosen program
and its confidence, the record, the report's numbers, and runs of the scripted model."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from meceng.eval.calibration import accuracy, calibration, calibration_error
from meceng.eval.consensus import consensus_of, group_samples, motions_agree
from meceng.eval.rates import Rate
from meceng.llm.backend_scripted import ScriptedBackend, ScriptedDraft, parse_scripted
from meceng.llm.types import ChatRequest, ChatResponse, LLMError, LLMSettings
from meceng.pipeline import RunSettings, run_benchmark

T = np.linspace(0.0, 1.0, 51)


def swing(radius: float = 1.0, rate: float = 3.0, shift: float = 0.0) -> dict[str, Any]:
    """A motion record of one mass point on a circle (the shape ``tools/motion.py`` writes)."""
    p = np.column_stack([radius * np.cos(rate * T) + shift, radius * np.sin(rate * T), 0 * T])
    rows = np.full((len(T), 18), np.nan)
    rows[:, 0:3], rows[:, 3:6] = p, np.gradient(p, T, axis=0)
    return {"bodies": [{"index": 0, "type": "MassPoint", "mass": 1.0, "inertia": None, "com": [0.0, 0.0, 0.0]}],
            "t": T, "states": rows[:, None, :]}


def test_equal_motions_group_a_faulty_one_does_not_and_the_largest_group_answers() -> None:
    good, faulty = swing(), swing(rate=3.3)
    result = consensus_of([good, faulty, swing(), good], ["a", "b", "a2", "a"], [False] * 4)
    assert result.groups == ((0, 2, 3), (1,))
    assert result.chosen == 0 and result.confidence == pytest.approx(0.75) and result.counted == 4
    words = {(a.a, a.b): a for a in result.agreements}
    assert words[(0, 3)].detail == "the same program"  # equal texts are not compared
    assert words[(0, 2)].agree and not words[(0, 1)].agree and "motions part" in words[(0, 1)].detail
    # a wrong program written most often is still outvoted; within the group the most written text wins
    assert consensus_of([faulty, good, good, swing()], ["b", "x", "y", "y"], [False] * 4).chosen == 2


def test_agreement_does_not_depend_on_which_sample_is_asked_first() -> None:
    """Tolerances are fractions of a motion's scales: the comparison takes the smaller of the two
    programs' scales (``eval/agreement``, the ``compare`` tool's), so two samples agree or not in
    either order. A motion with a larger range is compared at the smaller one's tolerance."""
    small, large = swing(radius=1.0), swing(radius=1.0, shift=0.003)
    wide = swing(radius=3.0)
    wide_shifted = swing(radius=3.0, shift=0.003)
    for a, b in ((small, large), (wide, wide_shifted)):
        assert motions_agree(a, b)[0] == motions_agree(b, a)[0]
    # the same offset: within 1e-3 of the wide motion's range, not of the small one's
    assert motions_agree(wide, wide_shifted)[0] and not motions_agree(small, large)[0]
    assert motions_agree(swing(), swing())[0] and not motions_agree(swing(), swing(radius=1.01))[0]
    assert motions_agree(swing(), None) == (False, "not both simulated")


def test_non_transitive_agreement_makes_cliques_around_the_best_connected_sample() -> None:
    # 1 agrees with 0, 2 and 3; 0, 2 and 3 with nobody else: 1 goes first and takes 0 (the earliest)
    links = {(0, 1), (1, 2), (1, 3)}
    result = group_samples([True] * 4, [False] * 4, lambda a, b: (a, b) in links)
    assert result.groups == ((0, 1), (2,), (3,)) and result.chosen == 0 and result.confidence == 0.5
    # complete agreement is one group whatever the order
    assert group_samples([True] * 3, [False] * 3, lambda a, b: True).groups == ((0, 1, 2),)


def test_failures_are_groups_of_their_own_and_lost_samples_are_not_counted() -> None:
    asked: list[tuple[int, int]] = []

    def agree(a: int, b: int) -> bool:
        asked.append((a, b))
        return True

    # samples 0 and 1 did not run, 3 was lost: two failures never form a group; the one that ran wins the tie
    result = group_samples([False, False, True, False], [False, False, False, True], agree)
    assert asked == [] and result.groups == ((2,), (0,), (1,))
    assert result.chosen == 2 and result.counted == 3 and result.confidence == pytest.approx(1 / 3)
    nothing = group_samples([False, False], [True, True], agree)
    assert nothing.chosen is None and nothing.groups == () and nothing.counted == 0


def test_the_reports_numbers_on_a_hand_made_set() -> None:
    def task(overall: bool, confidence: float, samples: list[bool | None], behaves: bool | None = None) -> dict:
        return {"overall": overall, "first_failure": None if overall else "solution_match",
                "behaviour": {"passed": overall if behaves is None else behaves},
                "consensus": {"confidence": confidence, "samples": [
                    {"lost": "server down"} if s is None else {"lost": None, "overall": s, "behaviour_passed": s}
                    for s in samples]}}

    tasks = [task(True, 1.0, [True, True]), task(True, 0.5, [True, False]), task(False, 0.5, [False, True, None]),
             task(False, 1.0, [False, False], behaves=True),
             {"overall": False, "first_failure": "infrastructure", "consensus": {"confidence": 0.0, "samples": []}}]
    rates = accuracy(tasks)
    assert rates["consensus"] == Rate(2, 4) and rates["single"] == Rate(4, 8)  # the lost sample is not counted
    assert rates["consensus_behaviour"] == Rate(3, 4) and rates["single_behaviour"] == Rate(4, 8)
    bins = {b["bin"]: b for b in calibration(tasks)}
    assert bins["(0.4, 0.6]"]["n"] == 2 and bins["(0.4, 0.6]"]["paper"] == Rate(1, 2)
    assert bins["(0.8, 1.0]"]["paper"] == Rate(1, 2) and bins["(0.8, 1.0]"]["behaviour"] == Rate(2, 2)
    assert bins["(0.0, 0.2]"]["n"] == 0
    # |0.5 - 0.5| for half the answers, |0.5 - 1.0| for the other half
    assert calibration_error(list(bins.values())) == pytest.approx(0.25)
    assert calibration_error(list(bins.values()), "behaviour") == pytest.approx(0.0)


def test_the_scripted_model_is_seeded_and_its_same_fault_twin_repeats_one_draft() -> None:
    drafts = {"t@0": (ScriptedDraft("a", "A", "x = 1"), ScriptedDraft("b", "B", "x = 2"))}
    mixed = ScriptedBackend("scripted:p=0.3", 42, drafts)
    draws = [mixed.answer("t@0", k, "gold")[1] for k in range(200)]
    assert draws == [ScriptedBackend("scripted:p=0.3", 42, drafts).answer("t@0", k, "gold")[1] for k in range(200)]
    assert 0.2 < draws.count("reference") / 200 < 0.4 and {"draft a [A]", "draft b [B]"} < set(draws)
    same = [ScriptedBackend("scripted-same:p=0.3", 42, drafts).answer("t@0", k, "gold")[1] for k in range(50)]
    assert set(same) == {"reference", "draft a [A]"}
    with pytest.raises(ValueError, match="scripted:p=P"):
        parse_scripted("scripted:p=2")


class Flaky:
    """A backend that loses every request of the samples it is told to, else answers as ``inner``."""

    def __init__(self, inner: Any, lose: set[int]) -> None:
        self.inner, self.lose, self.name = inner, lose, "flaky"

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.sample in self.lose:
            raise LLMError("connection refused", transient=True)
        return await self.inner.chat(request)

    async def aclose(self) -> None:
        return None


def settings(tmp_path: Path, model: str, name: str, samples: int = 3, **changes: Any) -> RunSettings:
    given: dict[str, Any] = {"only": ("single_mass_oscillator",), **changes}
    return RunSettings(llm=LLMSettings(model=model, backend="scripted", temperature=0.7), variations=1, out=tmp_path,
                       run_name=name, progress=False, workers=2, agent="consensus", samples=samples, **given)


async def test_a_consensus_record_keeps_every_sample_the_groups_and_the_chosen_programs_verdicts(
        tmp_path: Path) -> None:
    run = json.loads((await run_benchmark(settings(tmp_path, "scripted:p=0.5", "mixed", samples=6))).read_text())
    record = json.loads((tmp_path / "mixed" / "journal.jsonl").read_text().splitlines()[-1])
    block = record["consensus"]
    samples = block["samples"]
    assert block["k"] == 6 and len(samples) == 6 and [s["seed"] for s in samples] == list(range(42, 48))
    kinds = {s["endpoint"].removeprefix("scripted: ") for s in samples}
    assert "reference" in kinds and len(kinds) > 1  # this seed draws both (the test would be empty otherwise)
    for s in samples:
        assert s["code"] and s["lost"] is None and s["ran"] is True
        assert s["overall"] is (s["endpoint"] == "scripted: reference")  # the paper's verdict of each sample
        assert isinstance(s["behaviour_passed"], bool) and block["groups"][s["group"]].count(s["index"]) == 1
    chosen = samples[block["chosen"]]
    largest = block["groups"][0]
    assert block["chosen"] in largest and block["confidence"] == pytest.approx(len(largest) / 6, abs=1e-4)
    assert all(len(g) <= len(largest) for g in block["groups"])
    # the task's verdicts are the chosen program's
    assert record["overall"] is chosen["overall"] and record["behaviour"]["passed"] is chosen["behaviour_passed"]
    assert record["generation"]["code"] == chosen["code"]
    # same motion, same group: every pair inside a group agrees, none across two groups of programs that ran
    agree = {(a["a"], a["b"]): a["agree"] for a in block["agreements"]}
    for (a, b), ok in agree.items():
        assert ok is (samples[a]["group"] == samples[b]["group"])
    assert run["tasks"][0]["consensus"] == block  # run.json holds the journal's record


async def test_every_wrong_sample_the_same_fault_gives_a_confident_wrong_answer(tmp_path: Path) -> None:
    path = await run_benchmark(settings(tmp_path, "scripted-same:p=0.0", "same", samples=3))
    record = json.loads(path.read_text())["tasks"][0]
    assert record["consensus"]["groups"] == [[0, 1, 2]] and record["consensus"]["confidence"] == 1.0
    assert record["overall"] is False


async def test_a_lost_sample_is_not_a_wrong_program_and_all_lost_is_a_lost_task(tmp_path: Path) -> None:
    from meceng.pipeline.scripted import scripted_backend
    from meceng.tasks.registry import default_registry

    given = settings(tmp_path, "scripted:p=1", "lost")
    instance = default_registry().get("single_mass_oscillator").instance(0)
    inner = scripted_backend(given.llm, [instance])
    record = json.loads((await run_benchmark(given, backend=Flaky(inner, {1}))).read_text())["tasks"][0]
    block = record["consensus"]
    assert record["overall"] is True and block["counted"] == 2 and block["confidence"] == 1.0
    assert block["samples"][1]["lost"] and block["samples"][1]["group"] is None and "overall" not in block["samples"][1]
    gone = json.loads((await run_benchmark(settings(tmp_path, "scripted:p=1", "gone"),
                                           backend=Flaky(inner, {0, 1, 2}))).read_text())
    assert gone["tasks"][0]["first_failure"] == "infrastructure" and gone["summary"]["counted"] == 0


def test_consensus_is_refused_for_flexible_levels(tmp_path: Path) -> None:
    import asyncio

    with pytest.raises(ValueError, match="levels 1 and 2"):
        asyncio.run(run_benchmark(settings(tmp_path, "scripted:p=1", "flex", levels=("3a",), only=())))


def test_the_viewer_shows_the_groups_the_answer_and_each_samples_verdicts() -> None:
    from meceng.viewer.pages import task_page

    block = {"k": 3, "counted": 3, "chosen": 0, "confidence": 0.6667, "groups": [[0, 2], [1]],
             "agreements": [{"a": 0, "b": 1, "agree": False, "detail": "motions part at t = 0.01 s"}],
             "samples": [{"index": 0, "seed": 42, "lost": None, "group": 0, "code": "x = 1\n", "endpoint": "scripted: "
                          "reference", "ran": True, "overall": True, "first_failure": None, "behaviour_passed": True},
                         {"index": 1, "seed": 43, "lost": None, "group": 1, "code": "x = 2\n", "endpoint": "scripted: "
                          "draft mass [inertia and mass]", "ran": True, "overall": False,
                          "first_failure": "graph_content_match", "behaviour_passed": False},
                         {"index": 2, "seed": 44, "lost": None, "group": 0, "code": "x = 1\n", "endpoint": "scripted: "
                          "reference", "ran": True, "overall": True, "first_failure": None, "behaviour_passed": True}]}
    page = task_page({"slug": "s", "seed": 0, "overall": True, "consensus": block}, run_label="r", root="../",
                     program=None, reference=None, file_links={}, images={}, neighbours=(None, None))
    section = page.split("id='consensus'")[1]
    assert "group 1: 2 samples" in section and "group 2: 1 sample<" in section and "#0 ← answer" in section
    assert "failed at graph_content_match" in section and "motions part at t = 0.01 s" in section
    assert "sample #1 beside the answer (1 changed line(s))" in section
    assert "Other fields" not in page  # the block is shown, not dumped


def test_a_sweep_study_asks_for_consensus_at_a_sampling_temperature(tmp_path: Path) -> None:
    from meceng.sweeps.spec import load_spec, study_points

    spec = tmp_path / "consensus.toml"
    spec.write_text('[[models]]\nname = "qwen3:8b"\n[[studies]]\nname = "vote"\nagent = "consensus"\nsamples = 3\n'
                    '[[studies]]\nname = "greedy"\nagent = "consensus"\ngrid.temperature = [0.0]\n')
    vote, greedy = (study_points(s)[0] for s in load_spec(spec).studies)
    assert vote.name.endswith("_consensus-k3") and vote.samples == 3 and vote.llm().temperature == 0.7
    assert greedy.name.endswith("_consensus-k5") and greedy.llm().temperature == 0.0
