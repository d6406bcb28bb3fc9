"""Rotor / bearing-block parts (51, 52, 53, 66) against volumes, areas and frames derived by hand.

The ground-truth geometry is built in this process without meshing (meshing here would make the
executor's forked children deadlock) and compared with closed forms written from the dimensions:
boxes and cylinders exactly, a 45-degree chamfer of leg c removes c^2/2 per unit edge length (with
c^3/3 counted twice at each mitred corner of a closed edge loop, and pi (r c^2 - c^3/3) around a
circular end edge of radius r), the flat-bottomed keyway removes the circular segment above its
floor. One seed per part then runs the full pipeline (mesh, import, Hurty-Craig-Bampton) in a child.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable

import pytest

from meceng.tasks.part_base import PartModel
from meceng.tasks.parts import (
    balanced_rotor_part,
    bearing_block_part,
    bearing_block_with_pedestal_part,
    unbalanced_rotor_part,
)
from meceng.tasks.parts.masters_rotor import ROTOR_MASTERS
from meceng.tasks.registry import default_registry
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import execute

PI = math.pi
Box3 = tuple[tuple[float, float, float], tuple[float, float, float]]


# --- closed forms: volume, removed volume per feature, bounding box, interfaces (area, centre) ---

def block_51(v: dict) -> dict:
    bw, L, H, r = v["bearing_width"], v["block_length"], v["block_height"], v["shaft_radius"]
    features = {"bore": PI * r**2 * bw, "groove": v["groove_width"] * v["groove_depth"] * bw}
    return {
        "volume": bw * L * H - sum(features.values()), "features": features,
        "bbox": ((-bw / 2, -L / 2, 0.0), (bw / 2, L / 2, H)),
        "interfaces": {"bore": (2 * PI * r * bw, (0.0, 0.0, v["axis_height"])),
                       "bottom": (bw * (L - v["groove_width"]), (0.0, 0.0, 0.0))},
        "walls": {"foot": (L - v["groove_width"]) / 2, "groove to bore": v["axis_height"] - r - v["groove_depth"],
                  "top wall": H - v["axis_height"] - r},
    }


def pedestal_66(v: dict) -> dict:
    fw, fl, ft = v["foot_width"], v["foot_length"], v["foot_thickness"]
    bw, hl, H, r = v["bearing_width"], v["housing_length"], v["block_height"], v["shaft_radius"]
    c1, c2 = v["top_chamfer"], v["foot_chamfer"]
    features = {"bore": PI * r**2 * bw,
                "top chamfers": 2 * (c1**2 / 2) * bw,  # two edges of length bw, open ends
                "foot chamfers": (c2**2 / 2) * 2 * (fw + fl) - 4 * c2**3 / 3}  # closed loop, 4 mitred corners
    # distance from the bore axis to the top chamfer's plane y + z = hl/2 + H - c1, minus the bore radius
    chamfer_to_bore = (hl / 2 + H - c1 - v["axis_height"]) / math.sqrt(2) - r
    return {
        "volume": fw * fl * ft + bw * hl * (H - ft) - sum(features.values()), "features": features,
        "bbox": ((-fw / 2, -fl / 2, 0.0), (fw / 2, fl / 2, H)),
        "interfaces": {"bore": (2 * PI * r * bw, (0.0, 0.0, v["axis_height"])), "bottom": (fw * fl, (0.0, 0.0, 0.0))},
        "walls": {"chamfer to bore": chamfer_to_bore, "flat top": hl - 2 * c1, "foot chamfer to housing (x)":
                  (fw - bw) / 2 - c2, "foot chamfer to housing (y)": (fl - hl) / 2 - c2, "plate under chamfer": ft - c2,
                  "bore above plate": v["axis_height"] - r - ft},
    }


def unbalanced_52(v: dict) -> dict:
    r, bw, span = v["shaft_radius"], v["bearing_width"], v["bearing_span"]
    b, R, t, rh = v["body_radius"], v["disc_radius"], v["disc_thickness"], v["hole_radius"]
    features = {"unbalance hole": PI * rh**2 * t, "disc": PI * (R**2 - b**2) * t}
    offset = (b + R) / 2
    return {
        "volume": 2 * PI * r**2 * bw + PI * b**2 * (span - bw) + features["disc"] - features["unbalance hole"],
        "features": features,
        "bbox": ((0.0, -R, -R), (span + bw, R, R)),
        "interfaces": {"left": (2 * PI * r * bw, (bw / 2, 0.0, 0.0)),
                       "right": (2 * PI * r * bw, (span + bw / 2, 0.0, 0.0))},
        "walls": {"hole to body": offset - rh - b, "hole to rim": R - offset - rh, "shoulder": b - r,
                  "disc to seats": (span - bw - t) / 2},
    }


def balanced_53(v: dict) -> dict:
    re_, le, c = v["end_radius"], v["end_length"], v["end_chamfer"]
    r, bw, span = v["shaft_radius"], v["bearing_width"], v["bearing_span"]
    R, w, t, margin = v["mid_radius"], v["key_width"], v["key_depth"], v["key_margin"]
    a, key_length = w / 2, span - bw - 2 * margin
    # slot |y| <= a above the floor z = R - t: integral of (sqrt(R^2 - y^2) - (R - t)) over |y| <= a
    segment = a * math.sqrt(R**2 - a**2) + R**2 * math.asin(a / R) - 2 * a * (R - t)
    features = {"keyway": key_length * segment, "end chamfers": 2 * PI * (re_ * c**2 - c**3 / 3),
                "drive ends": 2 * PI * re_**2 * le}
    x1 = le
    x3 = le + span
    return {
        "volume": (features["drive ends"] + 2 * PI * r**2 * bw + PI * R**2 * (span - bw)
                   - features["keyway"] - features["end chamfers"]),
        "features": features,
        "bbox": ((0.0, -R, -R), (2 * le + span + bw, R, R)),
        "interfaces": {"left": (2 * PI * r * bw, (x1 + bw / 2, 0.0, 0.0)),
                       "right": (2 * PI * r * bw, (x3 + bw / 2, 0.0, 0.0))},
        "walls": {"end step": r - re_, "mid step": R - r, "keyway side walls": math.sqrt(R**2 - (R - t) ** 2) - a,
                  "keyway length": key_length, "chamfer": re_ - c},
    }


PARTS: dict[int, tuple[PartModel, Callable[[dict], dict]]] = {
    51: (bearing_block_part.TASK, block_51),
    52: (unbalanced_rotor_part.TASK, unbalanced_52),
    53: (balanced_rotor_part.TASK, balanced_53),
    66: (bearing_block_with_pedestal_part.TASK, pedestal_66),
}
#: features that must change the volume by >= 2 % (the metrics' mass tolerance is 1 %)
VISIBLE = {51: ("groove",), 52: ("unbalance hole",), 53: ("keyway",), 66: ("top chamfers", "foot chamfers")}


def build(model: PartModel, values: dict):
    namespace: dict = {}
    exec("from netgen.occ import *", namespace)
    namespace.update(values)
    exec(model.geometry_code, namespace)
    return namespace["shape"]


# --- 1. geometry of seeds 0..19 against the closed forms ---

@pytest.mark.parametrize("part_id", sorted(PARTS))
def test_geometry_matches_closed_form_for_twenty_seeds(part_id: int) -> None:
    model, closed = PARTS[part_id]
    for seed in range(20):
        values = model.sample_params(seed)
        shape = build(model, values)
        expected = closed(values)
        where = f"part {part_id} seed {seed}"
        assert len(shape.solids) == 1, where
        assert shape.mass == pytest.approx(expected["volume"], rel=1e-6), where
        low, high = shape.bounding_box  # OCC pads boxes by 1e-7
        for got, want in zip((*low, *high), (*expected["bbox"][0], *expected["bbox"][1]), strict=True):
            assert got == pytest.approx(want, abs=1e-6), (where, shape.bounding_box, expected["bbox"])
        names = [f.name for f in shape.faces]
        for name, (area, centre) in expected["interfaces"].items():
            faces = [f for f in shape.faces if f.name == name]
            assert faces, (where, name, names)
            total = sum(f.mass for f in faces)
            assert total == pytest.approx(area, rel=1e-6), (where, name)
            mean = [sum(f.mass * getattr(f.center, k) for f in faces) / total for k in "xyz"]
            assert mean == pytest.approx(list(centre), abs=1e-6), (where, name)
        assert set(model.interfaces) == set(expected["interfaces"])


@pytest.mark.parametrize("part_id", sorted(PARTS))
def test_every_range_combination_is_valid_and_features_are_visible(part_id: int) -> None:
    """All 2^n corners of the ranges: walls stay positive, the designed features stay >= 2 %."""
    model, closed = PARTS[part_id]
    for corner in itertools.product(*[(p.low, p.high) for p in model.params]):
        values = {p.name: x for p, x in zip(model.params, corner, strict=True)}
        values.update(model.derive(dict(values)))
        expected = closed(values)
        for wall, size in expected["walls"].items():
            assert size >= 0.0019, (part_id, wall, size, values)  # >= 2 mm
        for feature in VISIBLE[part_id]:
            share = expected["features"][feature] / expected["volume"]
            assert share >= 0.02, (part_id, feature, share, values)
        # a 5 % longer/wider main dimension must move the mass by > 1 %
        main = {51: "block_length", 52: "disc_radius", 53: "mid_radius", 66: "foot_length"}[part_id]
        bigger = {**values, main: values[main] * 1.05}
        bigger.update(model.derive(dict(bigger)))
        assert closed(bigger)["volume"] / expected["volume"] - 1 > 0.01, (part_id, main)


# --- 2. the ground truth through the pipeline's part runner ---

@pytest.mark.parametrize("part_id", sorted(PARTS))
async def test_ground_truth_is_meshed_and_reduced(part_id: int) -> None:
    model, closed = PARTS[part_id]
    instance = model.instance(0)
    result = await execute(instance.reference_program, "", ExecutionLimits(mode="part", timeout_s=120))
    assert result.stage == "reduced" and result.error is None, result.error
    part = result.part
    assert part["interfaces"] == list(model.interfaces)
    # Exudyn only warns when a boundary name is on no face; the node sets must all exist
    assert "could not compute" not in (result.stdout_tail or ""), result.stdout_tail
    material = model.material
    assert (part["youngs_modulus"], part["poissons_ratio"], part["density"]) == (
        material.youngs_modulus, material.poissons_ratio, material.density)
    # linear tets facet the curved surfaces: the mesh volume is within 2 % of the exact one
    assert part["mass"] == pytest.approx(material.density * closed(instance.params)["volume"], rel=0.02)
    frequencies = part["eigenfrequencies"]
    assert len(frequencies) >= 6 and all(f > 0 for f in frequencies)
    assert part["nodes"] <= 6000


# --- 3. master parameters ---

def test_masters_from_an_assembly_reach_params_text_and_derived_values() -> None:
    master = {"shaft_radius": 0.0166, "bearing_width": 0.0444, "axis_height": 0.111, "bearing_span": 0.333,
              "block_length": 0.5}  # not a master of any part: must be ignored
    for part_id, (model, _) in PARTS.items():
        instance = model.instance(3, master=master)
        for name in model.master:
            assert instance.params[name] == master[name]
            assert f"{name} = {master[name]} m" in instance.description, (part_id, name)
        assert instance.params.get("block_length") != 0.5
    block = bearing_block_part.TASK.instance(3, master=master).params
    assert block["block_height"] == pytest.approx(0.111 + 0.0166 + block["top_wall"], abs=1e-9)
    assert "axis_height" not in balanced_rotor_part.TASK.instance(3, master=master).params


def test_parts_drawn_for_one_assembly_fit_together() -> None:
    """Shared masters: each rotor seat has the bore's radius and the block's width, seats are
    bearing_span apart (the two blocks of assembly 75), and every unbalanced disc clears the ground."""
    master = {p.name: p.high for p in ROTOR_MASTERS}
    block_params = bearing_block_with_pedestal_part.TASK.sample_params(1, master)
    bore = next(f for f in build(bearing_block_with_pedestal_part.TASK, block_params).faces if f.name == "bore")
    for model in (unbalanced_rotor_part.TASK, balanced_rotor_part.TASK):
        values = model.sample_params(1, master)
        faces = {f.name: f for f in build(model, values).faces if f.name}
        left, right = faces["left"], faces["right"]
        assert left.mass == pytest.approx(bore.mass, rel=1e-9)  # same radius, same length
        assert right.center.x - left.center.x == pytest.approx(master["bearing_span"], abs=1e-9)
    disc = next(p for p in unbalanced_rotor_part.TASK.params if p.name == "disc_radius")
    height = next(p for p in ROTOR_MASTERS if p.name == "axis_height")
    assert disc.high < height.low


def test_family_is_registered_with_paper_ids_and_names() -> None:
    registry = default_registry()
    for part_id, (model, _) in PARTS.items():
        assert registry.get(part_id) is model
    assert {m.slug for m, _ in PARTS.values()} == {
        "bearing_block_part", "unbalanced_rotor_part", "balanced_rotor_part", "bearing_block_with_pedestal_part"}
