"""The values a sweep spec may hold, each checked where it is read (``sweep.load_spec``): a typo or
a value out of range is refused with the study's name, never silently changes what a study runs."""

from __future__ import annotations

from typing import Any

from meceng.tasks import default_registry


def as_tuple(value: Any) -> tuple[Any, ...]:
    if value is None:
        return ()
    return tuple(value) if isinstance(value, list | tuple) else (value,)


def temperature_of(value: Any) -> float | None:
    if value == "default":
        return None
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"temperature {value!r}: a number or \"default\"")
    return float(value)


def check_keys(where: str, data: dict[str, Any], known: set[str]) -> None:
    unknown = set(data) - known
    if unknown:
        raise ValueError(f"{where}: unknown keys {sorted(unknown)}")


SCOPE_KEYS = {"levels", "only", "variations", "seed", "grid", "description", "agent", "tools", "drafts_per_task",
              "texts", "samples", "consensus"}
AGENTS = ("pipeline", "loop", "repair", "consensus")
GRID_KEYS = {"temperature", "think", "select_template", "code_template", "texts"}


def only_of(value: Any) -> tuple[str, ...]:
    """A spec's ``only``: task keys, each one a task model (a typo must not shrink a study)."""
    only = tuple(str(x) for x in as_tuple(value))
    default_registry().check(only)
    return only


def texts_of(study: str, value: Any, levels: tuple[str, ...], only: tuple[str, ...]) -> tuple[str, ...]:
    """A study's ``texts`` (``["paper", "open"]``): each a kind of task text its levels have; a
    study of open texts on levels without them (3a, 3b) is refused here, not when its run starts."""
    texts = tuple(str(x) for x in as_tuple(value))
    registry = default_registry()
    for kind in texts:
        try:
            registry.with_texts(registry.select(levels, only or None), kind, levels, only)
        except ValueError as exc:
            raise ValueError(f"study {study}: texts = {kind!r}: {exc}") from None
    if not texts:
        raise ValueError(f"study {study}: texts = []; give \"paper\", \"open\" or both")
    return texts


def agent_of(study: str, value: Any) -> str:
    if value not in AGENTS:
        raise ValueError(f"study {study}: agent = {value!r}; choose from {', '.join(AGENTS)}")
    return str(value)


def tools_of(study: str, value: Any) -> bool:
    """``tools = "on"`` / ``"off"`` (or true / false) of a repair study."""
    if value in ("on", True):
        return True
    if value in ("off", False):
        return False
    raise ValueError(f"study {study}: tools = {value!r}; choose on or off")


def consensus_mode(study: str, value: Any, agent: str, models: int) -> str:
    """``consensus = "each"`` (a consensus run per model) or ``"across"`` (one run whose samples the
    study's models write in turn, sample k by model k mod M): across needs a consensus study of two
    models or more."""
    if value not in ("each", "across"):
        raise ValueError(f"study {study}: consensus = {value!r}; choose each or across")
    if value == "across" and (agent != "consensus" or models < 2):
        raise ValueError(f"study {study}: consensus = \"across\" needs agent = \"consensus\" and two models or more")
    return str(value)
