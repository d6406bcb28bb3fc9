"""The level 1-2 component catalog: names, dependencies, context, and every example program.

Each example runs in a fresh interpreter (as the pipeline runs a generated program): it must
succeed, leave no file behind and use no deprecated Exudyn name. Exudyn reports a deprecated
function, argument or setting as a DeprecationWarning attributed to the calling line (made an error
here for the program's own lines) and counts it in ``exudyn.sys['deprecationUse']`` (checked after
the run). Context texts are not run, so the calls they show are checked statically against the
installed Exudyn: every keyword must exist and must not be a deprecated one.
"""

from __future__ import annotations

import inspect
import os
import re
import subprocess
import sys
import warnings

import exudyn as exu
import exudyn.utilities as exu_utilities
import pytest

from meceng.agents.catalog import Catalog, rigid_catalog
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


# --- static check of the calls shown in context texts and examples ----------------------------

_CALL = re.compile(r"(?<![\w.])(mbs\.\w+|exu\.\w+|[A-Z]\w*)\(")
_MAIN_SYSTEM = exu.SystemContainer().AddSystem()
_ARGUMENT_DOC = re.compile(r"^\s*(\w+): (.*)$", re.MULTILINE)


def _deprecated_arguments(function) -> set[str]:
    """Arguments the docstring calls deprecated ('deprecated name of ...', 'deprecated since ...')
    or not accepted, as Exudyn documents them for the Create functions and the item classes."""
    doc = inspect.getdoc(function) or ""
    return {
        name
        for name, text in _ARGUMENT_DOC.findall(doc)
        if "deprecated" in text.lower() or text.startswith("not accepted")
    }


def _calls(text: str) -> list[tuple[str, list[str]]]:
    """(callee, top-level keyword names) of every call ``name(...)`` in the text."""
    calls = []
    for match in _CALL.finditer(text):
        depth, start, segments = 1, match.end(), []
        i = start
        while i < len(text) and depth:
            ch = text[i]
            if ch in "([{":
                depth += 1
            elif ch in ")]}":
                depth -= 1
            if (ch == "," and depth == 1) or depth == 0:
                segments.append(text[start:i])
                start = i + 1
            i += 1
        keywords = [m.group(1) for s in segments if (m := re.match(r"\s*(\w+)\s*=(?!=)", s))]
        calls.append((match.group(1), keywords))
    return calls


def _callable(name: str):
    if name.startswith("mbs."):
        return getattr(_MAIN_SYSTEM, name[4:], None)
    if name.startswith("exu."):
        return getattr(exu, name[4:], None)
    return getattr(exu_utilities, name, None)


def _parameters(function) -> set[str] | None:
    try:
        return set(inspect.signature(function).parameters)
    except (TypeError, ValueError):  # a C++ function without a Python signature
        return None


@pytest.mark.parametrize("name", EXPECTED_NAMES)
def test_calls_use_existing_current_names(catalog, name):
    component = catalog.get(name)
    for where, text in (("context", component.context), ("example", component.example)):
        for callee, keywords in _calls(text):
            function = _callable(callee)
            if function is None:
                # names defined by the program itself (e.g. a user function) are not Exudyn's
                assert not callee.startswith(("mbs.", "exu.")), f"{where}: unknown {callee}"
                assert not callee.startswith("Create"), f"{where}: unknown {callee}"
                continue
            doc = inspect.getdoc(function) or ""
            assert not doc.startswith("DEPRECATED"), f"{where}: {callee} is deprecated"
            deprecated = _deprecated_arguments(function)
            parameters = _parameters(function)
            for keyword in keywords:
                assert keyword not in deprecated, f"{where}: {callee}({keyword}=...) is deprecated"
                if parameters is not None and "kwargs" not in parameters:
                    assert keyword in parameters, f"{where}: {callee} has no argument {keyword}"


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
    calls = dict(_calls("mbs.CreateMassPoint(referencePosition=[0, 0, 0], physicsMass=f(1, 2), gravity=g)"))
    assert calls["mbs.CreateMassPoint"] == ["referencePosition", "physicsMass", "gravity"]
    assert "physicsMass" in _deprecated_arguments(_MAIN_SYSTEM.CreateMassPoint)
    assert "bodyNumbers" in _deprecated_arguments(_MAIN_SYSTEM.CreateSpringDamper)
    assert "bodyNumbers" not in _deprecated_arguments(_MAIN_SYSTEM.CreateRollingDisc)
    assert "factorValue1" in _deprecated_arguments(exu_utilities.CoordinateConstraint)
    assert "sphereRadius" not in _deprecated_arguments(_MAIN_SYSTEM.CreateSphereTriangleContact)
