"""``ast.parse`` behind one lock, for every parse the harness makes in the parent process (the
static check, the code extraction, the mesh pre-check, the repair drafts: every room may use it).

CPython 3.11 keeps the AST constructor's recursion depth in interpreter-wide state: two threads
parsing at once (the static check runs off the event loop, the code extraction on it) can break
it, and the parse fails with "SystemError: AST constructor recursion depth mismatch" — seen once
in a 1000-task gold run, where it cost a task as an infrastructure failure (CPython issue
gh-106905, fixed in later releases than this machine's 3.11.7). A parse takes about a millisecond,
so one at a time costs nothing.
"""

from __future__ import annotations

import ast
import threading

_PARSING = threading.Lock()


def parse(source: str) -> ast.Module:
    """``ast.parse(source)``, one thread at a time (SyntaxError passes through)."""
    with _PARSING:
        return ast.parse(source)
