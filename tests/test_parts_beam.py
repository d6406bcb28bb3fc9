"""Level 3a parts of the beam family (54-57) and the flexible table (58): the ground truth's exact
solid against volumes, bounding boxes and interface faces worked out by hand from the
dimensions, and one meshed and reduced ground truth per part.

The geometry checks build the solid in this process (no meshing: a process that meshes must not
fork workers later); the FEM checks run the reference program through the part executor.
"""

from __future__ import annotations

import asyncio
import itertools
import math
import textwrap
from typing import Any

import pytest

from meceng.tasks.part_base import PartModel
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

REGISTRY = default_registry()
BEAMS = (54, 55, 56, 57)
TABLE = 58
IDS = (*BEAMS, TABLE)
SEEDS = range(20)
BEAM_MASTER = {"beam_length": 0.777, "beam_width": 0.0444, "beam_height": 0.0222}
TABLE_MASTER = {"table_length": 0.777, "table_width": 0.555, "plate_thickness": 0.0222, "leg_height": 0.611,
                "leg_size": 0.0555, "leg_inset": 0.0333}


def model(task_id: int) -> PartModel:
    m = REGISTRY.get(task_id)
    assert isinstance(m, PartModel)
    return m


def build(m: PartModel, values: dict[str, Any]) -> Any:
    """The ground truth's solid for ``values``, built from the geometry code alone."""
    namespace: dict[str, Any] = {}
    exec("from netgen.occ import *", namespace)
    namespace.update(values)
    exec(textwrap.dedent(m.geometry_code), namespace)
    return namespace["shape"]


# ---------------------------------------------------------------- closed forms, worked out by hand


def beam_section(task_id: int, v: dict[str, Any]) -> float:
    """Area of the end faces (the beam's cross section at its ends)."""
    b, h = v["beam_width"], v["beam_height"]
    if task_id == 55:  # each rounded corner removes (1 - pi/4) r^2
        return b * h - (4 - math.pi) * v["fillet_radius"] ** 2
    if task_id == 56:  # rectangular ring
        t = v["wall_thickness"]
        return b * h - (b - 2 * t) * (h - 2 * t)
    return b * h  # 54; 57: the holes stay away from the end faces


def volume(task_id: int, v: dict[str, Any]) -> float:
    if task_id == TABLE:
        return (v["table_length"] * v["table_width"] * v["plate_thickness"]
                + 4 * v["leg_size"] ** 2 * v["leg_height"] + v["pad_size"] ** 2 * v["pad_height"])
    full = beam_section(task_id, v) * v["beam_length"]
    if task_id == 57:  # n cylinders through the height
        full -= v["n_holes"] * math.pi * v["hole_diameter"] ** 2 / 4 * v["beam_height"]
    return full


def surface_area(task_id: int, v: dict[str, Any]) -> float:
    """Total surface area: places the features (a hole drilled along y or a pad sunk into the
    plate changes it even where the volume stays)."""
    if task_id == TABLE:  # a leg's top and the pad's bottom replace plate surface: only their sides add
        L, W, t = v["table_length"], v["table_width"], v["plate_thickness"]
        return 2 * L * W + 2 * t * (L + W) + 16 * v["leg_size"] * v["leg_height"] + 4 * v["pad_size"] * v["pad_height"]
    L, b, h = v["beam_length"], v["beam_width"], v["beam_height"]
    ends = 2 * beam_section(task_id, v)
    if task_id == 55:  # flat strips plus four quarter cylinders
        r = v["fillet_radius"]
        return ends + L * (2 * (b - 2 * r) + 2 * (h - 2 * r) + 2 * math.pi * r)
    if task_id == 56:  # outer and inner mantle
        t = v["wall_thickness"]
        return ends + 2 * L * (b + h) + 2 * L * (b - 2 * t + h - 2 * t)
    if task_id == 57:  # each hole: two discs less on top and bottom, its wall more
        n, d = v["n_holes"], v["hole_diameter"]
        return ends + 2 * L * (b + h) + n * (math.pi * d * h - 2 * math.pi * d**2 / 4)
    return ends + 2 * L * (b + h)


def feature_volume(task_id: int, v: dict[str, Any]) -> float:
    """Volume a careless answer loses or gains by leaving the part's feature out (the plain beam
    has none: its whole volume)."""
    L, b, h = (v.get(k, 0.0) for k in ("beam_length", "beam_width", "beam_height"))
    if task_id == 55:
        return (4 - math.pi) * v["fillet_radius"] ** 2 * L
    if task_id == 56:
        return (b - 2 * v["wall_thickness"]) * (h - 2 * v["wall_thickness"]) * L
    if task_id == 57:
        return v["n_holes"] * math.pi * v["hole_diameter"] ** 2 / 4 * h
    if task_id == TABLE:
        return 4 * v["leg_size"] ** 2 * v["leg_height"]
    return L * b * h


def bounds(task_id: int, v: dict[str, Any]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    if task_id == TABLE:
        lo = (-v["table_length"] / 2, -v["table_width"] / 2, -v["plate_thickness"] / 2 - v["leg_height"])
        hi = (v["table_length"] / 2, v["table_width"] / 2, v["plate_thickness"] / 2 + v["pad_height"])
        return lo, hi
    return ((0.0, -v["beam_width"] / 2, -v["beam_height"] / 2),
            (v["beam_length"], v["beam_width"] / 2, v["beam_height"] / 2))


def interfaces(task_id: int, v: dict[str, Any]) -> dict[str, tuple[float, tuple[float, float, float]]]:
    """Interface name -> (area, centre)."""
    if task_id == TABLE:
        a, t, H = v["leg_size"], v["plate_thickness"], v["leg_height"]
        x = v["table_length"] / 2 - v["leg_inset"] - a / 2  # outer leg faces leg_inset inside the plate edges
        y = v["table_width"] / 2 - v["leg_inset"] - a / 2
        feet = {f"foot{i + 1}": (a * a, (sx * x, sy * y, -t / 2 - H))
                for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1)])}
        return {**feet, "load": (v["pad_size"] ** 2, (0.0, 0.0, t / 2 + v["pad_height"]))}
    area = beam_section(task_id, v)
    return {"left": (area, (0.0, 0.0, 0.0)), "right": (area, (v["beam_length"], 0.0, 0.0))}


def _xyz(p: Any) -> tuple[float, float, float]:
    return (p.x, p.y, p.z)


def named_faces(shape: Any, name: str) -> list[Any]:
    return [f for f in shape.faces if f.name == name]


def check_solid(task_id: int, v: dict[str, Any]) -> Any:
    m = model(task_id)
    shape = build(m, v)
    assert len(shape.solids) == 1
    assert shape.mass == pytest.approx(volume(task_id, v), rel=1e-6)
    assert sum(f.mass for f in shape.faces) == pytest.approx(surface_area(task_id, v), rel=1e-6)
    if task_id == 57:  # each hole wall is centred on its stated axis, half way up
        d, h, L, n = v["hole_diameter"], v["beam_height"], v["beam_length"], v["n_holes"]
        for i, x in enumerate(v["hole_x"]):
            assert x == pytest.approx((i + 0.5) * L / n, abs=5e-5)  # the text's rule, rounded
            walls = [f for f in shape.faces if abs(f.center.x - x) < 1e-7 and abs(f.center.y) < 1e-7
                     and abs(f.center.z) < 1e-7]
            assert sum(f.mass for f in walls) == pytest.approx(math.pi * d * h, rel=1e-6)
    (lo, hi), (elo, ehi) = shape.bounding_box, bounds(task_id, v)
    assert tuple(lo) == pytest.approx(elo, abs=1e-6) and tuple(hi) == pytest.approx(ehi, abs=1e-6)
    for name, (area, centre) in interfaces(task_id, v).items():
        faces = named_faces(shape, name)
        assert faces, f"interface {name!r} is on no face"
        assert sum(f.mass for f in faces) == pytest.approx(area, rel=1e-6), name
        for f in faces:  # every face of an end ring / foot lies in the interface's plane
            c = f.center
            axis = 0 if task_id in BEAMS else 2
            assert (c.x, c.y, c.z)[axis] == pytest.approx(centre[axis], abs=1e-7), name
        if len(faces) == 1:
            c = faces[0].center
            assert (c.x, c.y, c.z) == pytest.approx(centre, abs=1e-7), name
    assert {f.name for f in shape.faces} >= set(m.interfaces)
    return shape


# ---------------------------------------------------------------- 1. exact geometry, seeds 0..19


@pytest.mark.parametrize("task_id", IDS)
def test_ground_truth_solid_matches_closed_forms(task_id: int) -> None:
    m = model(task_id)
    for seed in SEEDS:
        v = m.sample_params(seed)
        check_solid(task_id, v)
        # the part's feature is visible to the mass metric (1 %) with margin
        assert feature_volume(task_id, v) / volume(task_id, v) >= 0.02, (seed, v)


def _corners(m: PartModel, tied: tuple[str, ...] = ()) -> list[dict[str, Any]]:
    """Every combination of the range ends of the part's parameters (derived values recomputed);
    the ``tied`` parameters take their low or their high end together."""
    free = [p for p in m.params if p.name not in tied]
    out = []
    for ends in itertools.product(*([0, 1] for _ in range(len(free) + bool(tied)))):
        end = dict(zip([p.name for p in free], ends, strict=False))
        v: dict[str, Any] = {}
        for p in m.params:
            value = (p.low, p.high)[end.get(p.name, ends[-1])]
            v[p.name] = int(value) if p.integer else value
        if m.derive is not None:
            v.update(m.derive(dict(v)))
        out.append(v)
    return out


@pytest.mark.parametrize("task_id", IDS)
def test_every_combination_of_range_ends_is_a_valid_part(task_id: int) -> None:
    """The ranges keep the geometry valid for any master values an assembly may give."""
    m = model(task_id)
    # the table's heights do not decide where its parts sit: varied together, 64 solids, not 256
    for v in _corners(m, tied=("plate_thickness", "leg_height", "pad_height") if task_id == TABLE else ()):
        check_solid(task_id, v)
        assert feature_volume(task_id, v) / volume(task_id, v) >= 0.02, v
        if task_id == 55:  # a flat strip stays between the fillets on the narrow sides
            assert v["fillet_radius"] < 0.49 * v["beam_height"]
        if task_id == 57:  # holes inside the width, apart from each other and from the end faces
            d, xs = v["hole_diameter"], v["hole_x"]
            assert d <= 0.6 * v["beam_width"] + 1e-12 and len(xs) == v["n_holes"]
            assert xs[0] - d / 2 > 0.01 and xs[-1] + d / 2 < v["beam_length"] - 0.01
            assert min(b - a for a, b in itertools.pairwise(xs)) > d + 0.01
        if task_id == TABLE:  # legs inside the plate and clear of the pad
            assert v["leg_x"] - v["leg_size"] / 2 > v["pad_size"] / 2
            assert v["leg_y"] - v["leg_size"] / 2 > v["pad_size"] / 2


@pytest.mark.parametrize("task_id", IDS)
def test_a_five_percent_error_in_a_main_dimension_moves_the_mass_by_more_than_one_percent(task_id: int) -> None:
    m = model(task_id)
    main = {54: ("beam_length", "beam_width", "beam_height"), 55: ("beam_length", "beam_width", "beam_height"),
            56: ("beam_length", "beam_width", "wall_thickness"), 57: ("beam_length", "beam_width", "beam_height"),
            58: ("table_length", "table_width", "plate_thickness", "leg_height")}[task_id]
    for v in _corners(m):
        for name in main:
            wrong = {**v, name: v[name] * 1.05}  # the derived values stay as the text states them
            assert abs(volume(task_id, wrong) / volume(task_id, v) - 1) > 0.01, (name, v)


def test_beams_share_masters_frame_and_interfaces() -> None:
    """The pendulum and the cantilever take any of 54-57 with one text: same masters, frame, names."""
    centres = []
    for task_id in BEAMS:
        m = model(task_id)
        assert m.master == ("beam_length", "beam_width", "beam_height") and m.interfaces == ("left", "right")
        v = m.sample_params(7, master=BEAM_MASTER)
        shape = check_solid(task_id, v)
        assert tuple(shape.bounding_box[1]) == pytest.approx((0.777, 0.0222, 0.0111), abs=1e-6)
        centres.append([c for n in ("left", "right") for c in _xyz(named_faces(shape, n)[0].center)])
    for other in centres[1:]:
        assert other == pytest.approx(centres[0], abs=1e-7)


def test_table_feet_are_numbered_counter_clockwise_from_minus_x_minus_y() -> None:
    m = model(TABLE)
    v = m.sample_params(3)
    shape = build(m, v)
    quadrants = []
    for i in range(1, 5):
        (foot,) = named_faces(shape, f"foot{i}")
        c = foot.center
        quadrants.append((c.x > 0, c.y > 0))
        assert c.z == pytest.approx(-(v["plate_thickness"] / 2 + v["leg_height"]), abs=1e-9)
    assert quadrants == [(False, False), (True, False), (True, True), (False, True)]
    (load,) = named_faces(shape, "load")
    assert load.center.z == pytest.approx(shape.bounding_box[1][2], abs=1e-6)


# ---------------------------------------------------------------- 2. meshed and reduced, seed 0


async def _run_all() -> dict[int, Any]:
    limits = ExecutionLimits(mode="part", timeout_s=120)
    runs = await asyncio.gather(*(execute(model(i).instance(0).reference_program, "", limits) for i in IDS))
    return dict(zip(IDS, runs, strict=True))


@pytest.fixture(scope="module")
def ground_truth_runs() -> dict[int, Any]:
    """Seed 0 of every part, meshed and reduced in child processes side by side."""
    return asyncio.run(_run_all())


@pytest.mark.parametrize("task_id", IDS)
def test_ground_truth_meshes_and_reduces(task_id: int, ground_truth_runs: dict[int, Any]) -> None:
    m, run = model(task_id), ground_truth_runs[task_id]
    assert run.error is None and run.stage == "reduced", run.error
    part = run.part
    assert part["interfaces"] == list(m.interfaces)
    assert (part["youngs_modulus"], part["poissons_ratio"], part["density"]) == (
        m.material.youngs_modulus, m.material.poissons_ratio, m.material.density)
    # linear tetrahedra facet the curved fillets (volume lost) and holes (volume gained)
    exact = m.material.density * volume(task_id, m.instance(0).params)
    assert part["mass"] == pytest.approx(exact, rel=0.02 if task_id in (55, 57) else 1e-9)
    frequencies = part["eigenfrequencies"]
    assert len(frequencies) >= 6 and all(f > 0 for f in frequencies)
    assert part["nodes"] <= 6000


# ---------------------------------------------------------------- 3. master parameters


@pytest.mark.parametrize("task_id", IDS)
def test_master_parameters_of_the_assembly_are_used(task_id: int) -> None:
    m = model(task_id)
    master = BEAM_MASTER if task_id in BEAMS else TABLE_MASTER
    instance = m.instance(4, master={**master, "unrelated": 1.0}, origin="assembly@4")
    assert set(m.master) == set(master)
    for name, value in master.items():
        assert instance.params[name] == value
        assert f"{name} = {value} m" in instance.description
        assert f"\n{name} = {value!r}\n" in instance.reference_program
    assert "unrelated" not in instance.params
    check_solid(task_id, instance.params)  # derived positions follow the master values
    own = m.instance(4)
    assert any(own.params[k] != v for k, v in master.items())
