"""The layout docs/architecture.md draws holds in the code: no import circle anywhere in
``meceng/``, each room imports only the rooms the picture allows, no module past 350 lines.

Imports inside functions count too: a lazy import is still a dependency."""

from __future__ import annotations

import ast
from pathlib import Path

import networkx as nx

PACKAGE = Path(__file__).resolve().parents[1] / "meceng"
#: room -> the rooms it may import (helpers at the package's top level are open to every room)
ALLOWED: dict[str, set[str]] = {
    "tasks": set(),
    "tools": set(),
    "llm": set(),
    "catalog": {"tasks"},
    "inspect": {"catalog"},
    "eval": {"tools"},  # the Execution type only (checked below)
    "agents": {"inspect", "catalog", "llm", "tools", "tasks", "eval"},  # eval: compare's agreement of two programs
    "pipeline": {"agents", "inspect", "catalog", "llm", "eval", "tools", "tasks"},
    "viewer": {"pipeline", "eval", "inspect", "tasks"},
    "sweeps": {"pipeline", "agents", "llm", "tools", "tasks"},  # agents: the prompt variants' names
    "report": {"eval"},
}
#: the package root keeps its face, ``__main__`` and the helpers every room shares; nothing else
ROOT_MODULES = {"meceng", "meceng.__main__", "meceng.logs", "meceng.jsonl", "meceng.syntax", "meceng.progress"}
HELPERS = {"meceng.logs", "meceng.jsonl", "meceng.syntax", "meceng.progress"}
MAX_LINES = 350


def _modules() -> dict[str, Path]:
    modules = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.with_suffix("").relative_to(PACKAGE.parent).parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        modules[name] = path
    return modules


def _graph() -> nx.DiGraph:
    modules = _modules()
    graph = nx.DiGraph()
    for name, path in modules.items():
        graph.add_node(name)
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join([*up, *([node.module] if node.module else [])])
                targets = [base] + [f"{base}.{alias.name}" for alias in node.names]
            else:
                continue
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target.startswith("meceng") and target != name:
                    graph.add_edge(name, target)
    return graph


def _room(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or ((PACKAGE / parts[-1]).is_dir() and len(parts) == 2) else None


def test_no_import_circle() -> None:
    circles = [sorted(c) for c in nx.strongly_connected_components(_graph()) if len(c) > 1]
    assert circles == []


def test_rooms_import_only_what_the_architecture_allows() -> None:
    wrong = []
    for source, target in _graph().edges:
        room, other = _room(source), _room(target)
        if room not in ALLOWED or other is None or other == room or target in HELPERS:
            continue
        if other not in ALLOWED[room] or (room == "eval" and target != "meceng.tools.execution"):
            wrong.append(f"{source} -> {target}")
    assert wrong == []


def test_the_package_root_holds_only_its_face_and_shared_helpers() -> None:
    root = {name for name in _modules() if name.count(".") <= 1 and not (PACKAGE / name.rpartition(".")[2]).is_dir()}
    assert root == ROOT_MODULES


def test_no_module_past_350_lines() -> None:
    long = {name: n for name, path in _modules().items() if (n := len(path.read_text().splitlines())) > MAX_LINES}
    assert long == {}
