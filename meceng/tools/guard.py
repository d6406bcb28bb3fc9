"""Runtime guard inside the child: a Python audit hook that refuses what a model program must
not do, whatever trick it uses to get there.

The static check reads the text; this hook sees the actual operations (``open`` for writing,
deleting or renaming files, sockets, processes, native code through ctypes), so obfuscation with
``__import__``, ``getattr`` or ``exec`` does not help. Audit hooks cannot be removed once added.
Writes are allowed inside the scratch directory only. Native code that bypasses Python (a C
extension writing a file) is outside its reach; the process limits and the scratch cwd cover that.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from typing import Any

#: Events refused outright while the program runs.
BLOCKED_EVENTS = frozenset({
    "subprocess.Popen", "os.system", "os.exec", "os.posix_spawn", "os.spawn", "os.fork", "os.forkpty",
    "os.kill", "os.killpg", "pty.spawn", "os.startfile",
    "socket.__new__", "socket.connect", "socket.bind", "socket.getaddrinfo", "socket.sendto",
    "socket.gethostbyname", "urllib.Request",
    "ctypes.dlopen", "ctypes.dlsym", "ctypes.string_at", "ctypes.wstring_at", "ctypes.cdata",
    "ctypes.call_function", "ctypes.addressof", "ctypes.seh_exception",
    "os.chdir", "os.setuid", "os.setgid", "sys.setrecursionlimit", "sys.settrace", "sys.setprofile",
    "signal.pthread_kill", "resource.setrlimit", "resource.prlimit", "os.truncate",
    "gc.get_objects", "gc.get_referrers", "gc.get_referents", "sys.addaudithook",
})

#: Events whose path arguments must lie inside the scratch directory.
PATH_EVENTS = {
    "os.remove": (0,), "os.rmdir": (0,), "os.mkdir": (0,), "os.rename": (0, 1), "os.link": (0, 1),
    "os.symlink": (0, 1), "os.chmod": (0,), "os.chown": (0,), "os.utime": (0,), "shutil.rmtree": (0,),
    "shutil.copyfile": (1,), "shutil.copytree": (1,), "shutil.move": (0, 1), "shutil.make_archive": (0,),
}

_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC


class SandboxRefusal(PermissionError):
    """What the program gets when it tries something the sandbox refuses."""


def install(scratch: str, record: Callable[[str], None]) -> Callable[[bool], None]:
    """Add the audit hook; returns ``set_active(flag)`` so the harness can do its own I/O."""
    root = os.path.realpath(scratch)
    state = {"active": False}

    def inside(path: Any) -> bool:
        if isinstance(path, int):
            return False
        try:
            real = os.path.realpath(os.fsdecode(path))
        except (TypeError, ValueError):
            return False
        return real == root or real.startswith(root + os.sep)

    def refuse(what: str) -> None:
        message = f"MecEng sandbox refused: {what}"
        record(message)
        raise SandboxRefusal(message)

    def hook(event: str, args: tuple[Any, ...]) -> None:
        if not state["active"]:
            return
        if event in BLOCKED_EVENTS:
            refuse(f"{event}{_short(args)}")
        elif event == "open":
            path, mode, flags = [*args, None, None, None][:3]
            writing = (isinstance(mode, str) and any(c in mode for c in "wax+")) or (
                isinstance(flags, int) and flags & _WRITE_FLAGS)
            if writing and not inside(path):
                refuse(f"writing {path!r} outside the scratch directory")
        elif event in PATH_EVENTS:
            for index in PATH_EVENTS[event]:
                if index < len(args) and args[index] is not None and not inside(args[index]):
                    refuse(f"{event} on {args[index]!r} outside the scratch directory")

    sys.addaudithook(hook)

    def set_active(flag: bool) -> None:
        state["active"] = flag

    return set_active


def _short(args: tuple[Any, ...]) -> str:
    text = repr(args)
    return text if len(text) < 120 else text[:117] + "..."
