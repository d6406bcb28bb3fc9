"""``meceng doctor``: can this machine run a sweep? One table, non-zero exit when a line fails.

The same checks as the preflight every run makes before its first request (the system libraries
the compiled modules need, the stack imported in the sandbox, one ground truth per task kind),
then the servers the run would use: reachable, the model served, its context where the API says
it (the longest prompt MecEng sends plus the answer limit must fit one slot's context).
"""

from __future__ import annotations

import argparse
import asyncio

from meceng.cli.arguments import add_llm_arguments, llm_settings, parse_levels

ALL_LEVELS = ("1", "2", "3a", "3b")


def add_doctor_arguments(parser: argparse.ArgumentParser) -> None:
    add_llm_arguments(parser)
    parser.add_argument("--levels", type=parse_levels, default=ALL_LEVELS,
                        help="the levels to check the stack for (default: all; 1,2 needs Exudyn only)")
    parser.add_argument("--executor", choices=("fork", "subprocess"), default="fork",
                        help="the sandbox the runs will use (default: the warm fork server)")
    parser.add_argument("--timeout", type=float, default=300.0,
                        help="CPU seconds per ground-truth execution (the wall clock stops it at 3x this plus 10 s)")


async def _checks(args: argparse.Namespace) -> list[tuple[str, bool | None, str]]:
    from meceng.eval.chain import Tolerances
    from meceng.llm.probe import probe
    from meceng.pipeline.evaluation import Evaluator
    from meceng.pipeline.preflight import MODULES, check_stack, kinds_of, missing_library, unlinked_libraries
    from meceng.tasks.registry import default_registry
    from meceng.tools.execution import ExecutionLimits
    from meceng.tools.executor import child_env
    from meceng.tools.warm import WarmPool

    registry = default_registry()
    instances = registry.instances(registry.select(args.levels, None), 0, 1)
    kinds = kinds_of(instances)
    modules = tuple(dict.fromkeys(m for k in kinds for m in MODULES[k]))
    rows: list[tuple[str, bool | None, str]] = []
    unlinked = unlinked_libraries(modules)
    for module in dict.fromkeys(m.split(".")[0] for m in modules):
        libraries = unlinked.get(module, [])
        said = "; ".join(missing_library(lib) or lib for lib in libraries)
        rows.append((f"system libraries of {module}", not libraries, said or "all found (ldd)"))
    pool = WarmPool(child_env()) if args.executor == "fork" else None
    evaluator = Evaluator(2, ExecutionLimits(timeout_s=args.timeout), Tolerances(), pool=pool,
                          part_timeout_s=args.timeout)
    try:
        for check in await check_stack(instances, evaluator):
            library = None if check.ok else missing_library(check.detail)
            rows.append((check.name, check.ok, check.detail[:300] + (f" -> missing {library}" if library else "")))
    finally:
        if pool is not None:
            await pool.close()
    settings = llm_settings(args)
    if settings.backend == "gold":
        rows.append(("server", None, "gold backend: no server to check (give --backend/--model/--host)"))
    for server in await probe(settings):
        rows.append((f"server {server.host}", server.ok, server.detail))
    return rows


def cmd_doctor(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    rows = asyncio.run(_checks(args))
    table = Table(title="meceng doctor", show_lines=False)
    table.add_column("check")
    table.add_column("result")
    table.add_column("detail", overflow="fold")
    for name, ok, detail in rows:
        mark = {True: "[green]ok[/]", False: "[red]FAILED[/]", None: "[dim]--[/]"}[ok]
        table.add_row(name, mark, detail)
    console = Console(width=max(Console().width, 140))
    console.print(table)
    failed = [name for name, ok, _ in rows if ok is False]
    if failed:
        console.print(f"{len(failed)} check{'s' if len(failed) != 1 else ''} failed: {', '.join(failed)}")
        return 1
    console.print("everything this machine needs for these levels and servers is in place")
    return 0
