"""The design verdict of a level-4 answer, as pure functions (issue 42).

Four recorded stages, in this order: the program's ``DESIGN`` read statically (a literal dict, the
task's names, values inside their ranges), exactly one simulation in the program, the design
verdict (the reference built with the candidate's values meets the specification), and the
behaviour verdict (the candidate's own program moves like that reference; made by ``chain``).
A missing or non-literal ``DESIGN``, a value out of range, a second simulation: the model's
failure at a named stage, never an infrastructure error.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from meceng.syntax import parse

DESIGN_DECLARED = "design_declared"
ONE_SIMULATION = "one_simulation"
DESIGN_MET = "design_met"

#: Calls that run a simulation, whatever object they are called on (Exudyn's solver functions, the
#: low-level solver objects' own entry point).
SOLVER_CALLS = frozenset({"SolveDynamic", "SolveStatic", "SolveSystem", "SolveSteps"})
#: Exudyn's low-level solver classes: a program that makes one can simulate without a solver call above.
SOLVER_CLASSES = frozenset({"MainSolverImplicitSecondOrder", "MainSolverExplicit", "MainSolverStatic"})


@dataclass(frozen=True)
class Declared:
    """What ``DESIGN`` declares: ``values`` when it is valid, else ``error`` says why not."""

    values: dict[str, float] | None
    error: str | None = None
    line: int | None = None


def read_design(code: str, ranges: Mapping[str, tuple[float, float]]) -> Declared:
    """``DESIGN`` of ``code``: one top-level assignment of a literal dict holding exactly the
    names of ``ranges``, each a number inside its range, and never assigned again."""
    try:
        tree = parse(code)
    except SyntaxError as exc:
        return Declared(None, f"the program does not parse: {exc.msg} (line {exc.lineno})", exc.lineno)
    top = [node for node in tree.body if _assigns_design(node)]
    stores = [node for node in ast.walk(tree) if _stores_design(node)]
    if not top:
        where = f" (it is assigned on line {stores[0].lineno}, not at the program's top level)" if stores else ""
        return Declared(None, "no top-level DESIGN = {...} literal" + where)
    if len(stores) > 1:
        lines = ", ".join(str(getattr(node, "lineno", "?")) for node in stores)
        return Declared(None, f"DESIGN is assigned or changed more than once (lines {lines}): declare it once",
                        top[0].lineno)
    node = top[0]
    try:
        value = ast.literal_eval(node.value)  # type: ignore[attr-defined]
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return Declared(None, "DESIGN is not a literal: write the numbers themselves, not expressions or names",
                        node.lineno)
    if not isinstance(value, dict):
        return Declared(None, f"DESIGN is a {type(value).__name__}, not a dict of name -> value", node.lineno)
    missing = [name for name in ranges if name not in value]
    extra = [str(name) for name in value if name not in ranges]
    if missing or extra:
        said = "; ".join(part for part in (f"missing {', '.join(missing)}" if missing else "",
                                           f"not a design variable: {', '.join(extra)}" if extra else "") if part)
        return Declared(None, f"DESIGN must hold exactly {', '.join(ranges)} ({said})", node.lineno)
    values: dict[str, float] = {}
    for name, (low, high) in ranges.items():
        number = value[name]
        if isinstance(number, bool) or not isinstance(number, int | float) or not math.isfinite(number):
            return Declared(None, f"DESIGN[{name!r}] = {number!r} is not a finite number", node.lineno)
        if not low <= number <= high:
            return Declared(None, f"DESIGN[{name!r}] = {number:g} is outside its range [{low:g}, {high:g}]",
                            node.lineno)
        values[name] = float(number)
    return Declared(values, None, node.lineno)


def _assigns_design(node: ast.stmt) -> bool:
    if isinstance(node, ast.Assign):
        return any(isinstance(t, ast.Name) and t.id == "DESIGN" for t in node.targets)
    return isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.target.id == "DESIGN" \
        and node.value is not None


def _stores_design(node: ast.AST) -> bool:
    """A name or item store into DESIGN anywhere (an assignment, ``DESIGN[k] = ``, ``+=``, a loop target)."""
    if isinstance(node, ast.Name) and node.id == "DESIGN" and isinstance(node.ctx, ast.Store):
        return True
    if isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Store | ast.Del):
        return isinstance(node.value, ast.Name) and node.value.id == "DESIGN"
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        owner = node.func.value
        return (isinstance(owner, ast.Name) and owner.id == "DESIGN"
                and node.func.attr in {"update", "pop", "clear", "setdefault", "popitem", "__setitem__"})
    return False


@dataclass(frozen=True)
class Simulations:
    """The solver calls a program makes, read from its text."""

    count: int
    lines: tuple[int, ...]
    error: str | None  # why this is not exactly one simulation (None: it is)


def count_simulations(code: str) -> Simulations:
    """Exactly one simulation: one solver call in the text, not inside a loop (where it could run
    more than once), and no low-level solver object of its own."""
    try:
        tree = parse(code)
    except SyntaxError as exc:
        return Simulations(0, (), f"the program does not parse: {exc.msg} (line {exc.lineno})")
    calls: list[int] = []
    looped: list[int] = []
    solvers: list[int] = []

    def visit(node: ast.AST, in_loop: bool) -> None:
        if isinstance(node, ast.Call):
            name = _called_name(node.func)
            if name in SOLVER_CALLS:
                calls.append(node.lineno)
                if in_loop:
                    looped.append(node.lineno)
            elif name in SOLVER_CLASSES:
                solvers.append(node.lineno)
        loop = isinstance(node, ast.For | ast.AsyncFor | ast.While | ast.comprehension | ast.ListComp
                          | ast.SetComp | ast.DictComp | ast.GeneratorExp)
        for child in ast.iter_child_nodes(node):
            visit(child, in_loop or loop)

    visit(tree, False)
    lines = tuple(sorted(calls))
    if solvers:
        return Simulations(len(calls), lines, f"the program makes a solver object of its own (line {solvers[0]}): "
                                              "run the one simulation with mbs.SolveDynamic")
    if not calls:
        return Simulations(0, lines, "the program runs no simulation (no mbs.SolveDynamic call)")
    if looped:
        return Simulations(len(calls), lines, f"the solver call on line {looped[0]} is inside a loop: "
                                              "the program must run exactly one simulation")
    if len(calls) > 1:
        return Simulations(len(calls), lines, f"{len(calls)} solver calls (lines {', '.join(map(str, lines))}): "
                                              "the program must run exactly one simulation")
    return Simulations(1, lines, None)


def _called_name(func: ast.expr) -> str | None:
    if isinstance(func, ast.Attribute):
        return func.attr
    if isinstance(func, ast.Name):
        return func.id
    return None


@dataclass(frozen=True)
class DesignOutcome:
    """The design verdict: the spec's quantity of the reference built with the candidate's values."""

    passed: bool
    value: float | None
    target: float
    tolerance: float
    values: dict[str, float] | None
    quantity: str
    unit: str
    detail: str

    @property
    def margin(self) -> float | None:
        """The tolerance left, in tolerances (1: on target, 0: at the edge, < 0: outside)."""
        if self.value is None or not math.isfinite(self.value):
            return None
        return 1.0 - abs(self.value - self.target) / self.tolerance

    def to_json(self) -> dict[str, Any]:
        margin = self.margin
        return {"passed": self.passed, "value": self.value, "target": self.target, "tolerance": self.tolerance,
                "values": self.values, "margin": None if margin is None else round(margin, 4),
                "quantity": self.quantity, "unit": self.unit, "detail": self.detail}


def judge_design(value: float | None, target: float, tolerance: float, values: dict[str, float] | None,
                 quantity: str, unit: str) -> DesignOutcome:
    """Does the measured ``value`` meet ``target`` within ``tolerance`` (absolute)?"""
    if values is None:
        return DesignOutcome(False, None, target, tolerance, None, quantity, unit, "not judged: no valid DESIGN")
    if value is None or not math.isfinite(value):
        return DesignOutcome(False, value, target, tolerance, values, quantity, unit,
                             f"with these values the motion never shows {quantity} within the simulated time")
    off = value - target
    passed = abs(off) <= tolerance
    detail = (f"{quantity}: {value:.6g} {unit} against the target {target:g} {unit} ± {tolerance:.3g} "
              f"({100 * off / target:+.2f} %, {'inside' if passed else 'outside'} the ±"
              f"{100 * tolerance / abs(target):.3g} % tolerance)")
    return DesignOutcome(passed, value, target, tolerance, values, quantity, unit, detail)
