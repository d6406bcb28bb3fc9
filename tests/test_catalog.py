"""The level 1-2 component catalog: names, dependencies, context, and every example program.

Each example runs in a fresh interpreter (as the pipeline runs a generated program): it must
succeed, leave no file behind and use no deprecated Exudyn name. Exudyn reports a deprecated
function, argument or setting as a DeprecationWarning attributed to the calling line (made an error
here for the program's own lines) and counts it in ``exudyn.sys['deprecationUse']`` (checked after
the run). Context texts are not run, so the calls they show are checked statically against the
installed Exudyn: every keyword must exist and must not be a deprecated one.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import warnings

import exudyn as exu
import exudyn.utilities as exu_utilities
import pytest
from exudyn_api import MAIN_SYSTEM, call_problems, calls, deprecated_arguments

from meceng.catalog.catalogs import rigid_catalog
from meceng.catalog.component import Catalog
from meceng.tasks.base import PREAMBLE

EXPECTED_NAMES = (
    "Ground",
    "MassPoint",
    "RigidBody",
    "InertiaCuboid",
    "InertiaCylinder",
    "InertiaSphere",
    "SpringDamper",
    "CartesianSpringDamper",
    "TorsionalSpringDamper",
    "RigidBodySpringDamper",
    "DistanceConstraint",
    "CoordinateSpringDamper",
    "CoordinateConstraint",
    "RevoluteJoint",
    "PrismaticJoint",
    "SphericalJoint",
    "GenericJoint",
    "RollingDisc",
    "Force",
    "Torque",
    "LoadUserFunction",
    "SphereSphereContact",
    "SphereTriangleContact",
    "Sensor",
    "JointPDControl",
)

#: Appended to every example: any deprecated name the program used, even where the warning was not
#: turned into an error (e.g. inside a user function called by the solver), fails the run.
DEPRECATION_CHECK = """
import exudyn as _exu
_used = _exu.sys.get('deprecationUse')
assert not _used, f'deprecated Exudyn names used: {_used}'
"""

SOLVE_BLOCK = re.compile(
    r"simulationSettings = exu\.SimulationSettings\(\)\n"
    r"simulationSettings\.timeIntegration\.endTime = [0-9.e+-]+\n"
    r"simulationSettings\.timeIntegration\.numberOfSteps = \d+\n"
    r"(?:simulationSettings\.[\w.]+ = .+\n)*"
    r"mbs\.SolveDynamic\(simulationSettings\)\n?$"
)


@pytest.fixture(scope="module")
def catalog() -> Catalog:
    return rigid_catalog()


def test_names_are_exactly_the_level_1_2_components(catalog):
    assert catalog.names == EXPECTED_NAMES


def test_dependencies_name_catalog_components(catalog):
    names = set(catalog.names)
    for component in catalog:
        assert set(component.dependencies) <= names, component.name
        assert component.name not in component.dependencies


def test_joint_context_brings_ground_and_rigid_body(catalog):
    text = catalog.context(["RevoluteJoint"])
    for name in ("Ground", "RigidBody", "RevoluteJoint"):
        assert f"### {name}\n" in text
    assert catalog.get("Ground").context.strip() in text
    assert catalog.get("RigidBody").context.strip() in text
    assert "mbs.CreateGround(" in text and "mbs.CreateRigidBody(" in text


def test_menu_has_one_line_per_component(catalog):
    lines = catalog.menu().splitlines()
    assert len(lines) == len(EXPECTED_NAMES)
    for component in catalog:
        assert component.description.strip() and "\n" not in component.description
        assert component.context.strip()
        assert component.group == "rigid"


@pytest.mark.parametrize("name", EXPECTED_NAMES)
def test_example_is_a_standard_program(catalog, name):
    example = catalog.get(name).example
    assert example.startswith(PREAMBLE)
    assert "mbs.Assemble()" in example
    assert SOLVE_BLOCK.search(example), "example must end with the standard simulation block"
    assert "simulationSettings.solution.file.write = False" in example
    for forbidden in ("exu.StartRenderer", "SolutionViewer", "fileName", "open(", "savefig", "writeToFile"):
        assert forbidden not in example


@pytest.mark.parametrize("name", EXPECTED_NAMES)
def test_example_runs_without_files_or_deprecations(catalog, name, tmp_path):
    example = catalog.get(name).example
    result = subprocess.run(
        [sys.executable, "-W", "error::DeprecationWarning:__main__", "-c", example + DEPRECATION_CHECK],
        cwd=tmp_path,
        env={**os.environ, "MPLBACKEND": "Agg"},
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert result.returncode == 0, result.stderr[-4000:]
    created = sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*"))
    assert created == [], f"example created files: {created}"


# --- static check of the calls shown in context texts and examples (tests/exudyn_api.py) ------


@pytest.mark.parametrize("name", EXPECTED_NAMES)
def test_calls_use_existing_current_names(catalog, name):
    component = catalog.get(name)
    for where, text in (("context", component.context), ("example", component.example)):
        assert call_problems(text) == [], where


@pytest.mark.parametrize("name", EXPECTED_NAMES)
def test_settings_and_output_types_exist_and_are_current(catalog, name):
    component = catalog.get(name)
    text = component.context + "\n" + component.example
    exu.special.deprecations.Reset()  # a name warned about before would not warn again
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        for path in re.findall(r"simulationSettings((?:\.\w+)+)", text):
            item = exu.SimulationSettings()
            for attribute in path.strip(".").split("."):
                item = getattr(item, attribute)  # raises for a missing or deprecated setting
    for variable in re.findall(r"exu\.OutputVariableType\.(\w+)", text):
        assert hasattr(exu.OutputVariableType, variable), variable


def test_the_static_check_finds_deprecated_arguments():
    found = dict(calls("mbs.CreateMassPoint(referencePosition=[0, 0, 0], physicsMass=f(1, 2), gravity=g)"))
    assert found["mbs.CreateMassPoint"] == ["referencePosition", "physicsMass", "gravity"]
    assert "physicsMass" in deprecated_arguments(MAIN_SYSTEM.CreateMassPoint)
    assert "bodyNumbers" in deprecated_arguments(MAIN_SYSTEM.CreateSpringDamper)
    assert "bodyNumbers" not in deprecated_arguments(MAIN_SYSTEM.CreateRollingDisc)
    assert "factorValue1" in deprecated_arguments(exu_utilities.CoordinateConstraint)
    assert "sphereRadius" not in deprecated_arguments(MAIN_SYSTEM.CreateSphereTriangleContact)
    assert call_problems("mbs.CreateMassPoint(physicsMass=1)") == ["mbs.CreateMassPoint(physicsMass=...) is deprecated"]
    assert call_problems("mbs.CreateGround(refPosition=[0, 0, 0])") == ["mbs.CreateGround has no argument refPosition"]
    assert call_problems("femArm.LoadFromFile('arm.npz'); mbs.CreateNothing()") == ["unknown mbs.CreateNothing"]
