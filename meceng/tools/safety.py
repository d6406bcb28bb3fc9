"""Static safety check of LLM-written programs, before anything runs.

The runtime guard (an audit hook in the child, ``guard.py``) confines every write made through
Python to the scratch folder and refuses processes, sockets and native code whatever trick a
program uses; the executor adds the process limits and the network namespace. So this check
refuses only what that guard cannot contain, and leaves ordinary Python alone
(``values.remove(x)``, ``plt.savefig``, ``print(exu.__version__)``). The remaining rules, and why
each has to be static:

1. **Imports from an allow-list** (the simulation stack and harmless standard modules): the hook
   cannot refuse reading files without refusing imports, so modules that read files or reach
   into the interpreter (``os``, ``pathlib``, ``io``, ``pickle``, ``importlib``, ``inspect``…)
   stay out.
2. **Builtins that read files or run code from strings** (``open``, ``exec``, ``eval``,
   ``compile``, ``__import__``, ``getattr``…): reading, and names built from strings that would
   get around rules 1, 3 and 5.
3. **Interpreter internals**: dunder attributes other than a few harmless ones (``__version__``,
   ``__name__``, ``__doc__``, ``__init__``…) lead from any object to the builtins
   (``().__class__.__bases__[0].__subclasses__()``).
4. **File readers of NumPy and SciPy** (``np.load``, ``np.loadtxt``, ``np.fromfile``,
   ``scipy.io.loadmat``…): reading, which the hook allows.
5. **Exudyn's native file writers** (``exu.SetWriteToFile``): written in C++, outside the hook's
   sight. (Sensor files, the other native writer, are confined to the scratch folder by the harness
   before it solves.)

It works on the syntax tree, so string tricks in comments do not matter, and it refuses with a
reason a person can read in the run record.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from meceng.syntax import parse

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

#: Builtins that read files, run code from strings or escape the namespace (rule 2).
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

#: Dunder attributes that reveal nothing of the interpreter (rule 3).
HARMLESS_DUNDERS = frozenset({"__version__", "__name__", "__qualname__", "__doc__", "__init__", "__module__",
                              "__len__", "__repr__", "__str__"})

#: File readers of the allowed numerical modules (rule 4): refused on any object, since these names
#: mean reading a file wherever they appear in a simulation program; ``load`` only on NumPy itself.
FILE_READERS = frozenset({"loadtxt", "fromfile", "genfromtxt", "memmap", "fromregex", "loadmat", "DataSource"})
NUMPY_READERS = frozenset({"load"})

#: Exudyn functions that write files from C++ (rule 5).
NATIVE_WRITERS = frozenset({"SetWriteToFile"})


@dataclass(frozen=True)
class SafetyVerdict:
    ok: bool
    reason: str = ""
    line: int | None = None

    def __bool__(self) -> bool:
        return self.ok


def check_program(source: str, allowed_imports: frozenset[str] = ALLOWED_IMPORT_ROOTS) -> SafetyVerdict:
    """Refuse programs that import outside the allow-list, read files, run code from strings,
    reach into the interpreter or write files natively (the module docstring says why these)."""
    try:
        tree = parse(source)
    except SyntaxError as exc:
        return SafetyVerdict(False, f"syntax error: {exc.msg}", exc.lineno)
    numpy_names = _numpy_aliases(tree)
    for node in ast.walk(tree):
        verdict = _check_node(node, allowed_imports, numpy_names)
        if not verdict.ok:
            return verdict
    return SafetyVerdict(True)


def _numpy_aliases(tree: ast.AST) -> frozenset[str]:
    """The names the program binds to NumPy (``import numpy as np``, ``import numpy``)."""
    names = {"numpy"}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.asname or a.name for a in node.names if a.name == "numpy")
    return frozenset(names)


def _check_node(node: ast.AST, allowed_imports: frozenset[str], numpy_names: frozenset[str]) -> SafetyVerdict:
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
        for alias in node.names:
            if alias.name in FILE_READERS | NATIVE_WRITERS or (root == "numpy" and alias.name in NUMPY_READERS):
                return SafetyVerdict(False, f"import of '{alias.name}' is not allowed (reads or writes files)", line)
    elif isinstance(node, ast.Name) and node.id in FORBIDDEN_NAMES:
        return SafetyVerdict(False, f"use of '{node.id}' is not allowed (file access or dynamic code)", line)
    elif isinstance(node, ast.Attribute):
        if node.attr.startswith("__") and node.attr.endswith("__") and node.attr not in HARMLESS_DUNDERS:
            return SafetyVerdict(False, f"access to interpreter internals '{node.attr}' is not allowed", line)
        if node.attr in FILE_READERS or (node.attr in NUMPY_READERS and isinstance(node.value, ast.Name)
                                         and node.value.id in numpy_names):
            return SafetyVerdict(False, f"call of '.{node.attr}' is not allowed (reads files)", line)
        if node.attr in NATIVE_WRITERS:
            return SafetyVerdict(False, f"call of '.{node.attr}' is not allowed (writes files outside the sandbox)",
                                 line)
    return SafetyVerdict(True)
