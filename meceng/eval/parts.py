"""Part metrics for level 3a (paper section 3.3), as pure functions of what two meshed parts are.

Order: choose part components -> interface names -> material (E, nu, rho exact) -> mass (1 %) ->
mesh (1 %) -> eigenfrequencies (first three, relative vector norm, 5 %) -> part overall.

The mesh metric compares the two surface meshes with PyMeshLab (and the solids' surfaces meshed
three times finer, when the part runner could make them; the smaller of the two estimates counts,
see ``surface_distance``): the mean distance of sampled points of each surface to the other one
(both directions; the mean, not the max, because faceting hides small changes in the max), times
the ground truth's surface area, is the volume between the surfaces; normalised by the ground
truth's volume it must stay below 1 %.

The mesh-size minimum of the pre-check is derived here too, from the ground truth's bounding box.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import numpy as np

from meceng.eval.chain import StageResult
from meceng.eval.components import check_components

PART_STAGES = ("choose_part_components", "interface_name_match", "material_match", "mass_match", "mesh_match",
               "eigenfrequencies_match")

#: An extrusion can make a box or a cylinder (paper: "extrusion is considered equally correct").
PART_ALTERNATIVES: dict[str, tuple[str, ...]] = {"Box": ("Extrude",), "Cylinder": ("Extrude",)}


@dataclass(frozen=True)
class PartData:
    """What a meshed part is: interfaces, material, mass, surface, eigenfrequencies."""

    interfaces: tuple[str, ...]
    youngs_modulus: float
    poissons_ratio: float
    density: float
    mass: float
    vertices: np.ndarray  # (n, 3) surface points
    triangles: np.ndarray  # (m, 3) indices into vertices
    eigenfrequencies: np.ndarray = field(default_factory=lambda: np.zeros(0))
    fine: tuple[np.ndarray, np.ndarray] | None = None  # the solid's surface meshed finer, when known


@dataclass(frozen=True)
class PartTolerances:
    mass: float = 0.01
    mesh: float = 0.01
    eigenfrequencies: float = 0.05
    compared_frequencies: int = 3
    samples: int = 20000


def part_data(part: Mapping[str, object], surface: tuple[np.ndarray, np.ndarray],
              fine: tuple[np.ndarray, np.ndarray] | None = None) -> PartData:
    """A part as the part runner described it (its JSON record and its surface arrays)."""
    return PartData(
        interfaces=tuple(str(n) for n in part["interfaces"]),  # type: ignore[union-attr]
        youngs_modulus=float(part["youngs_modulus"]),  # type: ignore[arg-type]
        poissons_ratio=float(part["poissons_ratio"]),  # type: ignore[arg-type]
        density=float(part["density"]),  # type: ignore[arg-type]
        mass=float(part["mass"]),  # type: ignore[arg-type]
        vertices=np.asarray(surface[0], dtype=float),
        triangles=np.asarray(surface[1], dtype=np.int64),
        eigenfrequencies=np.asarray(part.get("eigenfrequencies") or [], dtype=float),
        fine=fine,
    )


def minimum_maxh(reference: PartData, reference_maxh: float) -> float:
    """The finest mesh size a part program may ask for: 1 % of the ground truth's bounding-box
    diagonal, and never more than half the ground truth's own size (an answer that copies the
    text's maxh is never coarsened)."""
    extent = reference.vertices.max(axis=0) - reference.vertices.min(axis=0)
    return float(min(np.linalg.norm(extent) / 100.0, 0.5 * reference_maxh))


def surface_area(vertices: np.ndarray, triangles: np.ndarray) -> float:
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    return float(0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum())


def enclosed_volume(vertices: np.ndarray, triangles: np.ndarray) -> float:
    """Volume of a closed, consistently oriented triangle surface (divergence theorem)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    return float(abs(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6.0)


def load_mesh_library() -> None:
    """Import PyMeshLab on the calling thread; call it from the main thread before the first
    distance is computed on a worker thread.

    PyMeshLab's plugins bring their own libssh, whose library constructor allocates OpenSSL
    numbers on whichever thread first imports PyMeshLab. Imported on a worker thread (grading off
    the event loop), its destructor at process exit freed them into that thread's torn-down
    malloc arena and glibc aborted ("malloc_consolidate(): unaligned fastbin chunk detected",
    exit 134) after all work was done: seen after every level 3 run and every pytest session
    that graded parts. Imported on the main thread, it exits cleanly (gdb backtrace and the
    test session in the commit that added this).
    """
    import pymeshlab  # noqa: F401


def _distance(cand: tuple[np.ndarray, np.ndarray], ref: tuple[np.ndarray, np.ndarray],
              samples: int) -> dict[str, float]:
    import pymeshlab

    meshes = pymeshlab.MeshSet()
    meshes.add_mesh(pymeshlab.Mesh(vertex_matrix=np.asarray(cand[0], dtype=float),
                                   face_matrix=np.asarray(cand[1], dtype=np.int32)))
    meshes.add_mesh(pymeshlab.Mesh(vertex_matrix=np.asarray(ref[0], dtype=float),
                                   face_matrix=np.asarray(ref[1], dtype=np.int32)))
    forward = meshes.get_hausdorff_distance(sampledmesh=0, targetmesh=1, samplevert=True, sampleface=True,
                                            samplenum=samples)
    backward = meshes.get_hausdorff_distance(sampledmesh=1, targetmesh=0, samplevert=True, sampleface=True,
                                             samplenum=samples)
    mean = 0.5 * (forward["mean"] + backward["mean"])
    area = surface_area(ref[0], ref[1])
    volume = enclosed_volume(ref[0], ref[1])
    return {"mean_candidate_to_reference": float(forward["mean"]),
            "mean_reference_to_candidate": float(backward["mean"]), "mean": float(mean),
            "max": float(max(forward["max"], backward["max"])),
            "relative_volume_between": float(mean * area / volume) if volume > 0 else float("inf")}


def surface_distance(candidate: PartData, reference: PartData, samples: int = 20000) -> dict[str, float]:
    """Mean distances between the two surfaces in both directions, and the relative volume between.

    Faceting only adds distance, so two estimates are made when both parts carry a finer surface
    (the parts' own surface meshes, and the finer ones) and the smaller one counts: the finer one
    forgives facets placed elsewhere on a curved face, the coarse one a glitch of the surface
    mesher (Netgen's surface meshing is not always reproducible for the same solid).
    """
    coarse = _distance((candidate.vertices, candidate.triangles), (reference.vertices, reference.triangles), samples)
    coarse["surfaces"] = "part meshes"
    if candidate.fine is None or reference.fine is None:
        return coarse
    fine = _distance(candidate.fine, reference.fine, samples)
    fine["surfaces"] = "finer surface meshes"
    best = min((coarse, fine), key=lambda d: d["relative_volume_between"])
    return {**best, "part_meshes": coarse["relative_volume_between"], "finer": fine["relative_volume_between"]}


def relative_frequency_error(candidate: np.ndarray, reference: np.ndarray, count: int = 3) -> float:
    """|f_llm - f_gt| / |f_gt| over the first ``count`` eigenfrequencies."""
    cand = np.asarray(candidate, dtype=float)[:count]
    ref = np.asarray(reference, dtype=float)[:count]
    if len(cand) < count or len(ref) < count:
        return float("inf")
    return float(np.linalg.norm(cand - ref) / np.linalg.norm(ref))


def evaluate_part(
    candidate: PartData | None,
    reference: PartData,
    *,
    selected: Iterable[str] | None,
    required: Iterable[str],
    dependencies: Mapping[str, Iterable[str]],
    failure: str | None = None,
    tolerances: PartTolerances | None = None,
    reference_frequencies: np.ndarray | None = None,
) -> tuple[StageResult, ...]:
    """The part stages in the paper's order; ``candidate`` None means the part was not produced
    (no maxh, meshing failed, crash): every stage after the component choice fails with ``failure``.

    ``reference_frequencies``: the ground truth's eigenfrequencies at the candidate's mesh size,
    when that differs from the text's (linear tetrahedra are stiff: halving maxh moves the first
    frequencies by several percent, which says nothing about the part)."""
    tol = tolerances or PartTolerances()
    stages: list[StageResult] = []
    if selected is None:
        stages.append(StageResult("choose_part_components", None, "not applicable: no component selection"))
    else:
        chosen = set(selected)
        for name, alternatives in PART_ALTERNATIVES.items():
            if chosen & set(alternatives):
                chosen.add(name)
        check = check_components(chosen, required, dependencies)
        stages.append(StageResult("choose_part_components", check.passed, check.detail))
    if candidate is None:
        reason = failure or "the program produced no meshed part"
        stages += [StageResult(name, False, reason) for name in PART_STAGES[1:]]
        return tuple(stages)

    names_ok = sorted(candidate.interfaces) == sorted(reference.interfaces)
    stages.append(StageResult("interface_name_match", names_ok,
                              f"interfaces {sorted(candidate.interfaces)}"
                              + ("" if names_ok else f", expected {sorted(reference.interfaces)}")))
    material = (candidate.youngs_modulus, candidate.poissons_ratio, candidate.density)
    expected = (reference.youngs_modulus, reference.poissons_ratio, reference.density)
    stages.append(StageResult("material_match", material == expected,
                              f"E, nu, rho = {material}" + ("" if material == expected else f", expected {expected}")))
    mass_error = abs(candidate.mass - reference.mass) / reference.mass
    stages.append(StageResult("mass_match", mass_error <= tol.mass,
                              f"mass {candidate.mass:.6g} kg vs {reference.mass:.6g} kg ({100 * mass_error:.2f} %)"))
    distance = surface_distance(candidate, reference, tol.samples)
    mesh_error = distance["relative_volume_between"]
    stages.append(StageResult("mesh_match", mesh_error <= tol.mesh,
                              f"volume between the surfaces {100 * mesh_error:.2f} % of the part's volume "
                              f"(mean distance {distance['mean']:.3g} m, {distance['surfaces']})"))
    truth = reference.eigenfrequencies if reference_frequencies is None else reference_frequencies
    frequency_error = relative_frequency_error(candidate.eigenfrequencies, truth, tol.compared_frequencies)
    stages.append(StageResult("eigenfrequencies_match", frequency_error <= tol.eigenfrequencies,
                              f"first {tol.compared_frequencies} eigenfrequencies differ by "
                              f"{100 * frequency_error:.2f} %"))
    return tuple(stages)
