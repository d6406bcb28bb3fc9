"""Drafts for the repair benchmark: a task's ground-truth program with one realistic modelling error.

Each fault is one edit of the program's text at an expression the syntax tree locates, of a kind
models make — a sign, an axis, a value off by a decimal point, the neighbouring parameter, side
lengths in the wrong order, steel's density for aluminium, a cut left out — and carries the paper's
error category (Table 5) it should produce, or for a part the stages it should fail. Which of
several places a fault hits is drawn from the instance's seed, so every instance has its own
drafts and the same ones every time. Whether a draft really fails, and with which category, is the
grader's to say (``pipeline/drafts.py``); this module only writes them.
"""

from __future__ import annotations

import ast
import random
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from meceng.syntax import parse
from meceng.tasks.base import TaskInstance

#: For parts the grader gives stages, not categories: the stages a part fault should fail first.
PART_EXPECTED: dict[str, tuple[str, ...]] = {
    "wrong material": ("material_match",),
    "wrong dimension": ("mass_match", "mesh_match"),
    "missing feature": ("mass_match", "mesh_match"),
    "interface on the wrong face": ("interface_name_match", "mesh_match", "eigenfrequencies_match"),
}


@dataclass(frozen=True)
class Draft:
    """A program with one seeded fault: ``label`` is the paper's category (or the part fault's
    name), ``fault`` says in words what was changed."""

    id: str
    label: str
    fault: str
    program: str
    line: int
    graded: dict[str, Any] | None = None  # the grader's verdict on the draft (first failure, categories)

    def to_json(self) -> dict[str, Any]:
        return {"id": self.id, "label": self.label, "fault": self.fault, "line": self.line, "program": self.program,
                **({"graded": self.graded} if self.graded is not None else {})}


@dataclass(frozen=True)
class _Edit:
    start: int
    end: int
    text: str
    line: int


Operator = Callable[[str, ast.Module, random.Random], tuple[_Edit, str] | None]


def _offsets(source: str) -> list[int]:
    starts, total = [0], 0
    for line in source.splitlines(keepends=True):
        total += len(line.encode())
        starts.append(total)
    return starts


def _span(source: str, node: ast.AST) -> tuple[int, int]:
    """Character offsets of a node (ast gives UTF-8 byte columns)."""
    starts = _offsets(source)
    data = source.encode()
    begin = starts[node.lineno - 1] + node.col_offset  # type: ignore[attr-defined]
    end = starts[node.end_lineno - 1] + node.end_col_offset  # type: ignore[attr-defined]
    return len(data[:begin].decode()), len(data[:end].decode())


def _replace(source: str, node: ast.AST, text: str) -> _Edit:
    start, end = _span(source, node)
    return _Edit(start, end, text, node.lineno)  # type: ignore[attr-defined]


def _calls(tree: ast.Module, prefix: str = "Create") -> Iterator[ast.Call]:
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr.startswith(prefix):
            yield node


def _keywords(tree: ast.Module, names: tuple[str, ...], functions: tuple[str, ...] | None = None
              ) -> list[tuple[ast.Call, ast.keyword]]:
    out = []
    for call in _calls(tree):
        if functions is not None and call.func.attr not in functions:  # type: ignore[attr-defined]
            continue
        out.extend((call, kw) for kw in call.keywords if kw.arg in names)
    return out


def _segment(source: str, node: ast.AST) -> str:
    start, end = _span(source, node)
    return source[start:end]


def _list_items(node: ast.AST) -> list[ast.expr] | None:
    return list(node.elts) if isinstance(node, ast.List | ast.Tuple) else None


def _is_zero(source: str, node: ast.AST) -> bool:
    try:  # the node itself, not its text: a parse here would race the harness's parses in other threads
        return float(ast.literal_eval(node)) == 0.0
    except (ValueError, SyntaxError, TypeError):
        return False


def _pick(rng: random.Random, options: list) -> object | None:
    return options[rng.randrange(len(options))] if options else None


# ----------------------------------------------------------------------------- rigid faults

def _flip_sign(names: tuple[str, ...], what: str) -> Operator:
    def op(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
        options = []
        for call, kw in _keywords(tree, names):
            items = _list_items(kw.value)
            for item in items or []:
                if not _is_zero(source, item):
                    options.append((call, kw, item))
        chosen = _pick(rng, options)
        if chosen is None:
            return None
        call, kw, item = chosen
        text = _segment(source, item)
        flipped = text[1:].lstrip() if text.startswith("-") else f"-{text}" if text.isidentifier() else f"-({text})"
        return _replace(source, item, flipped), f"{what}: the sign of {kw.arg}'s component {text!r} flipped"
    return op


def _swap_components(names: tuple[str, ...], functions: tuple[str, ...] | None, what: str) -> Operator:
    def op(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
        options = []
        for call, kw in _keywords(tree, names, functions):
            items = _list_items(kw.value)
            if items and len(items) >= 2:
                texts = [_segment(source, i) for i in items]
                pairs = [(a, b) for a in range(len(texts)) for b in range(a + 1, len(texts)) if texts[a] != texts[b]]
                if pairs:
                    options.append((call, kw, items, texts, pairs))
        # the last body or joint created is the one a model is likeliest to get wrong ("the third body")
        chosen = options[-1] if options and rng.random() < 0.5 else _pick(rng, options)
        if chosen is None:
            return None
        call, kw, items, texts, pairs = chosen
        a, b = pairs[rng.randrange(len(pairs))]
        texts[a], texts[b] = texts[b], texts[a]
        bracket = "[{}]" if isinstance(kw.value, ast.List) else "({})"
        return (_replace(source, kw.value, bracket.format(", ".join(texts))),
                f"{what}: two components of {call.func.attr}'s {kw.arg} swapped")  # type: ignore[attr-defined]
    return op


def _scale(names: tuple[str, ...], factor: str, what: str) -> Operator:
    def op(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
        chosen = _pick(rng, [(c, kw) for c, kw in _keywords(tree, names) if not _is_zero(source, kw.value)])
        if chosen is None:
            return None
        call, kw = chosen
        text = _segment(source, kw.value)
        return _replace(source, kw.value, f"({text}) * {factor}"), f"{what}: {kw.arg} of {call.func.attr} x {factor}"  # type: ignore[attr-defined]
    return op


def _neighbour(name: str, other: str, what: str) -> Operator:
    """A value taken from the neighbouring parameter of the same call (stiffness <- damping)."""
    def op(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
        options = []
        for call in _calls(tree):
            given = {kw.arg: kw for kw in call.keywords}
            if name in given and other in given and _segment(source, given[name].value) != _segment(
                    source, given[other].value) and not _is_zero(source, given[other].value):
                options.append((call, given[name], given[other]))
        chosen = _pick(rng, options)
        if chosen is None:
            return None
        call, mine, theirs = chosen
        return (_replace(source, mine.value, _segment(source, theirs.value)),
                f"{what}: {call.func.attr}'s {name} given the value of its {other}")  # type: ignore[attr-defined]
    return op


def _side_lengths(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
    options = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")) == "InertiaCuboid":
            for kw in node.keywords:
                items = _list_items(kw.value) if kw.arg == "sideLengths" else None
                if items and len({_segment(source, i) for i in items}) > 1:
                    options.append((kw, items))
    chosen = _pick(rng, options)
    if chosen is None:
        return None
    kw, items = chosen
    texts = [_segment(source, i) for i in items]
    turned = texts[1:] + texts[:1]
    return (_replace(source, kw.value, "[" + ", ".join(turned) + "]"),
            "inertia: InertiaCuboid's side lengths in the wrong order (the box turned)")


RIGID_FAULTS: tuple[tuple[str, str, Operator], ...] = (
    ("mass", "inertia and mass", _scale(("mass",), "10", "a decimal point off")),
    ("side-lengths", "inertia and mass", _side_lengths),
    ("gravity-sign", "gravity and load", _flip_sign(("gravity",), "gravity up instead of down")),
    ("load-sign", "gravity and load", _flip_sign(("loadVector",), "load reversed")),
    ("velocity-sign", "initial velocities", _flip_sign(("initialVelocity", "initialAngularVelocity"),
                                                       "initial velocity reversed")),
    ("position-axes", "rigid body configuration",
     _swap_components(("referencePosition",), ("CreateMassPoint", "CreateRigidBody"), "axis mix-up")),
    ("stiffness-damping", "connector/constraint", _neighbour("stiffness", "damping", "the neighbouring parameter")),
    # Exudyn 1.13's Create*Joint turns the joint's markers to its axis: an axis is a marker's frame
    ("joint-axis", "kinematics/marker",
     _swap_components(("axis",), ("CreateRevoluteJoint", "CreatePrismaticJoint"), "joint axis along the wrong axis")),
    ("joint-position", "kinematics/marker",
     _swap_components(("position",), ("CreateRevoluteJoint", "CreateSphericalJoint", "CreatePrismaticJoint",
                                      "CreateGenericJoint"), "joint at the wrong point")),
)


# ----------------------------------------------------------------------------- part faults

def _material(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
    for call in _calls(tree, "ImportMeshFromNGsolve"):
        for kw in call.keywords:
            if kw.arg == "density":
                try:
                    value = float(ast.literal_eval(kw.value))
                except (ValueError, SyntaxError, TypeError):
                    return _replace(source, kw.value, "2700.0"), "material: aluminium's density"
                other = 2700.0 if abs(value - 2700.0) > 1.0 else 7850.0
                return _replace(source, kw.value, repr(other)), f"material: density {other:g} for {value:g}"
    return None


_DIMENSIONS = ("length", "width", "height", "radius", "thickness", "diameter", "span", "depth")


def _dimension(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
    options = [node for node in tree.body if isinstance(node, ast.Assign) and len(node.targets) == 1
               and isinstance(node.targets[0], ast.Name) and any(d in node.targets[0].id for d in _DIMENSIONS)
               and isinstance(node.value, ast.Constant) and isinstance(node.value.value, float)]
    chosen = _pick(rng, options)
    if chosen is None:
        return None
    name = chosen.targets[0].id  # type: ignore[attr-defined]
    factor = 2.0 if "radius" in name else 1.25
    value = chosen.value.value * factor  # type: ignore[attr-defined]
    why = "the diameter for the radius" if factor == 2.0 else "a dimension 25 % off"
    return _replace(source, chosen.value, repr(round(value, 9))), f"dimension: {name} = {value:.6g} ({why})"


def _missing_feature(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
    options = [node for node in ast.walk(tree) if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub)
               and isinstance(node.right, ast.Call) and getattr(node.right.func, "id", "") in ("Cylinder", "Box")]
    chosen = _pick(rng, options)
    if chosen is None:
        return None
    cut = _segment(source, chosen.right)
    return _replace(source, chosen, _segment(source, chosen.left)), f"feature: the cut {cut[:60]} left out"


def _wrong_face(source: str, tree: ast.Module, rng: random.Random) -> tuple[_Edit, str] | None:
    options = [node for node in ast.walk(tree) if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
               and node.func.attr in ("Min", "Max") and isinstance(node.func.value, ast.Attribute)
               and node.func.value.attr == "faces"]
    chosen = _pick(rng, options)
    if chosen is None:
        return None
    other = "Max" if chosen.func.attr == "Min" else "Min"  # type: ignore[attr-defined]
    text = _segment(source, chosen)
    return (_replace(source, chosen, text.replace(f".{chosen.func.attr}(", f".{other}(")),  # type: ignore[attr-defined]
            f"interface: faces.{other} where faces.{chosen.func.attr} was meant")  # type: ignore[attr-defined]


PART_FAULTS: tuple[tuple[str, str, Operator], ...] = (
    ("material", "wrong material", _material),
    ("dimension", "wrong dimension", _dimension),
    ("feature", "missing feature", _missing_feature),
    ("face", "interface on the wrong face", _wrong_face),
)


def candidate_drafts(instance: TaskInstance) -> list[Draft]:
    """Every fault this instance's ground truth admits, one draft each (levels 1, 2 and 3a)."""
    if instance.kind == "assembly":
        return []
    source = instance.reference_program
    tree = parse(source)
    faults = PART_FAULTS if instance.kind == "part" else RIGID_FAULTS
    drafts = []
    for name, label, operator in faults:
        rng = random.Random(f"{instance.key}:{name}")
        made = operator(source, tree, rng)
        if made is None:
            continue
        edit, fault = made
        program = source[:edit.start] + edit.text + source[edit.end:]
        if program != source:
            body, dropped = without_header(program)
            drafts.append(Draft(name, label, fault, body, edit.line - dropped))
    return drafts


def without_header(program: str) -> tuple[str, int]:
    """The program without the ground truth's leading comment block (it names itself the
    reference); returns the text and the number of lines dropped."""
    lines = program.splitlines(keepends=True)
    dropped = 0
    while dropped < len(lines) and (lines[dropped].startswith("#") or not lines[dropped].strip()):
        dropped += 1
    return "".join(lines[dropped:]), dropped
