"""Part metrics on parts whose answer is known: boxes made by hand."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from meceng.eval.parts import PartData, enclosed_volume, evaluate_part, relative_frequency_error, surface_area


def box(a: float, b: float, c: float, shift: float = 0.0, subdivisions: int = 8) -> tuple[np.ndarray, np.ndarray]:
    """A closed, outward-oriented triangulated box [shift, shift + a] x [0, b] x [0, c]."""
    vertices: list[list[float]] = []
    triangles: list[list[int]] = []
    n = subdivisions
    corners = np.array([a, b, c])
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0.0, 1.0):
            base = len(vertices)
            for i in range(n + 1):
                for j in range(n + 1):
                    p = np.zeros(3)
                    p[axis] = side * corners[axis]
                    p[u] = i / n * corners[u]
                    p[v] = j / n * corners[v]
                    vertices.append(list(p))
            for i in range(n):
                for j in range(n):
                    k = base + i * (n + 1) + j
                    quad = (k, k + n + 1, k + n + 2, k + 1)
                    t1, t2 = [quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]
                    if side == 0.0:
                        t1, t2 = t1[::-1], t2[::-1]
                    triangles += [t1, t2]
    points = np.array(vertices)
    points[:, 0] += shift
    return points, np.array(triangles)


def part(a: float = 1.0, b: float = 0.1, c: float = 0.05, shift: float = 0.0, density: float = 7850.0,
         frequencies: tuple[float, ...] = (100.0, 250.0, 400.0, 700.0, 900.0, 1200.0)) -> PartData:
    vertices, triangles = box(a, b, c, shift)
    return PartData(interfaces=("left", "right"), youngs_modulus=2.1e11, poissons_ratio=0.3, density=density,
                    mass=density * a * b * c, vertices=vertices, triangles=triangles,
                    eigenfrequencies=np.array(frequencies))


def stages(candidate: PartData, reference: PartData, selected=("Extrude", "GenerateMesh")) -> dict[str, bool]:
    result = evaluate_part(candidate, reference, selected=selected, required=("Box", "GenerateMesh"),
                           dependencies={})
    return {s.name: s.passed for s in result}


def test_geometry_helpers_on_a_box() -> None:
    vertices, triangles = box(1.0, 0.1, 0.05)
    assert enclosed_volume(vertices, triangles) == pytest.approx(0.005, rel=1e-12)
    assert surface_area(vertices, triangles) == pytest.approx(2 * (0.1 + 0.05 + 0.005), rel=1e-12)


def test_identical_part_passes_everything_and_extrusion_counts_as_box() -> None:
    assert all(stages(part(), part()).values())


def test_each_metric_catches_its_own_error() -> None:
    reference = part()
    assert stages(part(), reference, selected=("GenerateMesh",))["choose_part_components"] is False
    renamed = replace(part(), interfaces=("left", "Right"))
    assert stages(renamed, reference)["interface_name_match"] is False
    assert stages(replace(part(), poissons_ratio=0.29), reference)["material_match"] is False
    longer = part(a=1.02)  # 2 % more steel: mass and mesh both notice
    result = stages(longer, reference)
    assert result["mass_match"] is False and result["mesh_match"] is False
    moved = part(shift=0.05)  # same mass, displaced by 5 % of the length: only the mesh notices
    result = stages(moved, reference)
    assert result["mass_match"] is True and result["mesh_match"] is False
    slightly = part(a=1.004)  # 0.4 %: within both 1 % tolerances
    result = stages(slightly, reference)
    assert result["mass_match"] and result["mesh_match"]
    stiff = part(frequencies=(106.0, 265.0, 424.0, 700.0, 900.0, 1200.0))
    assert stages(stiff, reference)["eigenfrequencies_match"] is False
    assert relative_frequency_error(np.array([100.0, 250.0]), reference.eigenfrequencies) == float("inf")


def test_missing_part_fails_every_later_stage_with_the_reason() -> None:
    result = evaluate_part(None, part(), selected=None, required=(), dependencies={},
                           failure="no hard-coded maxh: not meshed")
    assert result[0].passed is None
    assert all(s.passed is False and "maxh" in s.detail for s in result[1:])
