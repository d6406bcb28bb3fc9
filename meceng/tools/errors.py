"""A program's exception as a person (or the agent repairing its program) needs it: the program's
own line — number and source — the exception type and message with Exudyn's own words, and no
frame of the harness and no path of this machine.

Runs inside the child (standard library only). Exudyn appends the Python line that called into
it (``[Python file '...', line N]``); when the harness wrapped the call (``mbs.Assemble``), that
line is the harness's, so it is replaced by the program's.
"""

from __future__ import annotations

import re
import traceback
from pathlib import Path
from typing import Any

PROGRAM_NAME = "program.py"
_EXUDYN_WHERE = re.compile(r"\s*\[Python file '[^']*', line \d+\]")
_LIBRARY_PATH = re.compile(r"(?:/[^\s'\"\[\]()]*)?/(?:site|dist)-packages/")
_HARNESS_FRAME = ("/meceng/tools/", "<frozen ")


def scrub_paths(text: str, scratch: str) -> str:
    """Paths as the program sees them: the scratch folder's files by name, libraries by their
    package path (``exudyn/utilities.py``)."""
    text = text.replace(scratch.rstrip("/") + "/", "")
    return _LIBRARY_PATH.sub("", text)


def program_error(exc: BaseException, program_path: str, source: str, scratch: str) -> dict[str, Any]:
    """``error`` (one line: where, type, message), ``error_type``, ``error_line`` (or None when no
    frame of the program is involved) and a ``traceback`` of the program's and libraries' frames."""
    if isinstance(exc, SystemExit):
        return {"error": f"program called exit({exc.code!r})", "error_type": "SystemExit", "error_line": None}
    frames = [f for f in traceback.extract_tb(exc.__traceback__)
              if not any(marker in f.filename for marker in _HARNESS_FRAME)]
    own = [f for f in frames if f.filename == program_path]
    line = own[-1].lineno if own else None
    message = str(exc)
    if isinstance(exc, SyntaxError) and exc.filename == program_path:
        line, message = exc.lineno, str(exc.msg)
    message = scrub_paths(_EXUDYN_WHERE.sub("", message), scratch).strip()
    kind = type(exc).__name__
    what = f"{kind}: {message}" if message else kind
    text = source.splitlines()[line - 1].strip() if line and 0 < line <= len(source.splitlines()) else ""
    where = f"line {line}" + (f" ({_shorten(text)})" if text else "") if line else ""
    lines = [f"  {_name(f.filename, program_path)}, line {f.lineno}, in {f.name}"
             + (f"\n    {f.line}" if f.line else "") for f in frames]
    return {"error": f"{where}: {what}" if where else what, "error_type": kind, "error_line": line,
            "traceback": scrub_paths("\n".join(["Traceback (most recent call last):", *lines, what]), scratch)}


def _name(filename: str, program_path: str) -> str:
    return PROGRAM_NAME if filename == program_path else filename


def _shorten(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def describe_exception(exc: BaseException, workdir: Path, program: str) -> dict[str, Any]:
    """The program's exception at its own line, without harness frames or this machine's paths."""
    return program_error(exc, str(workdir / PROGRAM_NAME), program, str(workdir))
