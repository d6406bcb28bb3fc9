"""The three catalogs a task chooses from, by task kind: rigid (levels 1-2), part (3a), assembly (3b).

The component lists are imported when a catalog is made (the part and flexible lists carry long
texts that a rigid run never needs)."""

from __future__ import annotations

from meceng.catalog.component import Catalog


def rigid_catalog() -> Catalog:
    from meceng.catalog.rigid import COMPONENTS

    return Catalog(COMPONENTS)


def part_catalog() -> Catalog:
    """Level 3a: geometry and FEM components."""
    from meceng.catalog.part import COMPONENTS

    return Catalog(COMPONENTS)


def assembly_catalog() -> Catalog:
    """Level 3b: the rigid components plus flexible bodies, interface joints and loads."""
    from meceng.catalog.flexible import COMPONENTS as FLEXIBLE
    from meceng.catalog.rigid import COMPONENTS as RIGID

    return Catalog(RIGID + FLEXIBLE)


def catalog_for(kind: str) -> Catalog:
    """The catalog a task of this kind chooses from: "rigid" (levels 1-2), "part" or "assembly"."""
    return {"part": part_catalog, "assembly": assembly_catalog}.get(kind, rigid_catalog)()
