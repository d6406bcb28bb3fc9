"""Static check of the Exudyn calls a text shows (a catalog's context and example, a task
description): every function must exist in the installed Exudyn, every keyword must be one of its
arguments and none may be deprecated. Shared by the catalog test and the prompt lint.

Exudyn documents deprecated and refused arguments in the docstrings of the Create functions and the
item classes ('deprecated name of ...', 'not accepted'); C++ functions without a Python signature
are checked for existence only.
"""

from __future__ import annotations

import inspect
import re
from typing import Any

import exudyn as exu
import exudyn.utilities as exu_utilities
from exudyn.FEM import FEMinterface

CALL = re.compile(r"(?<![\w.])(mbs\.\w+|exu\.\w+|fem\w*\.\w+|[A-Z]\w*)\(")
MAIN_SYSTEM = exu.SystemContainer().AddSystem()
_ARGUMENT_DOC = re.compile(r"^\s*(\w+): (.*)$", re.MULTILINE)


def deprecated_arguments(function: Any) -> set[str]:
    """Arguments the docstring calls deprecated or not accepted."""
    doc = inspect.getdoc(function) or ""
    return {name for name, text in _ARGUMENT_DOC.findall(doc)
            if "deprecated" in text.lower() or text.startswith("not accepted")}


def calls(text: str) -> list[tuple[str, list[str]]]:
    """(callee, top-level keyword names) of every call ``name(...)`` in the text."""
    found = []
    for match in CALL.finditer(text):
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
        found.append((match.group(1), keywords))
    return found


def resolve(name: str) -> Any:
    """The installed function a callee names, or None."""
    if name.startswith("mbs."):
        return getattr(MAIN_SYSTEM, name[4:], None)
    if name.startswith("exu."):
        return getattr(exu, name[4:], None)
    if name.startswith("fem"):
        return getattr(FEMinterface, name.partition(".")[2], None)
    return getattr(exu_utilities, name, None)


def parameters(function: Any) -> set[str] | None:
    try:
        return set(inspect.signature(function).parameters)
    except (TypeError, ValueError):  # a C++ function without a Python signature
        return None


def call_problems(text: str) -> list[str]:
    """What is wrong with the Exudyn calls in ``text``: unknown or deprecated functions, unknown or
    deprecated keywords. Capitalised names Exudyn does not have are the program's own or another
    library's (netgen.occ) and are left alone, except ``Create...``, which only Exudyn has."""
    problems = []
    for callee, keywords in calls(text):
        function = resolve(callee)
        if function is None:
            if callee.startswith(("mbs.", "exu.", "fem", "Create")):
                problems.append(f"unknown {callee}")
            continue
        doc = inspect.getdoc(function) or ""
        if doc.startswith("DEPRECATED"):
            problems.append(f"{callee} is deprecated")
        deprecated = deprecated_arguments(function)
        known = parameters(function)
        for keyword in keywords:
            if keyword in deprecated:
                problems.append(f"{callee}({keyword}=...) is deprecated")
            elif known is not None and "kwargs" not in known and keyword not in known:
                problems.append(f"{callee} has no argument {keyword}")
    return problems
