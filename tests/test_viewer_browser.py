"""The viewer in a real browser (headless Chromium from Debian's packages): a site over a run with
passing and failing tasks of every level and an agent run; the index's rows and filters, the task
pages' diff, stage details and images, and no message on the scripts' console.

Skipped where Chromium is missing, except in CI (CI=true), where a missing browser fails.
"""

from __future__ import annotations

import asyncio
import json
import os
import re
from pathlib import Path
from typing import Any

import pytest
from viewer_runs import agent_run, pipeline_run

from meceng.viewer.browser import find_chromium, load, screenshot
from meceng.viewer.site import build_site


def _need_chromium() -> None:
    if find_chromium() is None:
        if os.environ.get("CI") == "true":
            pytest.fail("CI: chromium is missing (apt-get install chromium)")
        pytest.skip("chromium is not installed")


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    _need_chromium()
    root = tmp_path_factory.mktemp("viewer")

    async def runs() -> None:
        await pipeline_run(root / "runs")
        await agent_run(root / "runs")

    asyncio.run(runs())
    stats = build_site([root / "runs"], root / "site", workers=2)
    records = {name: json.loads((root / "runs" / name / "run.json").read_text())["tasks"] for name in ("fake", "agent")}
    return {"root": root, "site": root / "site", "stats": stats, "records": records}


def _count(dom: str) -> tuple[int, int]:
    match = re.search(r'id="count" data-shown="(\d+)" data-total="(\d+)"', dom)
    assert match, "the index shows no record count"
    return int(match.group(1)), int(match.group(2))


def _body_rows(dom: str) -> int:
    body = dom.split("<tbody>", 1)[1].split("</tbody>", 1)[0]
    return body.count("<tr")


def _clean(page: Any, index: bool = True) -> None:
    """Nothing on the console; on the index, nothing in the box its error handler fills either."""
    assert page.console == [], page.console
    if index:
        errors = re.search(r'<pre id="errors"[^>]*>(.*?)</pre>', page.dom, re.S)
        assert errors is not None and errors.group(1) == "", errors


def test_index_shows_every_record_and_filters_narrow_it(site: dict[str, Any]) -> None:
    index = (site["site"] / "index.html").as_uri()
    records = [r for run in site["records"].values() for r in run]
    assert len(records) == 18 and {str(r["level"]) for r in records} == {"1", "2", "3a", "3b"}
    page = load(index)
    _clean(page)
    assert _count(page.dom) == (18, 18) and _body_rows(page.dom) == 18
    assert "cantilever_beam" in page.dom and "agent, 2 rounds" in page.dom

    failed = sum(1 for r in records if not r["overall"])
    page = load(index + "#status=failed")
    _clean(page)
    assert 0 < failed < 18 and _count(page.dom) == (failed, 18) and _body_rows(page.dom) == failed

    page = load(index + "#level=3b&task=cantilever_beam")
    assert _count(page.dom)[0] == 2 and "parts_overall" in page.dom
    page = load(index + "#category=inertia%20and%20mass")
    assert _count(page.dom)[0] == sum(1 for r in records if "inertia and mass" in r["error_categories"]) >= 2

    # as a user does it: a select changed, then a search typed (the page's own bench hook)
    page = load(index + "#bench=oscillator")
    _clean(page)
    counts = re.search(r'data-bench-counts="(\d+),(\d+)"', page.dom)
    assert counts is not None
    after_select, after_search = int(counts.group(1)), int(counts.group(2))
    assert 0 < after_search <= after_select < 18


def _page_of(site: dict[str, Any], run: int, name: str) -> tuple[Any, Path]:
    path = site["site"] / "tasks" / f"r{run}" / name
    page = load(path.as_uri())
    _clean(page, index=False)
    return page, path


def _image_ok(page_path: Path, dom: str, suffix: str) -> None:
    from matplotlib.image import imread

    src = re.search(rf'<img class="plot" alt="[^"]*" src="([^"]*{re.escape(suffix)})"', dom)
    assert src, f"no {suffix} image on {page_path.name}"
    pixels = imread(page_path.parent / src.group(1))
    assert pixels.shape[0] > 150 and pixels.shape[1] > 400 and pixels.std() > 0.02  # drawn, not blank


def test_a_failing_task_page_shows_diff_stages_and_plot(site: dict[str, Any]) -> None:
    page, path = _page_of(site, 1, "double_mass_oscillator-0.html")  # runs sorted: r0 agent, r1 fake
    assert "failed at graph_content_match" in page.dom
    assert '<table class="diff">' in page.dom and "<mark>" in page.dom
    assert "solutions differ (norm" in page.dom and "inertia and mass (1)" in page.dom
    assert "object:MassPoint#1" in page.dom
    _image_ok(path, page.dom, ".traj.png")
    assert "thinking (" in page.dom  # the answer's thinking, collapsed

    page, path = _page_of(site, 1, "cantilever_beam-1--flexible_beam_drilled_part-1.html")
    assert "failed at mass_match" in page.dom and "eigenfrequencies" in page.dom and "1 %" in page.dom
    _image_ok(path, page.dom, ".part.png")
    page, _ = _page_of(site, 1, "cantilever_beam-1.html")
    assert "a part failed" in page.dom or "not started" in page.dom

    page, _ = _page_of(site, 1, "free_fall_mass_point-0.html")
    assert "no program was extracted" in page.dom


def test_agent_page_shows_the_conversation(site: dict[str, Any], tmp_path: Path) -> None:
    page, path = _page_of(site, 0, "single_mass_oscillator-0.html")
    assert "Agent conversation" in page.dom and "tool result: simulate" in page.dom
    assert "TypeError" in page.dom and "round 2" in page.dom and "first program" in page.dom
    assert "simulate ×1" in page.dom and "{'simulate': 1}" not in page.dom  # counts, not a Python dict
    picture = screenshot(path.as_uri(), tmp_path / "agent.png", (1200, 1600))
    assert picture.stat().st_size > 20_000
