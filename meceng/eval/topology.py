"""Why two system graphs differ in topology, for a person reading the verdict.

The paper's rule stays: a program whose system has other items or other connections than the
ground truth fails ``topology_match`` (the simplest representation is expected). What this module
adds is the cause: the item types missing and surplus, whether the connections differ with the
same items, and which of the program's items are *inert* — they cannot affect the motion:

- a load with a zero vector and no user function;
- a marker no (non-inert) connector, load or sensor refers to;
- an object that is not a connector and that no (non-inert) marker refers to (a ground nothing
  is attached to, a body nothing acts on), and the nodes only such objects use.

Sensors are not in the graph (they are excluded from grading), so they never make an item live.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

import networkx as nx

#: The causes, in the order the report lists them.
CAUSES = ("missing item types", "surplus item types", "surplus inert items only", "connections")


@dataclass(frozen=True)
class TopologyCauses:
    cause: str
    missing: dict[str, int] = field(default_factory=dict)
    surplus: dict[str, int] = field(default_factory=dict)
    inert: tuple[str, ...] = ()  # the program's inert items, e.g. "object:Ground#2"

    def to_json(self) -> dict[str, Any]:
        return {"cause": self.cause, "missing": self.missing, "surplus": self.surplus, "inert": list(self.inert)}

    def text(self) -> str:
        parts = [f"cause: {self.cause}"]
        if self.inert:
            parts.append("inert (cannot affect the motion): " + ", ".join(self.inert[:6])
                         + (f" and {len(self.inert) - 6} more" if len(self.inert) > 6 else ""))
        return "; ".join(parts)


def _zero(value: Any) -> bool:
    if isinstance(value, list | tuple):
        return all(_zero(v) for v in value)
    return isinstance(value, int | float) and not isinstance(value, bool) and value == 0


def _dead_load(annotations: dict[str, Any], raw: dict[str, Any]) -> bool:
    vectors = [v for k, v in raw.items() if k in ("loadVector", "load")]
    functions = [v for k, v in raw.items() if "UserFunction" in k]
    return bool(vectors) and all(_zero(v) for v in vectors) and all(f in (0, None, "", "0") for f in functions)


def inert_items(graph: nx.DiGraph, items: dict[str, list[dict[str, Any]]]) -> list[tuple[str, int]]:
    """The graph nodes (``(kind, index)``) that cannot affect the motion, found to a fixed point
    (a marker used only by a dead load is dead too, and so is the ground only it was on)."""
    dead: set[tuple[str, int]] = set()
    for node in graph.nodes:
        kind, index = node
        if kind == "loads" and _dead_load(graph.nodes[node]["annotations"], items[kind][index]):
            dead.add(node)
    changed = True
    while changed:
        changed = False
        for node in graph.nodes:
            kind = node[0]
            if node in dead or kind == "loads":
                continue
            users = [u for u in graph.predecessors(node) if u not in dead]
            connector = kind == "objects" and any(t[0] == "markers" for t in graph.successors(node))
            if not users and not connector:
                dead.add(node)
                changed = True
    return sorted(dead)


def topology_causes(cand: nx.DiGraph, ref: nx.DiGraph, cand_items: dict[str, list[dict[str, Any]]],
                    ref_items: dict[str, list[dict[str, Any]]]) -> TopologyCauses:
    """The cause of a topology failure between the program's graph and the ground truth's.

    Missing types come first (something the motion needs is not there); then whether what is
    surplus is all inert: with the inert items of both systems left out, the systems are the same
    by type (``surplus inert items only``), or still differ in their connections, or in live items.
    """
    type_cand = _types(cand, cand.nodes)
    type_ref = _types(ref, ref.nodes)
    missing, surplus = dict(type_ref - type_cand), dict(type_cand - type_ref)
    dead = inert_items(cand, cand_items)
    inert = tuple(f"{cand.nodes[n]['type']}#{n[1]}" for n in dead)
    if missing:
        cause = CAUSES[0]
    else:
        live_cand = cand.subgraph(n for n in cand.nodes if n not in set(dead))
        ref_dead = set(inert_items(ref, ref_items))
        live_ref = ref.subgraph(n for n in ref.nodes if n not in ref_dead)
        if _types(live_cand, live_cand.nodes) != _types(live_ref, live_ref.nodes):
            cause = CAUSES[1]
        elif surplus and nx.vf2pp_is_isomorphic(live_cand, live_ref, node_label="type"):
            cause = CAUSES[2]
        else:
            cause = CAUSES[3]
    return TopologyCauses(cause, dict(sorted(missing.items())), dict(sorted(surplus.items())), inert)


def _types(graph: nx.DiGraph, nodes: Any) -> Counter[str]:
    return Counter(graph.nodes[n]["type"] for n in nodes)
