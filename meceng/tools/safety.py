"""Static safety check of LLM-written programs, before anything runs.

This is the first line of defence, not the only one (the executor isolates the process as well).
It works on the syntax tree, so string tricks in comments do not matter, and it refuses with a
reason a person can read in the run record.

Policy: imports come from an allow-list (Exudyn, NumPy and harmless standard modules); calls that
read or write files, run code from strings or reach into interpreter internals are refused.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

ALLOWED_IMPORT_ROOTS = frozenset(
    {
        "exudyn",
        "numpy",
        "math",
        "cmath",
        "copy",
        "itertools",
        "functools",
        "collections",
        "typing",
        "dataclasses",
        "enum",
        "fractions",
        "decimal",
        "random",
        "time",
        "scipy",
        "matplotlib",
        "__future__",
    }
)

#: Part programs (level 3a) also build geometry and meshes.
PART_IMPORT_ROOTS = ALLOWED_IMPORT_ROOTS | {"netgen", "ngsolve"}

#: Builtins that execute code, open files or escape the namespace.
FORBIDDEN_NAMES = frozenset(
    {
        "open",
        "exec",
        "eval",
        "compile",
        "__import__",
        "globals",
        "locals",
        "vars",
        "breakpoint",
        "input",
        "memoryview",
        "getattr",
        "setattr",
        "delattr",
        "__builtins__",
        "__loader__",
        "__spec__",
    }
)

#: Method names that write files (NumPy, pandas, matplotlib, pathlib, Exudyn exporters).
FORBIDDEN_ATTRIBUTES = frozenset(
    {
        "savefig",
        "save",
        "savez",
        "savez_compressed",
        "savetxt",
        "tofile",
        "to_csv",
        "write_text",
        "write_bytes",
        "unlink",
        "rmdir",
        "mkdir",
        "remove",
        "system",
        "popen",
        "load",
        "loadtxt",
        "fromfile",
        "genfromtxt",
        "ExportSolutionToFile",
    }
)


@dataclass(frozen=True)
class SafetyVerdict:
    ok: bool
    reason: str = ""
    line: int | None = None

    def __bool__(self) -> bool:
        return self.ok


def check_program(source: str, allowed_imports: frozenset[str] = ALLOWED_IMPORT_ROOTS) -> SafetyVerdict:
    """Refuse programs that import outside the allow-list or touch files and internals."""
    try:
        tree = ast.parse(source)
    except SyntaxError as exc:
        return SafetyVerdict(False, f"syntax error: {exc.msg}", exc.lineno)
    for node in ast.walk(tree):
        verdict = _check_node(node, allowed_imports)
        if not verdict.ok:
            return verdict
    return SafetyVerdict(True)


def _check_node(node: ast.AST, allowed_imports: frozenset[str]) -> SafetyVerdict:
    line = getattr(node, "lineno", None)
    if isinstance(node, ast.Import):
        for alias in node.names:
            root = alias.name.split(".")[0]
            if root not in allowed_imports:
                return SafetyVerdict(False, f"import of module '{alias.name}' is not allowed", line)
    elif isinstance(node, ast.ImportFrom):
        root = (node.module or "").split(".")[0]
        if node.level or root not in allowed_imports:
            return SafetyVerdict(False, f"import from module '{node.module}' is not allowed", line)
    elif isinstance(node, ast.Name) and node.id in FORBIDDEN_NAMES:
        return SafetyVerdict(False, f"use of '{node.id}' is not allowed (file access or dynamic code)", line)
    elif isinstance(node, ast.Attribute):
        if node.attr.startswith("__") and node.attr.endswith("__"):
            return SafetyVerdict(False, f"access to interpreter internals '{node.attr}' is not allowed", line)
        if node.attr in FORBIDDEN_ATTRIBUTES:
            return SafetyVerdict(False, f"call of '.{node.attr}' is not allowed (file or system access)", line)
    return SafetyVerdict(True)
