"""The child side for level 3a part programs: run the program, capture the meshed part.

The harness wraps ``FEMinterface.ImportMeshFromNGsolve`` (material and interface names as the
program gave them) and the mode computations (fewer than ``n_modes`` eigenmodes are silently
raised, so that parts stay comparable). After the program it reads from the program's own
FEMinterface: mass, eigenfrequencies and the surface triangulation, and writes them next to the
result under the job's token, like the rigid runner.
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path
from typing import Any

import numpy as np

from meceng.tools import guard
from meceng.tools.errors import describe_exception


def run_part(job: dict[str, Any], workdir: Path) -> int:
    # trusted libraries first: netgen loads its OCC kernel through ctypes, which the guard refuses
    import netgen.occ
    import ngsolve  # noqa: F401
    from exudyn.FEM import FEMinterface

    token = str(job.get("token", ""))
    n_modes = int(job.get("n_modes", 6))
    state: dict[str, Any] = {"stage": "started", "fem": None, "material": None, "interfaces": None,
                             "modes_requested": None}
    times: dict[str, float] = {"mesh_s": 0.0, "import_s": 0.0, "hcb_s": 0.0}
    warnings: list[str] = []
    stage_log = open(workdir / "stage.log", "a", buffering=1)  # noqa: SIM115 - kept open for the run
    stage_log.write("started\n")

    original_import = FEMinterface.ImportMeshFromNGsolve
    original_mesh = netgen.occ.OCCGeometry.GenerateMesh

    def generate_mesh(geometry: Any, *args: Any, **kwargs: Any) -> Any:
        state["geometry_source"] = (geometry, kwargs.get("maxh"))
        t = time.perf_counter()
        try:
            return original_mesh(geometry, *args, **kwargs)
        finally:
            times["mesh_s"] += time.perf_counter() - t

    def import_mesh(fem: Any, mesh: Any, density: float, youngsModulus: float, poissonsRatio: float,
                    *args: Any, **kwargs: Any) -> Any:
        t = time.perf_counter()
        out = original_import(fem, mesh, density, youngsModulus, poissonsRatio, *args, **kwargs)
        times["import_s"] += time.perf_counter() - t
        names = tuple(str(n) for n in (kwargs.get("boundaryNamesList") or ()))
        # a name that is on no face gives no node set (Exudyn only prints a warning): it is not an interface
        on_mesh = _boundary_names(mesh)
        missing = [n for n in names if on_mesh is not None and n not in on_mesh]
        if missing:
            warnings.append(f"interfaces without faces on the mesh: {missing}")
        state.update(fem=fem, material=(float(youngsModulus), float(poissonsRatio), float(density)),
                     interfaces=tuple(n for n in names if n not in missing), stage="meshed")
        state["geometry"] = _mesh_geometry(mesh, state["interfaces"], state.get("geometry_source"))
        stage_log.write("meshed\n")
        return out

    def raise_modes(name: str) -> None:
        original = getattr(FEMinterface, name)

        def wrapped(fem: Any, *args: Any, **kwargs: Any) -> Any:
            positional = args[1] if len(args) > 1 else None  # (boundaryNodesList, nEigenModes, ...)
            requested = kwargs.get("nEigenModes", positional)
            if requested is not None and int(requested) < n_modes:
                if "nEigenModes" in kwargs:
                    kwargs["nEigenModes"] = n_modes
                else:
                    args = (args[0], n_modes, *args[2:])
            state["modes_requested"] = requested
            t = time.perf_counter()
            out = original(fem, *args, **kwargs)
            times["hcb_s"] += time.perf_counter() - t
            state["stage"] = "reduced"
            stage_log.write("reduced\n")
            return out

        setattr(FEMinterface, name, wrapped)

    FEMinterface.ImportMeshFromNGsolve = import_mesh
    netgen.occ.OCCGeometry.GenerateMesh = generate_mesh
    for name in ("ComputeHurtyCraigBamptonModes", "ComputeHurtyCraigBamptonModesNGsolve"):
        if hasattr(FEMinterface, name):
            raise_modes(name)

    set_guard = guard.install(str(workdir), warnings.append) if job.get("guard", True) else (lambda active: None)
    result: dict[str, Any] = {"mode": "part", "error": None, "error_type": None}
    t0 = time.perf_counter()
    namespace: dict[str, Any] = {"__name__": "__main__"}
    try:
        set_guard(True)
        exec(compile(job["program"], str(workdir / "program.py"), "exec"), namespace)
    except BaseException as exc:  # every error of the program is a verdict
        result.update(describe_exception(exc, workdir, job["program"]))
    finally:
        set_guard(False)
    result["program_time"] = time.perf_counter() - t0
    fem = state["fem"]
    if fem is None and result["error"] is None:
        result.update(error="the program never called FEMinterface.ImportMeshFromNGsolve", error_type="NoMesh")
    if fem is not None:
        try:
            result["part"] = _describe_part(fem, state, workdir, token)
            if job.get("save_fem"):  # the reduced part, for the assemblies (FEMinterface's own format)
                fem.SaveToFile(str(workdir / f"fem-{token}.npz"))
        except Exception as exc:  # a half-built part is a verdict too
            reason = describe_exception(exc, workdir, job["program"])["error"]
            result.update(error=f"could not read the part: {reason}", error_type=type(exc).__name__)
    result.update(stage=state["stage"], warnings=warnings, token=token, part_times=times)
    tmp = workdir / f"result-{token}.json.tmp"
    tmp.write_text(json.dumps(result))
    os.replace(tmp, workdir / f"result-{token}.json")
    return 0


#: The surface the mesh metric compares is meshed this much finer than the part itself.
FINE_SURFACE_FACTOR = 3.0


def _fine_surface(source: tuple[Any, Any] | None) -> tuple[np.ndarray, np.ndarray] | None:
    """A surface-only mesh of the program's own solid, ``FINE_SURFACE_FACTOR`` times finer than its
    volume mesh: close to the exact geometry, so two correct parts meshed with their facets in
    other places (a fillet made by an arc, a cylinder turned about its axis) compare as equal."""
    if source is None or not isinstance(source[1], int | float) or source[1] <= 0:
        return None
    geometry, maxh = source
    try:
        from netgen.meshing import MeshingStep

        surface = geometry.GenerateMesh(maxh=float(maxh) / FINE_SURFACE_FACTOR, perfstepsend=MeshingStep.MESHSURFACE)
        points = np.asarray(surface.Coordinates(), dtype=float)
        triangles = np.asarray(surface.Elements2D().NumPy()["nodes"], dtype=np.int64)[:, :3] - 1  # 1-based
    except Exception:  # the metric falls back to the volume mesh's surface
        return None
    return (points, triangles) if len(triangles) else None


def _boundary_names(mesh: Any) -> set[str] | None:
    try:
        return {str(n) for n in mesh.GetBoundaries()}
    except Exception:  # not an ngsolve mesh: cannot tell, trust the list
        return None


def _mesh_geometry(mesh: Any, names: tuple[str, ...], source: tuple[Any, Any] | None = None) -> dict[str, Any]:
    """Volume of the mesh and, for every named interface, its area, centre, mean outward normal,
    number of geometry faces and of surface triangles (for the agent's ``mesh_part`` tool)."""
    try:
        import ngsolve as ngs

        one = ngs.CoefficientFunction(1.0)
        normal = ngs.specialcf.normal(3)
        shape = getattr(source[0], "shape", None) if source else None
        triangles: dict[str, int] = {}
        for element in mesh.Elements(ngs.BND):
            triangles[element.mat] = triangles.get(element.mat, 0) + 1
        interfaces = {}
        for name in names:
            region = mesh.Boundaries(str(name))
            area = float(ngs.Integrate(one, mesh, ngs.BND, definedon=region))
            centre = ([float(ngs.Integrate(c, mesh, ngs.BND, definedon=region)) / area for c in (ngs.x, ngs.y, ngs.z)]
                      if area > 0 else None)
            mean_normal = ([float(ngs.Integrate(normal[k], mesh, ngs.BND, definedon=region)) / area
                            for k in range(3)] if area > 0 else None)
            faces = sum(1 for face in shape.faces if face.name == name) if shape is not None else None
            interfaces[str(name)] = {"area": area, "centre": centre, "mean_normal": mean_normal,
                                     "geometry_faces": faces, "surface_triangles": triangles.get(str(name), 0)}
        return {"volume": float(ngs.Integrate(one, mesh)), "interfaces": interfaces}
    except Exception as exc:  # not an ngsolve mesh: the metrics do not need this
        return {"error": f"{type(exc).__name__}: {exc}"}


def _describe_part(fem: Any, state: dict[str, Any], workdir: Path, token: str) -> dict[str, Any]:
    triangles = np.asarray(fem.GetSurfaceTriangles(), dtype=np.int64)
    nodes = np.asarray(fem.GetNodePositionsAsArray(), dtype=float)
    used, compact = np.unique(triangles, return_inverse=True)
    fine = _fine_surface(state.get("geometry_source"))
    extra = {"fine_vertices": fine[0], "fine_triangles": fine[1]} if fine is not None else {}
    np.savez(workdir / f"part-{token}.npz", vertices=nodes[used], triangles=compact.reshape(triangles.shape),
             **extra)
    frequencies: list[float] = []
    try:
        frequencies = [float(f) for f in fem.GetEigenFrequenciesHz()]
    except Exception:  # no modes computed: the eigenfrequency metric says so
        frequencies = []
    youngs, poisson, density = state["material"]
    return {"interfaces": list(state["interfaces"]), "youngs_modulus": youngs, "poissons_ratio": poisson,
            "density": density, "mass": float(fem.GetRigidBodyInertia().Mass()), "eigenfrequencies": frequencies,
            "modes_requested": state["modes_requested"], "nodes": len(nodes), "surface_triangles": len(triangles),
            "bounding_box": [nodes.min(axis=0).tolist(), nodes.max(axis=0).tolist()],
            "geometry": state.get("geometry") or {}}
