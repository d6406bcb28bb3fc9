"""The viewer without a browser: traces kept small, the diff, the index data and the pages of a
site built over run folders (one without traces, one still running), and the report's links."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from meceng.pipeline.traces import MAX_POINTS, decimate_surface, load_traces, save_traces, traces_path
from meceng.tools.execution import Execution
from meceng.viewer.data import data_script, find_runs, index_data, load_run
from meceng.viewer.diff import side_by_side
from meceng.viewer.site import build_site


def _trajectory(steps: int, coords: int, shift: dict[int, float] | None = None) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 2.0, steps)
    q = np.sin(np.outer(t, np.arange(1, coords + 1)))
    for k, amount in (shift or {}).items():
        q[:, k] += amount * t
    return t, q


def _sphere(n: int = 80) -> tuple[np.ndarray, np.ndarray]:
    """A UV sphere of radius 1 with 2 n (n - 1) triangles."""
    theta, phi = np.meshgrid(np.linspace(0, np.pi, n), np.linspace(0, 2 * np.pi, n, endpoint=False), indexing="ij")
    v = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1).reshape(-1, 3)
    tris = []
    for i in range(n - 1):
        for j in range(n):
            a, b, c, d = i * n + j, i * n + (j + 1) % n, (i + 1) * n + j, (i + 1) * n + (j + 1) % n
            tris += [(a, c, b), (b, c, d)]
    return v, np.array(tris)


def test_traces_keep_the_differing_coordinates_on_at_most_200_points(tmp_path: Path) -> None:
    t, q = _trajectory(5001, 60)
    tc, qc = _trajectory(3001, 60, shift={41: 0.5, 7: 0.1})  # adaptive steps: another time grid
    path = save_traces(tmp_path, "origin@1/part@2", Execution("solved", times=tc, trajectory=qc),
                       Execution("solved", times=t, trajectory=q))
    assert path == str(traces_path(tmp_path, "origin@1/part@2").relative_to(tmp_path))
    traces = load_traces(tmp_path, "origin@1/part@2")
    assert traces is not None
    assert traces["ref_q"].shape == (MAX_POINTS, 24) and traces["cand_q"].shape == (MAX_POINTS, 24)
    assert list(traces["coordinates"][:2]) == [41, 7]  # the most different first
    assert list(traces["n_coordinates"]) == [60, 60]
    # what was kept is the trajectory, resampled: the end value of coordinate 41 is still there
    assert traces["cand_q"][-1, 0] == pytest.approx(qc[-1, 41], abs=1e-5)
    assert (tmp_path / path).stat().st_size < 60_000


def test_traces_of_a_program_that_never_ran_and_of_parts(tmp_path: Path) -> None:
    assert save_traces(tmp_path, "a@0", Execution("refused"), Execution("not_run")) is None
    assert not traces_path(tmp_path, "a@0").exists() and load_traces(tmp_path, "a@0") is None
    t, q = _trajectory(50, 3)
    assert save_traces(tmp_path, "b@0", Execution("refused"), Execution("solved", times=t, trajectory=q))
    traces = load_traces(tmp_path, "b@0")
    assert traces is not None and "cand_q" not in traces and traces["ref_q"].shape == (50, 3)
    sphere = _sphere()
    assert save_traces(tmp_path, "p@0", Execution("reduced", surface=sphere), Execution("reduced", surface=sphere))
    part = load_traces(tmp_path, "p@0")
    assert part is not None and 0 < len(part["cand_triangles"]) <= 2000 and "ref_q" not in part


def test_decimated_surface_keeps_its_shape() -> None:
    vertices, triangles = _sphere(120)
    assert len(triangles) > 20000
    small_v, small_t = decimate_surface(vertices, triangles)
    assert 500 < len(small_t) <= 2000
    assert small_t.max() < len(small_v)
    radius = np.linalg.norm(small_v, axis=1)
    assert radius.min() > 0.9 and radius.max() <= 1.0 + 1e-6  # still a unit sphere


def test_side_by_side_diff_marks_the_changed_characters() -> None:
    reference = "\n".join(f"line{i} = {i}" for i in range(40))
    program = reference.replace("line5 = 5", "line5 = 7").replace("line30 = 30\n", "")
    table, changed = side_by_side(program, reference)
    assert changed == 2
    assert "<mark>7</mark>" in table and "<mark>5</mark>" in table
    assert "equal lines" in table  # long equal stretches are folded
    assert side_by_side("<b>", "<i>")[0].count("&lt;") == 2  # escaped


def _record(slug: str, seed: int, *, failure: str | None = None, level: str = "1", **extra: object) -> dict:
    stages = [{"name": "choose_components", "passed": True, "detail": "all required components chosen"},
              {"name": "finished_assemble", "passed": failure != "finished_assemble", "detail": "NameError: x"},
              {"name": "solution_match", "passed": failure is None, "detail": "solutions differ (norm 0.3)"}]
    return {"id": 1, "slug": slug, "name": slug.replace("_", " "), "level": level, "seed": seed,
            "description": f"A {slug}.", "params": {"m": 1.0}, "stages": stages, "overall": failure is None,
            "first_failure": failure, "error_categories": ["inertia and mass"] if failure else [],
            "differences": [{"item": "object:MassPoint#1", "key": "mass", "value": 2.0, "expected": 1.0,
                             "category": "inertia and mass"}] if failure else [],
            "generation": {"prompt": "write it", "answer": "```python\nm = 2.0\n```", "code": "m = 2.0\nrun()\n",
                           "meta": {"thinking": "hmm"}},
            "timing": {"llm_s": 1.5, "evaluation_s": 0.25}, "tokens": {"prompt": 10, "completion": 5},
            "files": {"reference": f"programs/{slug}/seed{seed}_reference.py"}, **extra}


def _run_folder(folder: Path, records: list[dict], finished: bool = True) -> Path:
    folder.mkdir(parents=True)
    settings = {"llm": {"model": folder.name, "temperature": 0.0, "think": False},
                "prompt": {"select_template": "CI1", "code_template": "MBS1"}, "pipeline": {"agent": "pipeline"}}
    for r in records:
        (folder / r["files"]["reference"]).parent.mkdir(parents=True, exist_ok=True)
        (folder / r["files"]["reference"]).write_text("m = 1.0\nrun()\n")
    if finished:
        (folder / "run.json").write_text(json.dumps({"settings": settings, "summary": {}, "tasks": records}))
    else:
        (folder / "settings.json").write_text(json.dumps(settings))
        (folder / "journal.jsonl").write_text("".join(json.dumps(r) + "\n" for r in records) + '{"half a li')
    return folder


def test_site_over_a_finished_and_a_running_run(tmp_path: Path) -> None:
    done = _run_folder(tmp_path / "runs" / "model-a", [
        _record("single_pendulum", 0), _record("single_pendulum", 1, failure="solution_match"),
        _record("n_pendulum", 0, failure="topology_match",
                topology_causes={"cause": "missing item types", "missing": {"object:ConnectorSpringDamper": 1},
                                 "surplus": {}, "inert": []})])
    t, q = _trajectory(300, 4)
    save_traces(done, "single_pendulum@1", Execution("solved", times=t, trajectory=q + 0.1),
                Execution("solved", times=t, trajectory=q))
    running = _run_folder(tmp_path / "runs" / "model-b", [_record("single_pendulum", 0),
                                                         _record("single_pendulum", 0, failure="solution_match")],
                          finished=False)
    assert find_runs([tmp_path / "runs"]) == [done, running]
    assert len(load_run(running).tasks) == 1  # the journal's last line of a key wins; a torn line is cut

    stats = build_site([tmp_path / "runs"], tmp_path / "site", workers=1)
    assert (stats.records, stats.pages, stats.plots) == (4, 4, 1)
    data_js = (tmp_path / "site" / "data.js").read_text()
    data = json.loads(data_js.removeprefix("window.MECENG_DATA = ").rstrip().removesuffix(";"))
    assert len(data["rows"]) == 4 and data["stages"] == ["choose_components", "finished_assemble", "solution_match"]
    row = dict(zip(data["fields"], data["rows"][1], strict=True))
    assert row["stages"] == "PPF" and row["failure"] == "solution_match" and row["status"] == 0
    assert row["detail"] == "solutions differ (norm 0.3)" and row["tokens"] == 15
    for name in ("index.html", "static/viewer.js", "static/viewer.css"):
        assert (tmp_path / "site" / name).stat().st_size > 500

    failed = (tmp_path / "site" / row["href"]).read_text()
    assert "table class='diff'" in failed and "<mark>2</mark>" in failed  # program beside the reference
    assert "solutions differ (norm 0.3)" in failed and "single_pendulum-1.traj.png" in failed
    assert (tmp_path / "site" / row["href"]).with_name("single_pendulum-1.traj.png").stat().st_size > 5000
    assert "inertia and mass (1)" in failed and "thinking (3 characters)" in failed
    assert "href='../../../runs/model-a/programs/single_pendulum/seed1_reference.py'" in failed
    causes = (tmp_path / "site" / "tasks" / "r0" / "n_pendulum-0.html").read_text()
    assert "topology: why it differs" in causes and "1x object:ConnectorSpringDamper" in causes
    passed = (tmp_path / "site" / "tasks" / "r0" / "single_pendulum-0.html").read_text()
    assert ".png" not in passed  # a passing record draws no plot

    # built again: the plot is kept, not drawn again; a record gone from the run takes its page along
    run_json = json.loads((done / "run.json").read_text())
    run_json["tasks"] = run_json["tasks"][1:]
    (done / "run.json").write_text(json.dumps(run_json))
    again = build_site([tmp_path / "runs"], tmp_path / "site", workers=1)
    assert (again.records, again.plots) == (3, 0)
    assert "single_pendulum-1.traj.png" in (tmp_path / "site" / "tasks" / "r0" / "single_pendulum-1.html").read_text()
    assert not (tmp_path / "site" / "tasks" / "r0" / "single_pendulum-0.html").exists()


def test_data_script_cannot_end_its_script_element() -> None:
    text = data_script({"rows": [["</script><script>alert(1)</script>"]]})
    assert "</script>" not in text and text.startswith("window.MECENG_DATA = ")


def test_index_data_labels_two_runs_of_the_same_settings_apart(tmp_path: Path) -> None:
    a = load_run(_run_folder(tmp_path / "x" / "same", [_record("single_pendulum", 0)]))
    b = load_run(_run_folder(tmp_path / "y" / "same2", [_record("single_pendulum", 0)]))
    b.settings["llm"]["model"] = "same"
    labels = [r["label"] for r in index_data([a, b])["runs"]]
    assert labels[0] != labels[1] and labels[0].endswith("(same)")


def test_report_links_to_a_viewer_beside_it(tmp_path: Path) -> None:
    from meceng.report import build_report

    run = _run_folder(tmp_path / "runs" / "model-a", [_record("single_pendulum", 0)])
    run_json = json.loads((run / "run.json").read_text())
    run_json["settings"]["prompt"] = {"select_template": "CI1", "code_template": "MBS1"}
    run_json["summary"] = {}
    (run / "run.json").write_text(json.dumps(run_json))
    build_report([run], tmp_path / "report")
    assert "viewer/index.html" not in (tmp_path / "report" / "report.html").read_text()
    build_site([run], tmp_path / "report" / "viewer", pages=False)
    build_report([run], tmp_path / "report")
    assert "<a href='viewer/index.html#task=single_pendulum'>single_pendulum</a>" in (
        tmp_path / "report" / "report.html").read_text()


async def test_task_pages_draw_the_programs_system_beside_the_ground_truths(tmp_path: Path) -> None:
    """A link placed at its tip instead of its centre: the program's box and the ground truth's
    stand apart in the same view, on every page of a rigid record (passing ones too)."""
    import re

    from meceng.inspect.scene import VIEWS
    from meceng.pipeline import RunSettings, run_benchmark
    from meceng.pipeline.rescore import evaluate_program
    from meceng.tasks.registry import default_registry

    slug = "rrr_articulated_robot_with_3d_cubic_trajectory"
    settings = RunSettings(only=(slug,), levels=("2",), variations=1, out=tmp_path, run_name="gold",
                           progress=False)
    await run_benchmark(settings)
    stats = build_site([tmp_path / "gold"], tmp_path / "site")
    page = next((tmp_path / "site" / "tasks").rglob("*.html")).read_text()
    assert stats.pages == 1 and "System: program vs ground truth" in page
    assert page.count("<svg class='system'") == 4 * len(VIEWS)  # program and truth, t = 0 and the end
    assert page.count("<polygon") == 4 * len(VIEWS) * 3  # three links as boxes in every picture

    instance = default_registry().get(slug).instance(0)
    wrong = instance.reference_program.replace("referencePosition=[length2 + 0.5 * length3, 0, length1]",
                                               "referencePosition=[length2 + length3, 0, length1]")
    _, candidate, _ = await evaluate_program(instance, wrong)
    with np.load(traces_path(tmp_path / "gold", f"{slug}@0")) as data:
        arrays = json.loads(str(data["scenes"]))
    assert arrays["cand"]["shapes"][0] == arrays["ref"]["shapes"][0]  # the gold run's program is the truth
    from meceng.pipeline.traces import system_scenes

    moved = system_scenes(candidate)
    boxes = [s for s in moved["shapes"][0] if s[0] == "box"]
    truth = [s for s in arrays["ref"]["shapes"][0] if s[0] == "box"]
    centre = lambda shape: np.mean(np.asarray(shape[2]), axis=0)  # noqa: E731
    assert np.allclose(centre(boxes[2]) - centre(truth[2]), [instance.params["length3"] / 2, 0, 0], atol=1e-6)
    assert re.search(r"ground truth, t = 0 s", page)


def test_an_agents_picture_is_named_in_its_conversation() -> None:
    from meceng.viewer.pages import _chat

    html = _chat({"rounds": 1, "transcript": [{"role": "tool", "name": "snapshot", "content": "the picture follows",
                                               "images": ["PNG, 80000 bytes"]}]})
    assert "a picture went to the model (PNG, 80000 bytes)" in html
