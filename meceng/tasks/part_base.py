"""The shape of a level 3a part model (paper section 2.3, Part Generation).

A part model is a description template that fixes the geometry exactly (dimensions, features,
where they sit, the coordinate frame), the material, the named interfaces, and a ground truth
that builds the part with ``netgen.occ``, meshes it with a hard-coded ``maxh``, imports it into
Exudyn's ``FEMinterface`` with the interfaces as boundary names and reduces it with
Hurty-Craig-Bampton modes.

Master parameters are shared with the assemblies that use the part (the rotor's shaft radius is
the bearing's bore radius): a part drawn on its own samples them itself, a part drawn for an
assembly instance receives them from the assembly (``instance(seed, master=...)``).

Like a rigid task, the ground truth is program text: the saved reference program, the gold
answer and what the part runner executes are the same text.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from meceng.tasks.base import Param, TaskInstance, program_header, round_significant, slugify

#: Lines every part program starts with; the part prompt asks for the same names.
PART_PREAMBLE = """\
from netgen.occ import *
import ngsolve as ngs
import numpy as np
import exudyn as exu
from exudyn.FEM import FEMinterface, HCBstaticModeSelection
"""

#: Eigenmodes every part is reduced with; fewer requested are raised by the part runner.
N_MODES = 6


@dataclass(frozen=True)
class Material:
    name: str
    youngs_modulus: float
    poissons_ratio: float
    density: float

    def sentence(self) -> str:
        return (f"The part is made of {self.name} with Young's modulus E = {self.youngs_modulus:g} Pa, "
                f"Poisson's ratio nu = {self.poissons_ratio:g} and density rho = {self.density:g} kg/m^3.")


STEEL = Material("steel", 2.1e11, 0.3, 7850.0)
ALUMINIUM = Material("aluminium", 7.0e10, 0.33, 2700.0)
CAST_IRON = Material("cast iron", 1.1e11, 0.26, 7200.0)


@dataclass(frozen=True)
class PartSpec:
    """What the pipeline needs to know about a part instance beyond its text."""

    interfaces: tuple[str, ...]
    material: Material
    maxh: float
    n_modes: int = N_MODES
    geometry_text: str = ""  # the description without the meshing instructions (for an assembly's text)

    def to_json(self) -> dict[str, Any]:
        return {"interfaces": list(self.interfaces), "material": self.material.__dict__, "maxh": self.maxh,
                "n_modes": self.n_modes}


@dataclass(frozen=True)
class PartModel:
    """A parameterized part: template text, ranges, components and the ``netgen.occ`` ground truth.

    ``geometry_code`` uses the parameter names (and those returned by ``derive``) as variables and
    leaves the finished solid, with its interface faces named, in the variable ``shape``.
    ``mesh_size`` gives the ground truth's ``maxh`` from the parameter values; it is rounded to
    two significant digits and written as a literal, as the LLM is asked to do.
    ``master`` names the parameters an assembly may prescribe.
    """

    id: int
    name: str
    description: str
    params: tuple[Param, ...]
    components: tuple[str, ...]
    geometry_code: str
    interfaces: tuple[str, ...]
    mesh_size: Callable[[dict[str, Any]], float]
    material: Material = STEEL
    master: tuple[str, ...] = ()
    derive: Any = None  # Callable[[dict], dict] | None
    level: str = "3a"

    @property
    def slug(self) -> str:
        return slugify(self.name)

    def sample_params(self, seed: int, master: Mapping[str, Any] | None = None) -> dict[str, Any]:
        rng = np.random.default_rng([self.id, seed])
        values: dict[str, Any] = {p.name: p.sample(rng) for p in self.params}
        if master:  # an assembly's master parameters; those of its other parts are not ours
            values.update({k: v for k, v in master.items() if k in self.master})
        if self.derive is not None:
            values.update(self.derive(dict(values)))
        return values

    def maxh(self, values: Mapping[str, Any]) -> float:
        return round_significant(float(self.mesh_size(dict(values))), 2)

    def instance(self, seed: int, master: Mapping[str, Any] | None = None, origin: str = "") -> TaskInstance:
        values = self.sample_params(seed, master)
        maxh = self.maxh(values)
        text = " ".join(self.description.format(**values).split())
        names = ", ".join(f"'{n}'" for n in self.interfaces)
        description = (
            f"{text} {self.material.sentence()} Mesh the part with tetrahedral elements of maximum size "
            f"maxh = {maxh:g} m (hard-code this value in GenerateMesh), import the mesh into Exudyn's "
            f"FEMinterface with meshOrder=1 and the interfaces [{names}] as boundary names, in this order, and "
            f"compute Hurty-Craig-Bampton modes with {N_MODES} eigenmodes using these interfaces (RBE2)."
        )
        spec = PartSpec(self.interfaces, self.material, maxh, geometry_text=f"{text} {self.material.sentence()}")
        return TaskInstance(
            task_id=self.id, slug=self.slug, name=self.name, level=self.level, seed=seed, params=values,
            description=description, required_components=self.components, sim=None,
            reference_program=self.reference_program(values, description, seed, maxh),
            kind="part", part=spec, origin=origin,
        )

    def reference_program(self, values: Mapping[str, Any], description: str, seed: int, maxh: float) -> str:
        header = program_header(f"reference part: {self.id} {self.name}, seed {seed}", description)
        param_lines = "\n".join(f"{k} = {v!r}" for k, v in values.items())
        geometry = textwrap.dedent(self.geometry_code).strip("\n")
        return (f"{header}\n{PART_PREAMBLE}\n# parameters\n{param_lines}\n\n# geometry\n{geometry}\n\n"
                f"{fem_block(maxh, self.material, self.interfaces)}")


def fem_block(maxh: float, material: Material, interfaces: tuple[str, ...], n_modes: int = N_MODES) -> str:
    """Mesh, import with material and interfaces, reduce: the same lines for every part."""
    return (
        f"mesh = ngs.Mesh(OCCGeometry(shape).GenerateMesh(maxh={maxh!r}))\n"
        "fem = FEMinterface()\n"
        f"fem.ImportMeshFromNGsolve(mesh, density={material.density!r}, youngsModulus={material.youngs_modulus!r},\n"
        f"                          poissonsRatio={material.poissons_ratio!r}, meshOrder=1,\n"
        f"                          boundaryNamesList={list(interfaces)!r})\n"
        "boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()\n"
        f"fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes={n_modes},\n"
        "                                  boundaryNodesWeights=boundaryWeights,\n"
        "                                  computationMode=HCBstaticModeSelection.RBE2)\n"
    )
