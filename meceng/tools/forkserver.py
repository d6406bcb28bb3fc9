"""The warm fork server: imports the heavy modules once, then forks one child per program.

Started by :class:`meceng.tools.warm.WarmPool` as ``python -m meceng.tools.forkserver SOCKET``.
Protocol on the Unix socket, one connection per program: the client sends one JSON line
``{"job": path, "env": {...}, "limits": {...}}``; the server forks, answers ``{"pid": N}``, and
when the child has ended ``{"exit": code, "cpu_s": seconds}`` (negative: killed by that signal;
the child's CPU time from ``wait4``, all its threads). The server is
single-threaded and never meshes or solves, so its children can. It exits when its stdin closes
(the parent is gone).
"""

from __future__ import annotations

import contextlib
import importlib
import json
import os
import selectors
import signal
import socket
import sys
from typing import Any

PRELOAD = ("numpy", "exudyn", "exudyn.utilities", "exudyn.graphics", "exudyn.interactive", "exudyn.solver",
           "exudyn.FEM", "scipy.sparse.linalg", "ngsolve", "netgen.occ", "json", "traceback", "ctypes",
           "meceng.tools.runner", "meceng.tools.guard", "meceng.tools.warm", "meceng.tools.safety")


def _preload() -> None:
    # the libraries read their thread counts as they load: pinned before the first import (the
    # pool starts the server with them already; this holds for a server started any other way)
    from meceng.tools.pinning import THREAD_PINS, pin_eigensolvers

    os.environ.update(THREAD_PINS)
    pin_eigensolvers()
    for name in PRELOAD:
        with contextlib.suppress(Exception):  # an optional module missing only costs start-up later
            importlib.import_module(name)


def _read_line(conn: socket.socket, limit: int = 1 << 20) -> bytes:
    data = b""
    while not data.endswith(b"\n") and len(data) < limit:
        chunk = conn.recv(65536)
        if not chunk:
            break
        data += chunk
    return data


def serve(path: str) -> None:
    _preload()
    from meceng.tools.warm import child_main

    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(128)
    wake_r, wake_w = os.pipe()
    os.set_blocking(wake_w, False)
    signal.set_wakeup_fd(wake_w)
    signal.signal(signal.SIGCHLD, lambda *_: None)
    selector = selectors.DefaultSelector()
    selector.register(listener, selectors.EVENT_READ, "accept")
    selector.register(wake_r, selectors.EVENT_READ, "child")
    selector.register(sys.stdin.fileno(), selectors.EVENT_READ, "parent")
    waiting: dict[int, socket.socket] = {}
    sys.stdout.write("ready\n")
    sys.stdout.flush()
    while True:
        for key, _ in selector.select():
            if key.data == "parent":
                if not os.read(sys.stdin.fileno(), 4096):
                    return
            elif key.data == "accept":
                conn, _ = listener.accept()
                conn.settimeout(10)
                try:
                    request: dict[str, Any] = json.loads(_read_line(conn))
                except (OSError, ValueError):
                    conn.close()
                    continue
                pid = os.fork()
                if pid == 0:  # the child: drop the server's handles, then run the program
                    signal.set_wakeup_fd(-1)
                    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
                    selector.close()
                    for fd in (listener, conn, *waiting.values()):
                        fd.close()
                    os.close(wake_r)
                    os.close(wake_w)
                    child_main(request["job"], request["env"], request["limits"])
                    os._exit(1)  # child_main never returns
                waiting[pid] = conn
                with contextlib.suppress(OSError):
                    conn.sendall(json.dumps({"pid": pid}).encode() + b"\n")
            else:
                with contextlib.suppress(BlockingIOError):
                    os.read(wake_r, 4096)
                _reap(waiting)


def _reap(waiting: dict[int, socket.socket]) -> None:
    while True:
        try:
            pid, status, usage = os.wait4(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        conn = waiting.pop(pid, None)
        if conn is not None:
            ended = {"exit": os.waitstatus_to_exitcode(status), "cpu_s": usage.ru_utime + usage.ru_stime}
            with contextlib.suppress(OSError):
                conn.sendall(json.dumps(ended).encode() + b"\n")
            conn.close()


if __name__ == "__main__":
    serve(sys.argv[1])
