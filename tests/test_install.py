"""The install is complete: every module of the package imports, every module a graded program may
import is there, and the command line answers. A dependency missing from pyproject.toml fails
here at once, with its name, instead of as a ground truth that fails for every user."""

from __future__ import annotations

import importlib
import pkgutil
import subprocess
import sys

import pytest

import meceng
from meceng.tools.safety import PART_IMPORT_ROOTS


def _modules() -> list[str]:
    return sorted(m.name for m in pkgutil.walk_packages(meceng.__path__, prefix="meceng."))


def test_the_package_has_its_modules() -> None:
    names = _modules()
    assert "meceng.cli" in names and "meceng.tools.part_runner" in names and len(names) > 100


@pytest.mark.parametrize("name", _modules())
def test_every_module_imports(name: str) -> None:
    importlib.import_module(name)


# what the part runner and the FE reduction use at run time, beyond the allow-list's roots
RUNTIME_MODULES = ("exudyn.FEM", "exudyn.utilities", "netgen.occ", "ngsolve", "scipy.sparse.linalg", "scipy.linalg",
                   "pymeshlab", "matplotlib.pyplot")


@pytest.mark.parametrize("name", sorted(PART_IMPORT_ROOTS - {"__future__"}) + list(RUNTIME_MODULES))
def test_what_graded_programs_import_is_installed(name: str) -> None:
    importlib.import_module(name)


def test_version_command_names_the_simulation_stack() -> None:
    proc = subprocess.run([sys.executable, "-m", "meceng", "--version"], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith(f"meceng {meceng.__version__} (exudyn 1.13.")
    assert "not installed" not in proc.stdout
