"""Flexible slider-crank parts (67-69 simple, 70-72 advanced): the ground truth geometry against
volumes, areas, positions and bounding boxes derived by hand from the text's dimensions, the
validity of every range combination, the features that must matter, the masters that tie crank,
rod and slider together, and one full GT run per part through the part runner."""

from __future__ import annotations

import asyncio
import itertools
import math
from typing import Any

import pytest
from partgeometry import build
from scipy.integrate import quad

from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

CRANK, ROD, SLIDER, CRANK_ADV, ROD_ADV, SLIDER_ADV = 67, 68, 69, 70, 71, 72
PARTS = (CRANK, ROD, SLIDER, CRANK_ADV, ROD_ADV, SLIDER_ADV)
SEEDS = range(20)
MASTERS = ("crank_length", "rod_length", "pin_radius", "thickness")


def model(pid: int):
    return default_registry().get(pid)


def disc_strip(radius: float, a: float) -> float:
    """Area of the strip |y| <= a inside the half disc x >= 0 of ``radius``: int_{-a}^{a} sqrt(R^2 - y^2) dy."""
    return a * math.sqrt(radius**2 - a**2) + radius**2 * math.asin(a / radius)


def bar_between_discs(length: float, width: float, ra: float, rb: float) -> float:
    """Cross-section integral of a bar |y| <= width/2 from the disc of ``ra`` about x = 0 to the disc of
    ``rb`` about x = length: the area of the bar outside both discs (times a thickness gives the volume)."""
    a = width / 2
    return 2 * a * length - disc_strip(ra, a) - disc_strip(rb, a)


def ring_chamfer(radius: float, c: float) -> float:
    """45-degree chamfer c on the outer circular edge of a cylinder of ``radius``: the triangle c^2/2
    revolved about the axis at its centroid radius R - c/3 (Pappus)."""
    return math.pi * c**2 * (radius - c / 3)


def closed_form_volume(pid: int, v: dict[str, Any]) -> float:
    r, t = v["pin_radius"], v.get("thickness")
    if pid == CRANK:
        w, length = v["crank_width"], v["crank_length"]
        return (length + w) * w * t - 2 * math.pi * r**2 * t
    if pid == ROD:
        big = v["eye_radius"]
        return (2 * math.pi * big**2 + bar_between_discs(v["rod_length"], v["shank_width"], big, big)
                - 2 * math.pi * r**2) * t
    if pid in (SLIDER, SLIDER_ADV):
        length, height, width = v["slider_length"], v["slider_height"], v["slider_width"]
        volume = length * height * width - math.pi * r**2 * width
        if pid == SLIDER_ADV:
            volume -= length * (v["groove_width"] * v["groove_depth"] + 4 * v["chamfer"] ** 2 / 2)
        return volume
    if pid == CRANK_ADV:
        ra, rb, c = v["hub_radius"], v["boss_radius"], v["chamfer"]
        bosses = math.pi * (ra**2 + rb**2 - 2 * r**2) * t - 2 * (ring_chamfer(ra, c) + ring_chamfer(rb, c))
        return bosses + v["web_thickness"] * bar_between_discs(v["crank_length"], v["web_width"], ra, rb)
    assert pid == ROD_ADV
    ra, rb, length = v["eye_a_radius"], v["eye_b_radius"], v["rod_length"]
    pockets = 2 * v["pocket_width"] * v["pocket_depth"] * (length - ra - rb)
    return (math.pi * (ra**2 + rb**2 - 2 * r**2) + bar_between_discs(length, v["shank_width"], ra, rb)) * t - pockets


def expected_box(pid: int, v: dict[str, Any]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    if pid in (SLIDER, SLIDER_ADV):
        half = (v["slider_length"] / 2, v["slider_height"] / 2, v["slider_width"] / 2)
        return tuple(-h for h in half), half
    t2 = v["thickness"] / 2
    if pid == CRANK:
        w2 = v["crank_width"] / 2
        return (-w2, -w2, -t2), (v["crank_length"] + w2, w2, t2)
    if pid == ROD:
        big = v["eye_radius"]
        return (-big, -big, -t2), (v["rod_length"] + big, big, t2)
    ra, rb, length = ((v["hub_radius"], v["boss_radius"], v["crank_length"]) if pid == CRANK_ADV
                      else (v["eye_a_radius"], v["eye_b_radius"], v["rod_length"]))
    return (-ra, -ra, -t2), (length + rb, ra, t2)


def expected_interfaces(pid: int, v: dict[str, Any]) -> dict[str, tuple[float, tuple[float, float, float], int]]:
    """Interface name -> (total area, area-weighted centre, number of faces), from the text."""
    r = v["pin_radius"]
    if pid in (SLIDER, SLIDER_ADV):
        length, height, width = v["slider_length"], v["slider_height"], v["slider_width"]
        bore = (2 * math.pi * r * width, (0.0, 0.0, 0.0), 1)
        if pid == SLIDER:
            return {"bore": bore, "guide": (length * width, (0.0, -height / 2, 0.0), 1)}
        gw, gd = v["groove_width"], v["groove_depth"]
        floor, flank = length * gw, length * gd  # the floor and each of the two side faces
        y = (floor * (-height / 2 + gd) + 2 * flank * (-height / 2 + gd / 2)) / (floor + 2 * flank)
        return {"bore": bore, "guide": (floor + 2 * flank, (0.0, y, 0.0), 3)}
    length = v["crank_length"] if pid in (CRANK, CRANK_ADV) else v["rod_length"]
    area = 2 * math.pi * r * v["thickness"]
    return {"hole_a": (area, (0.0, 0.0, 0.0), 1), "hole_b": (area, (length, 0.0, 0.0), 1)}


def xyz(p) -> tuple[float, float, float]:
    return (p.x, p.y, p.z)


def check_geometry(pid: int, v: dict[str, Any], label: Any) -> None:
    shape = build(pid, v)
    assert len(shape.solids) == 1, label
    assert shape.mass == pytest.approx(closed_form_volume(pid, v), rel=1e-6), (label, v)
    low, high = shape.bounding_box
    box = expected_box(pid, v)
    assert xyz(low) == pytest.approx(box[0], abs=1e-6) and xyz(high) == pytest.approx(box[1], abs=1e-6), label
    names = [f.name for f in shape.faces]
    for name, (area, centre, count) in expected_interfaces(pid, v).items():
        faces = list(shape.faces[name])
        assert len(faces) == count == names.count(name), (label, name, names)
        total = sum(f.mass for f in faces)
        assert total == pytest.approx(area, rel=1e-6), (label, name)
        weighted = [sum(f.mass * c for f, c in zip(faces, axis, strict=True)) / total
                    for axis in zip(*(xyz(f.center) for f in faces), strict=True)]
        assert weighted == pytest.approx(centre, abs=1e-7), (label, name)
    assert set(names) - {None} - set(model(pid).interfaces) <= {"chamfer"}, label  # no stray interface names


@pytest.mark.parametrize("pid", PARTS)
def test_gt_geometry_matches_the_closed_form(pid: int) -> None:
    m = model(pid)
    for seed in SEEDS:
        check_geometry(pid, m.sample_params(seed), seed)


def corners(pid: int):
    """Every combination of the ends of the parameter ranges (masters included), derived values added."""
    m = model(pid)
    for ends in itertools.product(*((p.low, p.high) for p in m.params)):
        v = {p.name: x for p, x in zip(m.params, ends, strict=True)}
        if m.derive is not None:
            v.update(m.derive(dict(v)))
        yield v


def margins(pid: int, v: dict[str, Any]) -> dict[str, float]:
    """Wall thicknesses and clearances that must stay positive (in m) for the text to be buildable."""
    r = v["pin_radius"]
    if pid == CRANK:
        return {"ligament": v["crank_width"] / 2 - r - 0.007, "holes apart": v["crank_length"] - 2 * r - 0.03}
    if pid == ROD:
        big, half = v["eye_radius"], v["shank_width"] / 2
        return {"eye wall": big - r - 0.005, "shank narrower than eye": big - half - 0.004,
                "eyes apart": v["rod_length"] - 2 * big - 0.1}
    if pid == SLIDER:
        return {"wall above/below bore": v["slider_height"] / 2 - r - 0.0095,
                "wall beside bore": v["slider_length"] / 2 - r - 0.02}
    if pid == CRANK_ADV:
        ra, rb, c = v["hub_radius"], v["boss_radius"], v["chamfer"]
        return {"boss wall": rb - r - 0.005, "hub wall": ra - r - 0.009,
                "exposed web": v["crank_length"] - ra - rb - 0.012,
                "web narrower than boss": rb - v["web_width"] / 2 - 0.002,
                "chamfer above web": (v["thickness"] - v["web_thickness"]) / 2 - c - 0.0007,
                "chamfer beside hole": rb - c - r - 0.0015}
    if pid == ROD_ADV:
        ra, rb = v["eye_a_radius"], v["eye_b_radius"]
        return {"eye wall": rb - r - 0.004, "shank narrower than eye": rb - v["shank_width"] / 2 - 0.002,
                "flange": (v["shank_width"] - v["pocket_width"]) / 2 - 0.003,
                "web": v["thickness"] - 2 * v["pocket_depth"] - 0.4 * v["thickness"] + 1e-12,
                "pocket length": v["rod_length"] - ra - rb - 0.12}
    assert pid == SLIDER_ADV
    h2, w = v["slider_height"] / 2, v["slider_width"]
    return {"groove below bore": h2 - v["groove_depth"] - r - 0.004,
            "flat beside groove": (w - v["groove_width"]) / 2 - v["chamfer"] - 0.0035,
            "chamfer above bore": h2 - v["chamfer"] - r - 0.005}


@pytest.mark.parametrize("pid", PARTS)
def test_every_range_combination_gives_valid_geometry(pid: int) -> None:
    cases = list(corners(pid))
    for v in cases:
        bad = {k: x for k, x in margins(pid, v).items() if x < -1e-12}
        assert not bad, (bad, v)
    # the closed form holds at the extreme corners too (all low, all high, and a spread of mixed ones)
    for k, v in enumerate([*cases[:: max(1, len(cases) // 6)], cases[-1]]):
        check_geometry(pid, v, f"corner {k}")


def feature_volumes(pid: int, v: dict[str, Any]) -> dict[str, float]:
    """Volume each feature of the text removes (or adds): leaving one out changes the mass by this much."""
    r = v["pin_radius"]
    t = v.get("thickness")
    if pid in (CRANK, ROD, CRANK_ADV, ROD_ADV):
        out = {"holes": 2 * math.pi * r**2 * t}
        if pid == CRANK_ADV:
            ra, rb, c = v["hub_radius"], v["boss_radius"], v["chamfer"]
            out["chamfers"] = 2 * (ring_chamfer(ra, c) + ring_chamfer(rb, c))
            out["thin web"] = (t - v["web_thickness"]) * bar_between_discs(v["crank_length"], v["web_width"], ra, rb)
        if pid == ROD_ADV:
            out["pockets"] = 2 * v["pocket_width"] * v["pocket_depth"] * (v["rod_length"] - v["eye_a_radius"]
                                                                          - v["eye_b_radius"])
        return out
    out = {"bore": math.pi * r**2 * v["slider_width"]}
    if pid == SLIDER_ADV:
        out["groove"] = v["slider_length"] * v["groove_width"] * v["groove_depth"]
        out["chamfers"] = 2 * v["slider_length"] * v["chamfer"] ** 2
    return out


@pytest.mark.parametrize("pid", PARTS)
def test_features_matter_to_the_one_percent_metrics(pid: int) -> None:
    m = model(pid)
    for seed in SEEDS:
        v = m.sample_params(seed)
        volume = closed_form_volume(pid, v)
        for feature, dv in feature_volumes(pid, v).items():
            assert dv >= 0.02 * volume, (seed, feature, dv / volume)
    for v in corners(pid):  # the features stay visible (> the 1 % tolerances) over the whole ranges
        volume = closed_form_volume(pid, v)
        for feature, dv in feature_volumes(pid, v).items():
            assert dv >= 0.012 * volume, (feature, dv / volume, v)


MAIN_DIMENSIONS = {
    CRANK: ("crank_length", "crank_width", "thickness"),
    ROD: ("rod_length", "eye_radius", "shank_width", "thickness"),
    SLIDER: ("slider_length", "slider_height", "slider_width"),
    CRANK_ADV: ("crank_length", "hub_radius", "boss_radius", "thickness"),
    ROD_ADV: ("rod_length", "eye_a_radius", "shank_width", "thickness"),
    SLIDER_ADV: ("slider_length", "slider_height", "slider_width"),
}


@pytest.mark.parametrize("pid", PARTS)
def test_main_dimensions_change_the_mass_by_more_than_the_tolerance(pid: int) -> None:
    m = model(pid)
    base = m.sample_params(0)
    volume = build(pid, base).mass
    for name in MAIN_DIMENSIONS[pid]:
        v = dict(base)
        v[name] *= 1.05
        if m.derive is not None:
            v.update(m.derive(dict(v)))
        changed = build(pid, v).mass
        assert changed == pytest.approx(closed_form_volume(pid, v), rel=1e-6), name
        assert abs(changed / volume - 1) > 0.01, name


def thinnest_wall(pid: int, v: dict[str, Any]) -> float:
    if pid in (CRANK, ROD):
        return v["thickness"]
    if pid == SLIDER:
        return min(v["slider_height"], v["slider_width"]) / 2 - v["pin_radius"]
    if pid == CRANK_ADV:
        return v["web_thickness"]
    if pid == ROD_ADV:
        return v["thickness"] - 2 * v["pocket_depth"]
    return min(v["groove_depth"], v["slider_height"] / 2 - v["groove_depth"] - v["pin_radius"])


@pytest.mark.parametrize("pid", PARTS)
def test_mesh_size_resolves_the_thinnest_wall(pid: int) -> None:
    m = model(pid)
    for seed in SEEDS:
        v = m.sample_params(seed)
        maxh = m.maxh(v)
        assert maxh <= thinnest_wall(pid, v) / 1.5 * 1.03, seed  # ~2 elements (maxh has two digits)
        if pid in (CRANK, ROD):
            assert maxh <= 0.5 * v["thickness"] * 1.03, seed


async def test_gt_runs_mesh_and_reduce() -> None:
    limits = ExecutionLimits(mode="part", timeout_s=180)
    instances = [model(pid).instance(0) for pid in PARTS]
    runs = await asyncio.gather(*(execute(i.reference_program, "", limits) for i in instances))
    for pid, inst, run in zip(PARTS, instances, runs, strict=True):
        assert run.error is None and run.stage == "reduced", (pid, run.error)
        part = run.part
        assert part["interfaces"] == list(model(pid).interfaces), pid
        expected = model(pid).material.density * closed_form_volume(pid, inst.params)
        assert part["mass"] == pytest.approx(expected, rel=0.02), pid
        frequencies = part["eigenfrequencies"]
        assert len(frequencies) >= 6 and min(frequencies) > 0, pid
        assert part["nodes"] <= 6000, pid


def test_masters_from_the_assembly_are_used() -> None:
    master = {"crank_length": 0.0654, "rod_length": 0.211, "pin_radius": 0.00612, "thickness": 0.0133,
              "unrelated": 1.0}
    for pid in PARTS:
        m = model(pid)
        inst = m.instance(3, master=master)
        own = m.instance(3)
        assert set(m.master) <= set(MASTERS) and "pin_radius" in m.master
        for name in MASTERS:
            if name in m.master:
                assert inst.params[name] == master[name] != own.params[name], (pid, name)
                assert f"{name} = {master[name]} m" in inst.description, (pid, name)
                assert f"{name} = {master[name]!r}" in inst.reference_program, (pid, name)
            else:
                assert name not in inst.params, (pid, name)  # another part's master is not ours
        assert "unrelated" not in inst.params
        check_geometry(pid, inst.params, f"master {pid}")
    # derived values follow the master thickness
    crank = model(CRANK_ADV).instance(3, master=master)
    assert crank.params["web_thickness"] == pytest.approx(crank.params["web_ratio"] * 0.0133, rel=5e-3)
    assert f"web_thickness = {crank.params['web_thickness']} m" in crank.description
    rod = model(ROD_ADV).instance(3, master=master)
    assert rod.params["pocket_depth"] == pytest.approx(rod.params["pocket_ratio"] * 0.0133, rel=5e-3)
    assert f"pocket_depth = {rod.params['pocket_depth']} m" in rod.description


def test_the_mechanism_closes_with_shared_masters() -> None:
    """One assembly draw: the crank's pin hole, the rod's two holes and the slider's bore have the same
    radius, crank and rod the same thickness, and the joint spacings are the master lengths."""
    for seed in range(5):
        master = {k: x for k, x in model(CRANK).sample_params(seed).items() if k in MASTERS}
        master["rod_length"] = model(ROD).sample_params(seed)["rod_length"]
        for crank, rod, slider in ((CRANK, ROD, SLIDER), (CRANK_ADV, ROD_ADV, SLIDER_ADV)):
            vc, vr, vs = (model(p).sample_params(seed, master) for p in (crank, rod, slider))
            sc, sr, ss = build(crank, vc), build(rod, vr), build(slider, vs)
            radius = {f"{p}:{n}": f.mass / (2 * math.pi * height) for p, s, height in
                      ((crank, sc, vc["thickness"]), (rod, sr, vr["thickness"]), (slider, ss, vs["slider_width"]))
                      for n in ("hole_a", "hole_b", "bore") for f in s.faces[n]}
            assert len(radius) == 5 and max(radius.values()) - min(radius.values()) < 1e-9, radius
            assert xyz(sc.faces["hole_b"][0].center)[0] == pytest.approx(master["crank_length"], abs=1e-9)
            assert xyz(sr.faces["hole_b"][0].center)[0] == pytest.approx(master["rod_length"], abs=1e-9)
            assert vc["thickness"] == vr["thickness"] == master["thickness"]


@pytest.mark.parametrize("pid", PARTS)
def test_text_names_every_interface_and_value(pid: int) -> None:
    m = model(pid)
    inst = m.instance(5)
    for name in m.interfaces:
        assert f"'{name}'" in inst.description
    used = [name for name in inst.params if name in m.geometry_code]
    for name in used:  # every value the geometry uses is stated in the text with its name
        assert f"{name} = {inst.params[name]} m" in inst.description, name
    for name, value in inst.params.items():
        assert f"{name} = {value!r}" in inst.reference_program


def test_corner_integral_helper_is_exact() -> None:
    """disc_strip against numerical quadrature (it carries every closed form of eyes and bosses)."""
    for radius, a in ((0.02, 0.01), (0.013, 0.011), (0.019, 0.0075)):
        numeric = quad(lambda y, r=radius: math.sqrt(r * r - y * y), -a, a, epsabs=1e-15)[0]
        assert disc_strip(radius, a) == pytest.approx(numeric, rel=1e-10)
