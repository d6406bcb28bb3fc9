"""Level 3a parts of the simplified wind turbine (59 tower, 60 rotor) and the grinding bench
(61 housing, 62 spindle with disks).

The ground-truth geometry is checked against volumes, bounding boxes and interface areas/centres
derived by hand from the dimensions in the text (OCC's exact volume, no meshing), for 20 seeds
and for corners of the parameter ranges; the ground truth is run once per part as the pipeline
runs it; master parameters given by an assembly reach the text and make the interfaces of the
two parts of an assembly coincide.
"""

from __future__ import annotations

import asyncio
import math
import textwrap
from typing import Any

import numpy as np
import pytest

from meceng.tasks.part_base import PartModel
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

PART_IDS = (59, 60, 61, 62)
REL = 1e-6  # OCC volumes and areas of boxes/cylinders are exact up to round-off
POS = 1e-6  # m, face centres and bounding boxes (OCC enlarges boxes by ~1e-7)

Interface = dict[str, tuple[float, list[tuple[float, float, float]]]]  # name -> (total area, face centres)


def model(task_id: int) -> PartModel:
    m = default_registry().get(task_id)
    assert isinstance(m, PartModel)
    return m


def build(part: PartModel, values: dict[str, Any]) -> Any:
    """The GT solid, built in-process from the geometry code (netgen.occ only, no mesh)."""
    namespace: dict[str, Any] = {}
    exec("from netgen.occ import *", namespace)
    namespace.update(values)
    exec(textwrap.dedent(part.geometry_code), namespace)
    return namespace["shape"]


# ---------------------------------------------------------------- closed forms, derived by hand


def tower(v: dict[str, Any]) -> tuple[float, tuple, Interface]:
    """Plate + square tube above the plate + nacelle - closed square cavity - bore."""
    tube_height = v["tower_top"] - v["base_thickness"]
    volume = (v["base_width"] ** 2 * v["base_thickness"]
              + (v["tower_width"] ** 2 - v["cavity_width"] ** 2) * tube_height
              + v["nacelle_length"] * v["nacelle_width"] * v["nacelle_height"]
              - math.pi * v["shaft_radius"] ** 2 * v["nacelle_length"])
    half_x = max(v["base_width"], v["nacelle_length"]) / 2
    half_y = max(v["base_width"], v["nacelle_width"]) / 2
    bbox = ((-half_x, -half_y, 0.0), (half_x, half_y, v["tower_top"] + v["nacelle_height"]))
    interfaces = {"ground": (v["base_width"] ** 2, [(0.0, 0.0, 0.0)]),
                  "bore": (2 * math.pi * v["shaft_radius"] * v["nacelle_length"], [(0.0, 0.0, v["hub_height"])])}
    return volume, bbox, interfaces


def rotor(v: dict[str, Any]) -> tuple[float, tuple, Interface]:
    """Shaft + hub + 3 blades; of each blade only the part outside the hub cylinder counts:
    the strip |y| <= a = w/2, z >= 0 cuts the area a*sqrt(R^2 - a^2) + R^2*asin(a/R) out of the hub disk."""
    a, hub_r, tip = v["blade_width"] / 2, v["hub_radius"], v["rotor_radius"]
    inside_hub = a * math.sqrt(hub_r**2 - a**2) + hub_r**2 * math.asin(a / hub_r)
    volume = (math.pi * v["shaft_radius"] ** 2 * v["nacelle_length"] + math.pi * hub_r**2 * v["hub_length"]
              + 3 * v["blade_thickness"] * (v["blade_width"] * tip - inside_hub))
    # blades 2, 3 (120, 240 deg about x): outer tip corners at y = +-(tip*sqrt(3)/2 + w/4), z = -(tip/2 + w*sqrt(3)/4)
    half_y = tip * math.sqrt(3) / 2 + v["blade_width"] / 4
    bbox = ((0.0, -half_y, -(tip / 2 + v["blade_width"] * math.sqrt(3) / 4)), (v["hub_front"], half_y, tip))
    shaft_area = 2 * math.pi * v["shaft_radius"] * v["nacelle_length"]
    interfaces = {"shaft": (shaft_area, [(v["nacelle_length"] / 2, 0.0, 0.0)]),
                  "hub": (math.pi * hub_r**2, [(v["hub_front"], 0.0, 0.0)])}
    return volume, bbox, interfaces


def housing(v: dict[str, Any]) -> tuple[float, tuple, Interface]:
    """Length x (plate + rectangle below the axis + upper half disk - channel) - bores in the end walls - cavity."""
    length, body_r = v["housing_length"], v["body_radius"]
    section = (v["base_width"] * v["base_thickness"] + 2 * body_r * (v["axis_height"] - v["base_thickness"])
               + math.pi * body_r**2 / 2 - v["recess_width"] * v["recess_depth"])
    volume = (length * section - math.pi * v["spindle_radius"] ** 2 * 2 * v["bearing_length"]
              - math.pi * v["cavity_radius"] ** 2 * (length - 2 * v["bearing_length"]))
    bbox = ((-length / 2, -v["base_width"] / 2, 0.0), (length / 2, v["base_width"] / 2, v["axis_height"] + body_r))
    foot_y = (v["base_width"] + v["recess_width"]) / 4
    seat_x = (length - v["bearing_length"]) / 2
    seat_area = 2 * math.pi * v["spindle_radius"] * v["bearing_length"]
    interfaces = {"feet": (length * (v["base_width"] - v["recess_width"]), [(0.0, -foot_y, 0.0), (0.0, foot_y, 0.0)]),
                  "bearing_left": (seat_area, [(-seat_x, 0.0, v["axis_height"])]),
                  "bearing_right": (seat_area, [(seat_x, 0.0, v["axis_height"])])}
    return volume, bbox, interfaces


def spindle(v: dict[str, Any]) -> tuple[float, tuple, Interface]:
    """Armature + 2 journals + 2 shaft ends (outside the disks) + 2 disks."""
    volume = (math.pi * v["armature_radius"] ** 2 * 2 * v["inner_x"]
              + 2 * math.pi * v["spindle_radius"] ** 2 * v["bearing_length"]
              + 2 * math.pi * v["end_radius"] ** 2 * (v["end_length"] - v["disk_thickness"])
              + 2 * math.pi * v["disk_radius"] ** 2 * v["disk_thickness"])
    r = v["disk_radius"]
    bbox = ((-v["end_x"], -r, -r), (v["end_x"], r, r))
    seat_x = (v["housing_length"] - v["bearing_length"]) / 2
    seat_area = 2 * math.pi * v["spindle_radius"] * v["bearing_length"]
    interfaces = {"bearing_left": (seat_area, [(-seat_x, 0.0, 0.0)]),
                  "bearing_right": (seat_area, [(seat_x, 0.0, 0.0)])}
    return volume, bbox, interfaces


CLOSED_FORM = {59: tower, 60: rotor, 61: housing, 62: spindle}


def check_geometry(part: PartModel, values: dict[str, Any]) -> None:
    shape = build(part, values)
    volume, (low, high), interfaces = CLOSED_FORM[part.id](values)
    assert len(shape.solids) == 1, "the part must be one solid"
    assert shape.mass == pytest.approx(volume, rel=REL)
    box_low, box_high = shape.bounding_box
    assert tuple(box_low) == pytest.approx(low, abs=POS) and tuple(box_high) == pytest.approx(high, abs=POS)
    named = [f.name for f in shape.faces if f.name]
    assert set(named) == set(part.interfaces), named
    for name, (area, centres) in interfaces.items():
        faces = [f for f in shape.faces if f.name == name]
        assert sum(f.mass for f in faces) == pytest.approx(area, rel=REL), name
        found = [tuple(f.center) for f in faces]
        assert len(found) == len(centres), name
        assert all(any(np.allclose(f, c, atol=POS) for f in found) for c in centres), (name, found, centres)


@pytest.mark.parametrize("task_id", PART_IDS)
def test_geometry_matches_closed_forms(task_id: int) -> None:
    part = model(task_id)
    for seed in range(20):
        check_geometry(part, part.sample_params(seed))


@pytest.mark.parametrize("task_id", PART_IDS)
def test_geometry_is_valid_at_the_corners_of_the_ranges(task_id: int) -> None:
    """Every combination must keep the geometry valid (hub covers the blade overlaps, cavity
    inside the body, tube under the nacelle, ...): the closed forms assume it."""
    part = model(task_id)
    rng = np.random.default_rng(task_id)
    corners = [{p.name: p.low for p in part.params}, {p.name: p.high for p in part.params}]
    corners += [{p.name: (p.low, p.high)[int(rng.integers(2))] for p in part.params} for _ in range(10)]
    for values in corners:
        values.update(part.derive(dict(values)))
        check_geometry(part, values)


# ---------------------------------------------------------------- ground truth as the pipeline runs it


def blade_frequency(v: dict[str, Any], material: Any) -> float:
    """First bending frequency of one blade as an Euler-Bernoulli cantilever clamped at the hub."""
    length = v["rotor_radius"] - v["hub_radius"]
    t = v["blade_thickness"]
    return 1.875104**2 / (2 * math.pi * length**2) * math.sqrt(material.youngs_modulus * t**2
                                                               / (12 * material.density))


async def test_ground_truth_parts_mesh_and_reduce() -> None:
    parts = [model(i) for i in PART_IDS]
    instances = [p.instance(0) for p in parts]
    limits = ExecutionLimits(mode="part", timeout_s=240)
    runs = await asyncio.gather(*(execute(inst.reference_program, "", limits) for inst in instances))
    for part, inst, run in zip(parts, instances, runs, strict=True):
        assert run.error is None and run.stage == "reduced", (part.name, run.stage, run.error)
        result = run.part
        assert result["interfaces"] == list(part.interfaces), part.name
        volume = CLOSED_FORM[part.id](inst.params)[0]
        assert result["mass"] == pytest.approx(part.material.density * volume, rel=0.02), part.name
        frequencies = np.array(result["eigenfrequencies"])
        assert len(frequencies) >= 6 and np.all(frequencies > 0), (part.name, frequencies)
        assert result["nodes"] <= 6000, (part.name, result["nodes"])
        if part.id == 60:  # three equal blades: three nearly equal first modes, close to a clamped blade
            first = frequencies[:3]
            assert first.max() / first.min() < 1.1, first
            assert 1.0 < first.mean() / blade_frequency(inst.params, part.material) < 1.5, first


# ---------------------------------------------------------------- master parameters of the assemblies

WIND_TURBINE = {"shaft_radius": 0.0234, "nacelle_length": 0.246, "hub_height": 0.987}
GRINDING_BENCH = {"spindle_radius": 0.0117, "housing_length": 0.234, "bearing_length": 0.0255, "axis_height": 0.137}
MASTERS = {59: WIND_TURBINE, 60: WIND_TURBINE, 61: GRINDING_BENCH, 62: GRINDING_BENCH}


@pytest.mark.parametrize("task_id", PART_IDS)
def test_master_parameters_reach_params_and_text(task_id: int) -> None:
    part = model(task_id)
    given = {**MASTERS[task_id], "unrelated_master": 1.0}
    inst = part.instance(3, master=given)
    assert "unrelated_master" not in inst.params
    assert set(part.master) <= set(given)
    for name in part.master:
        assert inst.params[name] == given[name]
        assert f"{name} = {given[name]} m" in inst.description, name
    for name in set(given) - set(part.master):  # e.g. hub_height is not the rotor's business
        assert name not in inst.params
    own = part.instance(3)
    assert all(own.params[p.name] == inst.params[p.name] for p in part.params if p.name not in part.master)
    assert f"maxh = {inst.part.maxh:g} m" in inst.description and f"maxh={inst.part.maxh!r}" in inst.reference_program


def interface_faces(part: PartModel, values: dict[str, Any]) -> dict[str, tuple[float, np.ndarray]]:
    shape = build(part, values)
    out = {}
    for name in part.interfaces:
        faces = [f for f in shape.faces if f.name == name]
        area = sum(f.mass for f in faces)
        out[name] = (area, sum(np.array(tuple(f.center)) * f.mass for f in faces) / area)
    return out


@pytest.mark.parametrize(("fixed", "moving", "pairs", "shift"), [
    (59, 60, {"bore": "shaft"}, lambda m: (-m["nacelle_length"] / 2, 0.0, m["hub_height"])),
    (61, 62, {"bearing_left": "bearing_left", "bearing_right": "bearing_right"},
     lambda m: (0.0, 0.0, m["axis_height"])),
])
def test_assembly_interfaces_coincide(fixed: int, moving: int, pairs: dict[str, str], shift: Any) -> None:
    """With the shared masters the joint surfaces of the two parts have the same area (same radius and
    length) and, after the placement documented in the masters module, the same centre."""
    master = MASTERS[fixed]
    for seed in range(3):
        a = interface_faces(model(fixed), model(fixed).sample_params(seed, master))
        b = interface_faces(model(moving), model(moving).sample_params(seed + 10, master))
        for name_a, name_b in pairs.items():
            assert a[name_a][0] == pytest.approx(b[name_b][0], rel=REL)
            assert np.allclose(a[name_a][1], b[name_b][1] + np.array(shift(master)), atol=POS)
