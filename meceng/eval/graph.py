"""The system graph of an Exudyn model and its comparison (paper section 3.2).

Items (nodes, objects, markers, loads, and optionally sensors) are graph nodes labelled with
their type; index references between items are directed edges labelled with the referring field
(``nodeNumber``, ``markerNumbers`` ...), so the graph does not depend on the order in which the
items were added. Every other parameter becomes an annotation, except names, user functions,
graphics / visualization and file settings.

Comparison has three levels, each only if the previous one passed: counts (nodes, edges, types),
topology (isomorphism by item type) and annotations (isomorphism by type + annotation values).
Plain VF2 explodes on symmetric systems; VF2++ with hashable labels does not.
"""

from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field
from typing import Any

import networkx as nx

from meceng.eval.categories import categorize
from meceng.eval.topology import TopologyCauses, topology_causes

KIND_TYPE_KEY = {"nodes": "nodeType", "objects": "objectType", "markers": "markerType",
                 "loads": "loadType", "sensors": "sensorType"}

#: Which kind of item a reference field points at.
REF_TARGET = {
    "nodeNumber": "nodes", "nodeNumbers": "nodes",
    "bodyNumber": "objects", "bodyNumbers": "objects", "objectNumber": "objects", "objectNumbers": "objects",
    "markerNumber": "markers", "markerNumbers": "markers",
    "loadNumber": "loads", "loadNumbers": "loads",
    "sensorNumber": "sensors", "sensorNumbers": "sensors",
}

IGNORED_KEYS = frozenset({"name", "fileName", "writeToFile", "storeInternal", "graphicsData"})

#: Significant digits used in hash labels; values are compared with ``rtol`` afterwards.
LABEL_DIGITS = 8


@dataclass(frozen=True)
class GraphTolerance:
    rtol: float = 1e-6
    atol: float = 1e-10
    max_nodes: int = 5000
    include_sensors: bool = False
    timeout_s: float = 120.0


@dataclass
class GraphComparison:
    counts_match: bool
    topology_match: bool | None
    content_match: bool | None
    detail: str
    differences: list[dict[str, Any]] = field(default_factory=list)
    error_categories: list[str] = field(default_factory=list)
    topology: TopologyCauses | None = None  # why the topology differs, when it does


def is_ignored(key: str) -> bool:
    return key in IGNORED_KEYS or key.startswith("V") or "UserFunction" in key


def build_graph(items: dict[str, list[dict[str, Any]]], include_sensors: bool = False) -> nx.DiGraph:
    """Items -> directed graph; graph node ids are (kind, index) and carry type + annotations."""
    graph = nx.DiGraph()
    kinds = [k for k in KIND_TYPE_KEY if include_sensors or k != "sensors"]
    for kind in kinds:
        for index, item in enumerate(items.get(kind, [])):
            item_type = f"{kind[:-1]}:{item.get(KIND_TYPE_KEY[kind], '?')}"
            annotations = {k: v for k, v in item.items()
                           if k != KIND_TYPE_KEY[kind] and k not in REF_TARGET and not is_ignored(k)}
            graph.add_node((kind, index), type=item_type, annotations=annotations)
    for kind in kinds:
        for index, item in enumerate(items.get(kind, [])):
            for key, value in item.items():
                target_kind = REF_TARGET.get(key)
                if target_kind is None or (target_kind == "sensors" and not include_sensors):
                    continue
                targets = value if isinstance(value, list) else [value]
                for slot, target in enumerate(targets):
                    if isinstance(target, int) and target >= 0 and (target_kind, target) in graph:
                        graph.add_edge((kind, index), (target_kind, target), field=key, slot=slot)
    for (kind, _), data in graph.nodes(data=True):
        data["label"] = data["type"] + "|" + _hash_annotations(data["annotations"])
        # partial labels: pair items by geometry when physics differs, and the other way round,
        # so that the differences of a wrong answer are reported between the right partners
        geometric = kind in ("nodes", "markers")
        data["label_geometry"] = data["label"] if geometric else data["type"]
        data["label_physics"] = data["type"] if geometric else data["label"]
    return graph


def _canonical(value: Any) -> Any:
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, int | float):
        x = float(value)
        if not math.isfinite(x):
            return str(x)
        if abs(x) < 1e-12:
            return 0.0
        return float(f"{x:.{LABEL_DIGITS}g}")
    if isinstance(value, list | tuple):
        return tuple(_canonical(v) for v in value)
    if isinstance(value, dict):
        return tuple(sorted((k, _canonical(v)) for k, v in value.items()))
    return str(value)


def _hash_annotations(annotations: dict[str, Any]) -> str:
    return repr(sorted((k, _canonical(v)) for k, v in annotations.items()))


def values_close(a: Any, b: Any, tol: GraphTolerance) -> bool:
    if isinstance(a, bool) or isinstance(b, bool) or a is None or b is None or isinstance(a, str):
        return a == b
    if isinstance(a, int | float) and isinstance(b, int | float):
        return math.isclose(float(a), float(b), rel_tol=tol.rtol, abs_tol=tol.atol)
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(values_close(x, y, tol) for x, y in zip(a, b, strict=True))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(values_close(a[k], b[k], tol) for k in a)
    return a == b


def compare_graphs(
    candidate: dict[str, list[dict[str, Any]]],
    reference: dict[str, list[dict[str, Any]]],
    tol: GraphTolerance | None = None,
) -> GraphComparison:
    """Compare an LLM system with the ground truth on the paper's three graph levels."""
    tol = tol or GraphTolerance()
    g_cand = build_graph(candidate, tol.include_sensors)
    g_ref = build_graph(reference, tol.include_sensors)

    # level 1: counts
    type_cand = Counter(d["type"] for _, d in g_cand.nodes(data=True))
    type_ref = Counter(d["type"] for _, d in g_ref.nodes(data=True))
    if g_cand.number_of_nodes() != g_ref.number_of_nodes() or g_cand.number_of_edges() != g_ref.number_of_edges():
        causes = topology_causes(g_cand, g_ref, candidate, reference)
        detail = (f"item/reference counts differ: {g_cand.number_of_nodes()} items and "
                  f"{g_cand.number_of_edges()} references vs {g_ref.number_of_nodes()} and "
                  f"{g_ref.number_of_edges()} in the ground truth; {_type_diff(type_cand, type_ref)}; {causes.text()}")
        return GraphComparison(False, False, False, detail, topology=causes)
    if type_cand != type_ref:
        causes = topology_causes(g_cand, g_ref, candidate, reference)
        return GraphComparison(False, False, False, f"item types differ: {_type_diff(type_cand, type_ref)}; "
                               f"{causes.text()}", topology=causes)
    if g_ref.number_of_nodes() > tol.max_nodes:
        return GraphComparison(True, None, None, f"graph too large to compare ({g_ref.number_of_nodes()} items)")

    # level 2: topology by type. Items added in the same order as in the ground truth (the usual
    # case) pair up as written, an O(E) check; VF2++ is only needed when the order differs.
    identity = {n: n for n in g_cand.nodes}
    same_order = _is_type_isomorphism(g_cand, g_ref, identity)
    if same_order and _annotations_match(g_cand, g_ref, identity, tol):
        return GraphComparison(True, True, True, "systems are identical")

    # level 3 first where possible: a labelled isomorphism (type + rounded annotations) is found
    # fast even on symmetric structures, where a type-only search can take minutes
    try:
        full = _isomorphism(g_cand, g_ref, "label", tol.timeout_s)
        if full is not None and _annotations_match(g_cand, g_ref, full, tol):
            return GraphComparison(True, True, True, "systems are identical")
        mapping = identity if same_order else _partner_mapping(g_cand, g_ref, tol.timeout_s)
    except ComparisonTimeout:
        return GraphComparison(True, False, False, f"graph comparison timed out after {tol.timeout_s:g} s")
    if mapping is None:
        causes = topology_causes(g_cand, g_ref, candidate, reference)
        return GraphComparison(True, False, False, f"topology differs (connections between items); {causes.text()}",
                               topology=causes)
    differences = _differences(g_cand, g_ref, mapping, tol)
    if not differences:
        # hash labels split values that are equal within tolerance: accept the type mapping
        return GraphComparison(True, True, True, "systems are identical within tolerance")
    categories = sorted({d["category"] for d in differences})
    first = differences[0]
    detail = (f"{len(differences)} parameter difference(s), e.g. {first['item']}.{first['key']}: "
              f"{_short(first['value'])} vs {_short(first['expected'])} expected")
    return GraphComparison(True, True, False, detail, differences, categories)


def _partner_mapping(g1: nx.DiGraph, g2: nx.DiGraph, timeout_s: float) -> dict[Any, Any] | None:
    """A type isomorphism that pairs items as well as the annotations allow."""
    for label in ("label_geometry", "label_physics", "type"):
        mapping = _isomorphism(g1, g2, label, timeout_s)
        if mapping is not None:
            return mapping
    return None


class ComparisonTimeout(Exception):
    """The isomorphism search ran out of its time budget."""


def _isomorphism(g1: nx.DiGraph, g2: nx.DiGraph, label: str, timeout_s: float = 120.0) -> dict[Any, Any] | None:
    """An isomorphism g1 -> g2 respecting node labels and edge fields, or None.

    Colour refinement (1-WL on both graphs jointly) first, then individualisation of one node of
    the smallest ambiguous colour class at a time, refining again after each choice. Symmetric
    systems (grids, chains, trusses) resolve after a few choices, where a plain VF2 search can
    take minutes. Raises :class:`ComparisonTimeout` past ``timeout_s``.
    """
    h1, h2 = _with_edge_nodes(g1, label), _with_edge_nodes(g2, label)
    if h1.number_of_nodes() != h2.number_of_nodes() or h1.number_of_edges() != h2.number_of_edges():
        return None
    initial = {(k, n): d["label"] for k, h in ((0, h1), (1, h2)) for n, d in h.nodes(data=True)}
    deadline = time.monotonic() + timeout_s
    mapping = _search(h1, h2, _refine(h1, h2, initial), deadline)
    if mapping is None:
        return None
    return {n: mapping[n] for n in g1.nodes}


def _refine(h1: nx.DiGraph, h2: nx.DiGraph, colours: dict[tuple[int, Any], Any]) -> dict[tuple[int, Any], int]:
    """Stable joint colouring: a node's colour is its old colour plus its neighbours' colours."""
    palette = {c: i for i, c in enumerate(sorted(set(colours.values()), key=repr))}
    current = {key: palette[c] for key, c in colours.items()}
    graphs = ((0, h1), (1, h2))
    while True:
        signature = {
            (k, n): (current[(k, n)],
                     tuple(sorted(current[(k, p)] for p in h.predecessors(n))),
                     tuple(sorted(current[(k, q)] for q in h.successors(n))))
            for k, h in graphs for n in h.nodes
        }
        palette = {sig: i for i, sig in enumerate(sorted(set(signature.values())))}
        refined = {key: palette[sig] for key, sig in signature.items()}
        if len(palette) == len(set(current.values())):
            return refined
        current = refined


def _search(h1: nx.DiGraph, h2: nx.DiGraph, colours: dict[tuple[int, Any], int], deadline: float,
            ) -> dict[Any, Any] | None:
    classes: dict[int, tuple[list[Any], list[Any]]] = {}
    for (k, n), c in colours.items():
        classes.setdefault(c, ([], []))[k].append(n)
    if any(len(a) != len(b) for a, b in classes.values()):
        return None
    ambiguous = [(len(a), c) for c, (a, _) in classes.items() if len(a) > 1]
    if not ambiguous:
        mapping = {a[0]: b[0] for a, b in classes.values()}
        edges1 = {(mapping[u], mapping[v]) for u, v in h1.edges}
        return mapping if edges1 == set(h2.edges) else None
    _, colour = min(ambiguous)
    first, candidates = classes[colour]
    fresh = max(colours.values()) + 1
    for candidate in candidates:
        if time.monotonic() > deadline:
            raise ComparisonTimeout
        trial = dict(colours)
        trial[(0, first[0])] = trial[(1, candidate)] = fresh
        found = _search(h1, h2, _refine(h1, h2, trial), deadline)
        if found is not None:
            return found
    return None


def _with_edge_nodes(graph: nx.DiGraph, label: str) -> nx.DiGraph:
    helper = nx.DiGraph()
    for node, data in graph.nodes(data=True):
        helper.add_node(node, label=data[label])
    for u, v, data in graph.edges(data=True):
        edge_node = ("edge", u, v)
        helper.add_node(edge_node, label="ref:" + data["field"])
        helper.add_edge(u, edge_node)
        helper.add_edge(edge_node, v)
    return helper


def _is_type_isomorphism(g1: nx.DiGraph, g2: nx.DiGraph, mapping: dict[Any, Any]) -> bool:
    if any(m not in g2 or g1.nodes[n]["type"] != g2.nodes[m]["type"] for n, m in mapping.items()):
        return False
    edges1 = {(mapping[u], mapping[v], d["field"]) for u, v, d in g1.edges(data=True)}
    edges2 = {(u, v, d["field"]) for u, v, d in g2.edges(data=True)}
    return edges1 == edges2


def _annotations_match(g1: nx.DiGraph, g2: nx.DiGraph, mapping: dict[Any, Any], tol: GraphTolerance) -> bool:
    return all(
        _diff_keys(g1.nodes[n]["annotations"], g2.nodes[m]["annotations"], tol) == []
        for n, m in mapping.items()
    )


def _diff_keys(a: dict[str, Any], b: dict[str, Any], tol: GraphTolerance) -> list[str]:
    keys = sorted(set(a) | set(b))
    return [k for k in keys if k not in a or k not in b or not values_close(a[k], b[k], tol)]


def _differences(g1: nx.DiGraph, g2: nx.DiGraph, mapping: dict[Any, Any], tol: GraphTolerance) -> list[dict[str, Any]]:
    out = []
    for n in sorted(mapping, key=lambda x: (x[0], x[1])):
        m = mapping[n]
        a, b = g1.nodes[n]["annotations"], g2.nodes[m]["annotations"]
        item_type = g2.nodes[m]["type"]
        for key in _diff_keys(a, b, tol):
            out.append({
                "item": f"{item_type}#{m[1]}",
                "key": key,
                "value": a.get(key),
                "expected": b.get(key),
                "category": categorize(item_type, key),
            })
    return out


def _type_diff(a: Counter[str], b: Counter[str]) -> str:
    extra = a - b
    missing = b - a
    parts = []
    if missing:
        parts.append("missing " + ", ".join(f"{n}x {t}" for t, n in sorted(missing.items())))
    if extra:
        parts.append("surplus " + ", ".join(f"{n}x {t}" for t, n in sorted(extra.items())))
    return "; ".join(parts) or "same item types"


def _short(value: Any, limit: int = 80) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."
