"""Headless Chromium for the viewer's tests and measurements: the DOM after the page's scripts
ran, the console's errors, a screenshot. Debian's ``chromium`` package, run as a subprocess (no
driver library: dumping the DOM is all the tests need)."""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
         "--enable-logging=stderr", "--v=0")
#: a console message of a page's script as Chromium logs it (uncaught exceptions included; the level
#: is not in the line, and the viewer's pages log nothing, so every message counts)
CONSOLE_LINE = re.compile(r":CONSOLE[^\]]*\]\s*(.*)")


def find_chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome", "chrome"):
        if path := shutil.which(name):
            return path
    return None


@dataclass(frozen=True)
class Loaded:
    dom: str
    console: list[str]


def _run(extra: list[str], url: str, timeout_s: float) -> subprocess.CompletedProcess[str]:
    binary = find_chromium()
    if binary is None:
        raise FileNotFoundError("chromium is not installed (Debian: apt-get install chromium)")
    with tempfile.TemporaryDirectory(prefix="meceng-chromium-") as profile:
        return subprocess.run([binary, *FLAGS, f"--user-data-dir={profile}", *extra, url], capture_output=True,
                              text=True, timeout=timeout_s, check=False)


def load(url: str, budget_ms: int = 5000, timeout_s: float = 120.0) -> Loaded:
    """The DOM once the page's scripts ran (virtual time ``budget_ms``) and its console messages."""
    done = _run(["--dump-dom", f"--virtual-time-budget={budget_ms}"], url, timeout_s)
    errors = [m.group(1) for line in done.stderr.splitlines() if (m := CONSOLE_LINE.search(line))]
    return Loaded(done.stdout, errors)


def screenshot(url: str, path: Path, size: tuple[int, int] = (1400, 2400), timeout_s: float = 120.0) -> Path:
    _run([f"--screenshot={path}", f"--window-size={size[0]},{size[1]}", "--virtual-time-budget=5000"], url,
         timeout_s)
    return path
