"""Turning LLM answers into data: the component list and the program.

A malformed answer is a recorded result (``error`` set), never an exception.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from meceng.syntax import parse

_THINK = re.compile(r"<think>.*?</think>", re.S | re.I)
_BLOCK = re.compile(r"<components>(.*?)</components>", re.S | re.I)
_ITEM = re.compile(r"<component>(.*?)</component>", re.S | re.I)
_FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_+-]*)[^\n]*\n(.*?)```", re.S)


@dataclass(frozen=True)
class ParsedSelection:
    names: tuple[str, ...]
    unknown: tuple[str, ...] = ()
    error: str | None = None


def _normalize(name: str) -> str:
    return re.sub(r"[^a-z0-9]", "", name.lower())


def parse_components(answer: str, known: Iterable[str]) -> ParsedSelection:
    """Read ``<components><component>Name</component>...</components>``.

    Names are matched to the catalog ignoring case, spaces and punctuation; unknown names are
    kept aside. No list at all, or an empty one, is an error.
    """
    text = _THINK.sub("", answer or "")
    blocks = _BLOCK.findall(text)
    if not blocks:
        return ParsedSelection((), (), "no <components>...</components> list in the answer")
    body = blocks[-1]
    raw_items = _ITEM.findall(body)
    if not raw_items:
        raw_items = [p for p in re.split(r"[,\n;]", body)]
    cleaned = [re.sub(r"^[\s\-*\d.)]+", "", item).strip().strip("`'\"") for item in raw_items]
    cleaned = [c for c in cleaned if c]
    if not cleaned:
        return ParsedSelection((), (), "the <components> list is empty")
    by_norm = {_normalize(k): k for k in known}
    names: list[str] = []
    unknown: list[str] = []
    for item in cleaned:
        match = by_norm.get(_normalize(item))
        if match is None:
            unknown.append(item)
        elif match not in names:
            names.append(match)
    if not names:
        return ParsedSelection((), tuple(unknown), "none of the listed components exists in the catalog")
    return ParsedSelection(tuple(names), tuple(unknown))


@dataclass(frozen=True)
class ExtractedCode:
    code: str | None
    error: str | None = None


def extract_code(answer: str) -> ExtractedCode:
    """The program in the answer: the fenced block that calls Assemble (longest if several).

    Without fences, the whole answer is taken if it parses as Python and uses Exudyn.
    """
    text = _THINK.sub("", answer or "")
    blocks = [body for lang, body in _FENCE.findall(text) if lang.lower() in ("", "python", "py", "python3")]
    if blocks:
        with_assemble = [b for b in blocks if "Assemble(" in b]
        chosen = max(with_assemble or blocks, key=len)
        return ExtractedCode(chosen.strip("\n") + "\n")
    stripped = text.strip()
    if "exudyn" in stripped:
        try:
            parse(stripped)
        except SyntaxError:
            pass
        else:
            return ExtractedCode(stripped + "\n")
    return ExtractedCode(None, "no Python code block in the answer")
