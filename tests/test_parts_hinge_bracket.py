"""Door hinge leaves (parts 63, 64) and mounting bracket (part 65): the ground truth geometry
against volumes, areas and positions derived by hand from the text's dimensions, the fit of the two
leaves, the chamfers that must matter, and one full GT run per part through the part runner."""

from __future__ import annotations

import asyncio
import itertools
import math
from typing import Any

import pytest
from netgen.occ import Cylinder, Pnt, Z
from partgeometry import build

from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

GAP, PIN, BRACKET = 63, 64, 65
PARTS = (GAP, PIN, BRACKET)
SEEDS = range(20)
HINGE_MASTERS = ("pin_radius", "knuckle_outer_radius", "knuckle_length", "leaf_thickness", "knuckle_clearance")


def model(pid: int):
    return default_registry().get(pid)


def strip_in_disc(radius: float, thickness: float) -> float:
    """Area of the half strip x >= 0, |y| <= thickness/2 inside the circle of ``radius`` about the
    origin: integral of sqrt(r^2 - y^2) over |y| <= a, a = thickness/2 (the leaf inside a knuckle)."""
    a = thickness / 2
    return a * math.sqrt(radius**2 - a**2) + radius**2 * math.asin(a / radius)


def closed_form_volume(pid: int, v: dict[str, Any]) -> float:
    if pid in (GAP, PIN):
        t, width, lk = v["leaf_thickness"], v["leaf_width"], v["knuckle_length"]
        ro, rp, rh = v["knuckle_outer_radius"], v["pin_radius"], v["hole_radius"]
        notch = ro + v["knuckle_clearance"]
        plate = width * t * 3 * lk
        knuckle = lk * (math.pi * ro**2 - strip_in_disc(ro, t))  # one knuckle beyond the plate
        holes = 2 * math.pi * rh**2 * t
        if pid == GAP:  # one notch, two knuckles, bored through
            return plate - notch * t * lk + 2 * knuckle - 2 * lk * math.pi * rp**2 - holes
        # two notches, one knuckle, the pin in both gaps (inside the knuckle it is already counted)
        return plate - 2 * notch * t * lk + knuckle + 2 * lk * math.pi * rp**2 - holes
    t, w = v["bracket_thickness"], v["bracket_width"]
    return (w * t * (v["base_length"] + v["upright_height"] - t) - 3 * chamfer_volume(v)
            - 4 * math.pi * v["hole_radius"] ** 2 * t)


def chamfer_volume(v: dict[str, Any]) -> float:
    """One 45-degree chamfer of size c along the bracket's width: a triangular prism c^2/2 * w."""
    return v["chamfer_size"] ** 2 / 2 * v["bracket_width"]


def expected_box(pid: int, v: dict[str, Any]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    if pid in (GAP, PIN):
        ro, h = v["knuckle_outer_radius"], 3 * v["knuckle_length"]
        if pid == GAP:
            return (-ro, -ro, 0.0), (v["leaf_width"], ro, h)
        return (-v["leaf_width"], -ro, 0.0), (ro, ro, h)
    w2 = v["bracket_width"] / 2
    return (0.0, -w2, 0.0), (v["base_length"], w2, v["upright_height"])


def expected_interfaces(pid: int, v: dict[str, Any]) -> dict[str, tuple[float, list[tuple[float, float, float]]]]:
    """Interface name -> (total area, centres of its faces), from the text."""
    if pid in (GAP, PIN):
        lk, t, rh = v["knuckle_length"], v["leaf_thickness"], v["hole_radius"]
        axis = (2 * 2 * math.pi * v["pin_radius"] * lk, [(0.0, 0.0, lk / 2), (0.0, 0.0, 2.5 * lk)])
        x = v["hole_x"] if pid == GAP else -v["hole_x"]
        holes = (2 * 2 * math.pi * rh * t, [(x, 0.0, lk / 2), (x, 0.0, 2.5 * lk)])
        return {"bore": axis, "door": holes} if pid == GAP else {"pin": axis, "mount": holes}
    t, rh, y = v["bracket_thickness"], v["hole_radius"], v["hole_y"]
    area = 2 * 2 * math.pi * rh * t
    return {"base_holes": (area, [(v["base_hole_x"], s * y, t / 2) for s in (-1, 1)]),
            "upright_holes": (area, [(t / 2, s * y, v["upright_hole_z"]) for s in (-1, 1)])}


def xyz(p) -> tuple[float, float, float]:
    return (p.x, p.y, p.z)


def ordered(points):
    """Points (or (point, ...) tuples) in a stable order: float noise in x must not decide."""
    def key(item):
        point = item[0] if isinstance(item[0], tuple) else item
        return tuple(round(c, 6) for c in point)
    return sorted(points, key=key)


@pytest.mark.parametrize("pid", PARTS)
def test_gt_geometry_matches_the_closed_form(pid: int) -> None:
    m = model(pid)
    for seed in SEEDS:
        v = m.sample_params(seed)
        shape = build(pid, v)
        assert shape.mass == pytest.approx(closed_form_volume(pid, v), rel=1e-6), (seed, v)
        low, high = shape.bounding_box
        box = expected_box(pid, v)
        assert xyz(low) == pytest.approx(box[0], abs=1e-6) and xyz(high) == pytest.approx(box[1], abs=1e-6), seed
        names = [f.name for f in shape.faces]
        for name, (area, centres) in expected_interfaces(pid, v).items():
            faces = list(shape.faces[name])
            assert len(faces) == len(centres) == names.count(name), (seed, name, names)
            assert sum(f.mass for f in faces) == pytest.approx(area, rel=1e-6), (seed, name)
            found = ordered(xyz(f.center) for f in faces)
            for got, want in zip(found, ordered(centres), strict=True):
                assert got == pytest.approx(want, abs=1e-7), (seed, name)
        assert set(m.interfaces) <= set(names)


def test_bracket_chamfers_sit_on_the_three_outer_edges_and_matter() -> None:
    m = model(BRACKET)
    for seed in SEEDS:
        v = m.sample_params(seed)
        shape = build(BRACKET, v)
        c, w, length, height = v["chamfer_size"], v["bracket_width"], v["base_length"], v["upright_height"]
        for centre in ((c / 2, 0, c / 2), (length - c / 2, 0, c / 2), (c / 2, 0, height - c / 2)):
            face = shape.faces.Nearest(Pnt(*centre))
            assert face.mass == pytest.approx(math.sqrt(2) * c * w, rel=1e-9), seed
            assert xyz(face.center) == pytest.approx(centre, abs=1e-9), seed
    # leaving out any one chamfer must be visible to the 1 % mass and mesh metrics: >= 2 % of the
    # volume, for every combination of the ranges (monotonic in each parameter: corners suffice)
    for v in [*(m.sample_params(seed) for seed in SEEDS), *corners(BRACKET)]:
        assert chamfer_volume(v) >= 0.02 * closed_form_volume(BRACKET, v), v


def corners(pid: int):
    """Every corner of the parameter ranges, with the derived values."""
    m = model(pid)
    for combo in itertools.product(*((p.low, p.high) for p in m.params)):
        v = {p.name: x for p, x in zip(m.params, combo, strict=True)}
        v.update(m.derive(dict(v)))
        yield v


def margins(pid: int, v: dict[str, Any]) -> dict[str, float]:
    """Walls and distances (in m) that must stay positive for the text to describe a sound part."""
    rh = v["hole_radius"]
    if pid in (GAP, PIN):
        ro, t, x = v["knuckle_outer_radius"], v["leaf_thickness"], v["hole_x"]
        return {"knuckle wall >= 4 mm": ro - v["pin_radius"] - 0.004 + 1e-12,
                "plate narrower than the knuckle": ro - t / 2 - 0.005,
                "hole clear of the notch": x - rh - v["notch_depth"] - 0.005,
                "hole clear of the outer edge": v["leaf_width"] - x - rh - 0.005,
                "hole clear of the plate ends": v["knuckle_length"] / 2 - rh - 0.005,
                "clearance": v["knuckle_clearance"] - 0.0005 + 1e-12}
    t, c = v["bracket_thickness"], v["chamfer_size"]
    bx, uz, y = v["base_hole_x"], v["upright_hole_z"], v["hole_y"]
    return {"free end face left by the chamfer": t - c - 0.001 + 1e-12,
            "base hole clear of the upright": bx - rh - t - 0.01,
            "base hole clear of the end chamfer": v["base_length"] - c - bx - rh - 0.004,
            "upright hole clear of the base": uz - rh - t - 0.01,
            "upright hole clear of the top chamfer": v["upright_height"] - c - uz - rh - 0.004,
            "hole clear of the side": v["bracket_width"] / 2 - y - rh - 0.005,
            "holes apart": 2 * y - 2 * rh - 0.01}


@pytest.mark.parametrize("pid", PARTS)
def test_every_range_combination_gives_a_sound_part(pid: int) -> None:
    cases = list(corners(pid))
    for v in cases:
        bad = {k: x for k, x in margins(pid, v).items() if x < 0}
        assert not bad, (bad, v)
    for v in cases[:: max(1, len(cases) // 12)] + cases[-1:]:  # the closed form holds there too
        assert build(pid, v).mass == pytest.approx(closed_form_volume(pid, v), rel=1e-6), v


def test_the_two_hinge_leaves_fit_in_the_common_frame() -> None:
    gap, pin = model(GAP), model(PIN)
    for seed in SEEDS:
        master = {k: v for k, v in gap.sample_params(seed).items() if k in HINGE_MASTERS}
        vg, vp = gap.sample_params(seed, master), pin.sample_params(seed + 100, master)
        a, b = build(GAP, vg), build(PIN, vp)
        assert (a * b).mass <= 1e-9 * a.mass, seed  # they touch, never overlap
        # the pin-side leaf's 'pin' is exactly where the gap-side leaf's 'bore' is
        bores = ordered((xyz(f.center), f.mass) for f in a.faces["bore"])
        pins = ordered((xyz(f.center), f.mass) for f in b.faces["pin"])
        for (cb, ab), (cp, ap) in zip(bores, pins, strict=True):
            assert cb == pytest.approx(cp, abs=1e-9) and ab == pytest.approx(ap, rel=1e-9), seed
        # the clearance is real: the gap-side leaf stays clear of the middle knuckle grown by less than it
        lk = vp["knuckle_length"]
        grown = Cylinder(Pnt(0, 0, lk), Z, r=vp["knuckle_outer_radius"] + 0.9 * vp["knuckle_clearance"], h=lk)
        assert (a * grown).mass <= 1e-9 * a.mass, seed


@pytest.mark.parametrize("pid", PARTS)
def test_main_dimensions_change_the_mass_by_more_than_the_tolerance(pid: int) -> None:
    m = model(pid)
    mains = (("leaf_thickness", "leaf_width", "knuckle_length", "knuckle_outer_radius") if pid != BRACKET
             else ("bracket_thickness", "bracket_width", "base_length", "upright_height"))
    base = m.sample_params(0)
    volume = build(pid, base).mass
    for name in mains:
        v = {k: x for k, x in base.items()}
        v[name] *= 1.05
        v.update(m.derive(dict(v)))
        assert abs(build(pid, v).mass / volume - 1) > 0.01, name


@pytest.mark.parametrize("pid", PARTS)
def test_mesh_size_resolves_the_thin_walls(pid: int) -> None:
    m = model(pid)
    for seed in SEEDS:
        v = m.sample_params(seed)
        maxh = m.maxh(v)
        thinnest = v["bracket_thickness"] if pid == BRACKET else v["leaf_thickness"]
        assert maxh <= 0.5 * thinnest * 1.03  # two elements through the plate (maxh has two digits)
        if pid != BRACKET:
            assert maxh <= v["knuckle_outer_radius"] - v["pin_radius"]  # the knuckle wall


async def test_gt_runs_mesh_and_reduce() -> None:
    limits = ExecutionLimits(mode="part", timeout_s=120)
    instances = [model(pid).instance(0) for pid in PARTS]
    runs = await asyncio.gather(*(execute(i.reference_program, "", limits) for i in instances))
    for pid, inst, run in zip(PARTS, instances, runs, strict=True):
        assert run.error is None and run.stage == "reduced", (pid, run.error)
        part = run.part
        assert part["interfaces"] == list(model(pid).interfaces)
        expected = model(pid).material.density * closed_form_volume(pid, inst.params)
        assert part["mass"] == pytest.approx(expected, rel=0.02), pid
        assert len(part["eigenfrequencies"]) >= 6 and min(part["eigenfrequencies"]) > 0, pid
        assert part["nodes"] <= 6000, pid


def test_hinge_masters_from_the_assembly_are_used() -> None:
    master = {"pin_radius": 0.00456, "knuckle_outer_radius": 0.0101, "knuckle_length": 0.0234,
              "leaf_thickness": 0.00512, "knuckle_clearance": 0.00077, "bracket_width": 0.123}
    for pid in (GAP, PIN):
        inst = model(pid).instance(3, master=master)
        for name in HINGE_MASTERS:
            assert inst.params[name] == master[name]
            assert f"{name} = {master[name]}" in inst.description
        assert "bracket_width" not in inst.params  # another part's master is not ours
        assert inst.params["notch_depth"] == pytest.approx(0.0101 + 0.00077, abs=1e-12)
        assert f"hinge_length = 3 * knuckle_length = {3 * 0.0234:.4f} m" in inst.description
        assert inst.part.maxh == 0.0026  # leaf_thickness / 2 to two digits
        assert "{" not in inst.description and "}" not in inst.description
    own = model(GAP).instance(3)
    assert own.params["pin_radius"] != master["pin_radius"]
    bracket = model(BRACKET).instance(3, master=master)  # no masters: nothing is taken over
    assert bracket.params == model(BRACKET).instance(3).params


@pytest.mark.parametrize("pid", PARTS)
def test_text_names_every_interface_and_value(pid: int) -> None:
    for seed in range(5):
        inst = model(pid).instance(seed)
        for name in model(pid).interfaces:
            assert f"'{name}'" in inst.description
        for name, value in inst.params.items():  # the text states every value the GT uses
            assert str(value) in inst.description, (seed, name)
            assert f"{name} = {value!r}" in inst.reference_program
