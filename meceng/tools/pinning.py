"""What is pinned in every child so that a program's work (and so its CPU time and its result)
follows the program, not the launcher that started it (issue 45).

Measured on the corpus's flexible pendulum on a wrong hinge axis (a Newton solve on the edge of
convergence, whose adaptive step count follows the last bits of its inputs), on 2 cores:

* ARPACK's start vector. SciPy's ``eigsh`` (Exudyn's Hurty-Craig-Bampton and eigenmode
  computations) draws it from OS entropy when none is given, so every making of the same part
  (the same mesh and matrices) gave another, equally valid mode basis, and every launcher makes
  an assembly's parts itself: on three makings the program took 18,957 steps (27 s of CPU) and
  twice stopped after 12 and 16 steps (0.5 s). Pinned to a fixed seed per call
  (``pin_eigensolvers``): every making gives the same bytes, and the program stops after 12 steps
  in 0.2-0.6 s of CPU in every launcher (scripts/bench_cpu_time.py).
* The thread count of the numerical libraries. On one part file, NumPy's OpenBLAS with two
  threads and with one summed in other orders: 14,271 steps (22 s of CPU) against 42,101 steps
  (55 s). OpenBLAS, OpenMP and NGSolve read their counts from the environment as they load, so
  the counts must be in the environment of the process that imports them: the cold child's, and
  the fork server's for every warm child (whatever environment the pool was given).
* Python's string hashing (``PYTHONHASHSEED``): a program that builds its system by iterating
  a set of names would otherwise build it in another order in every process.

CPU affinity is not pinned: with one thread per library, a child's CPU time does not depend on
how many cores it may use, only its wall time does (a level-1 program with 0.7 s of extra Python:
0.93-0.99 s of CPU on every core, on one core, and on one core shared with four busy loops, while
the wall clock read 3.3-5.8 s on a loaded machine).
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import inspect
import sys
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any

#: one thread for every numerical library a program can reach; read when the library loads
THREAD_PINS = {
    "OMP_NUM_THREADS": "1",
    "OPENBLAS_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
    "BLIS_NUM_THREADS": "1",
    "VECLIB_MAXIMUM_THREADS": "1",
    "NUMEXPR_NUM_THREADS": "1",
    "NGS_NUM_THREADS": "1",  # NGSolve's TaskManager (netgen.libs' libngcore)
}
#: everything pinned in a child's environment
PINNED_ENV = {**THREAD_PINS, "PYTHONHASHSEED": "0"}

#: the seed of every ARPACK start vector a program leaves to chance
EIGEN_SEED = 0
_EIGEN_SOLVERS = ("eigsh", "eigs", "svds")
_MODULE = "scipy.sparse.linalg"


def _seeded(function: Callable[..., Any]) -> Callable[..., Any]:
    """``function`` with a fixed random generator where the caller gave neither a start vector nor
    a generator (SciPy >= 1.15 calls it ``rng``, older releases ``random_state``)."""
    if getattr(function, "__meceng_pinned__", False):
        return function
    parameters = inspect.signature(function).parameters
    name = "rng" if "rng" in parameters else "random_state" if "random_state" in parameters else None
    if name is None:
        return function

    def pinned(*args: Any, **kwargs: Any) -> Any:
        if kwargs.get(name) is None and kwargs.get("v0") is None:
            import numpy as np

            kwargs[name] = np.random.default_rng(EIGEN_SEED)
        return function(*args, **kwargs)

    pinned.__wrapped__ = function  # type: ignore[attr-defined]
    pinned.__meceng_pinned__ = True  # type: ignore[attr-defined]
    pinned.__doc__ = function.__doc__
    pinned.__name__ = function.__name__
    return pinned


def _pin_module(module: ModuleType) -> None:
    for attribute in _EIGEN_SOLVERS:
        function = getattr(module, attribute, None)
        if callable(function):
            setattr(module, attribute, _seeded(function))


class _PinOnImport(importlib.abc.MetaPathFinder):
    """Pins SciPy's eigensolvers when ``scipy.sparse.linalg`` is first imported: importing it
    up front would cost every cold child ~0.2 s of CPU for the few programs that use it."""

    def find_spec(self, fullname: str, path: Sequence[str] | None, target: ModuleType | None = None,
                  ) -> importlib.machinery.ModuleSpec | None:
        if fullname != _MODULE:
            return None
        spec = importlib.machinery.PathFinder.find_spec(fullname, path)
        if spec is None or spec.loader is None or not hasattr(spec.loader, "exec_module"):
            return spec
        loader = spec.loader
        execute = loader.exec_module

        def exec_module(module: ModuleType) -> None:
            execute(module)
            _pin_module(module)

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


def pin_eigensolvers() -> None:
    """Seed SciPy's ARPACK eigensolvers in this process: now if SciPy's sparse solvers are already
    loaded (the fork server preloads them), else when they are first imported."""
    module = sys.modules.get(_MODULE)
    if module is not None:
        _pin_module(module)
    elif not any(isinstance(finder, _PinOnImport) for finder in sys.meta_path):
        sys.meta_path.insert(0, _PinOnImport())
