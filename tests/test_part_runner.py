"""Level 3a part programs run in isolation; the harness captures the meshed part."""

from __future__ import annotations

import numpy as np
import pytest

from meceng.eval.parts import PartData, evaluate_part
from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.warm import WarmPool

BEAM = """
from netgen.occ import *
import ngsolve as ngs
from exudyn.FEM import FEMinterface, HCBstaticModeSelection

L, b, h = {L!r}, 0.04, 0.02
shape = Box(Pnt(0, -b / 2, -h / 2), Pnt(L, b / 2, h / 2))
shape.faces.Min(X).name = 'left'
shape.faces.Max(X).name = 'right'
mesh = ngs.Mesh(OCCGeometry(shape).GenerateMesh(maxh=0.02))
fem = FEMinterface()
fem.ImportMeshFromNGsolve(mesh, density=7850, youngsModulus=2.1e11, poissonsRatio=0.3, meshOrder=1,
                          boundaryNamesList=['left', 'right'])
nodes, weights = fem.GetBoundaryNodeSetsAsLists()
fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=nodes, nEigenModes=2, boundaryNodesWeights=weights,
                                  computationMode=HCBstaticModeSelection.RBE2)
"""


def as_part(run) -> PartData:
    p = run.part
    return PartData(tuple(p["interfaces"]), p["youngs_modulus"], p["poissons_ratio"], p["density"], p["mass"],
                    run.surface[0], run.surface[1], np.array(p["eigenfrequencies"]))


@pytest.mark.parametrize("warm", [False, True])
async def test_beam_part_is_captured_and_graded(warm: bool) -> None:
    pool = WarmPool(child_env()) if warm else None
    limits = ExecutionLimits(mode="part", timeout_s=120)
    try:
        reference = await execute(BEAM.format(L=0.8), "", limits, check=False, pool=pool)
        longer = await execute(BEAM.format(L=0.816), "", limits, check=False, pool=pool)
    finally:
        if pool is not None:
            await pool.close()
    assert reference.error is None and reference.stage == "reduced", reference.error
    part = reference.part
    assert part["interfaces"] == ["left", "right"]
    assert (part["youngs_modulus"], part["poissons_ratio"], part["density"]) == (2.1e11, 0.3, 7850.0)
    assert part["mass"] == pytest.approx(7850 * 0.8 * 0.04 * 0.02, rel=1e-9)  # a box: mesh volume is exact
    assert part["modes_requested"] == 2 and len(part["eigenfrequencies"]) >= 6  # raised to six
    vertices, triangles = reference.surface
    assert vertices.shape[1] == 3 and triangles.max() < len(vertices)

    same = {s.name: s.passed for s in evaluate_part(as_part(reference), as_part(reference), selected=None,
                                                     required=(), dependencies={})}
    assert all(v for k, v in same.items() if k != "choose_part_components")
    graded = {s.name: s.passed for s in evaluate_part(as_part(longer), as_part(reference), selected=None,
                                                       required=(), dependencies={})}
    assert graded["mass_match"] is False and graded["mesh_match"] is False  # 2 % longer
    assert graded["interface_name_match"] and graded["material_match"]


async def test_part_program_without_mesh_import_is_a_verdict() -> None:
    result = await execute("x = 1\n", "", ExecutionLimits(mode="part"), check=False)
    assert result.part is None and "never called FEMinterface.ImportMeshFromNGsolve" in (result.error or "")


async def test_an_interface_name_on_no_face_is_not_an_interface() -> None:
    program = BEAM.format(L=0.5).replace("shape.faces.Max(X).name = 'right'\n", "")
    run = await execute(program, "", ExecutionLimits(mode="part", timeout_s=120), check=False)
    assert run.error is None and run.part["interfaces"] == ["left"]
    assert any("['right']" in w for w in run.warnings)
