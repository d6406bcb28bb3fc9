"""Command line: ``meceng tasks|evaluate|drafts|run|report|view|rescore|doctor``.

Exit codes: 0 success, 1 the graded program failed (``evaluate``) or a check failed (``doctor``), 2 wrong
usage or unknown task, 3 this machine cannot grade the chosen levels (the preflight of ``run``/``rescore``).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from meceng.agents.prompts import CODE_TEMPLATES, DEFAULT_CODE, DEFAULT_SELECT, SELECT_TEMPLATES
from meceng.cli.arguments import (
    LEVELS,
    TIMEOUT_HELP,
    add_run_arguments,
    add_texts_argument,
    parse_levels,
    parse_think,
    positive_int,
)
from meceng.cli.commands import (
    cmd_drafts,
    cmd_evaluate,
    cmd_report,
    cmd_rescore,
    cmd_run,
    cmd_tasks_list,
    cmd_tasks_prompt,
    cmd_tasks_reference,
    cmd_tasks_show,
    cmd_view,
    print_summary,
)
from meceng.cli.doctor import add_doctor_arguments, cmd_doctor

__all__ = ["build_parser", "console_main", "exit_now", "main", "parse_levels", "parse_think", "positive_int",
           "print_summary"]


class _VersionAction(argparse.Action):
    """MecEng's version and those of the simulation stack it grades with (looked up only when asked)."""

    def __init__(self, option_strings: list[str], dest: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest, nargs=0, **kwargs)

    def __call__(self, parser: argparse.ArgumentParser, *args: Any, **kwargs: Any) -> None:
        from meceng import __version__
        from meceng.pipeline import versions

        found = versions()
        stack = ", ".join(f"{name} {found[name]}" for name in ("exudyn", "ngsolve", "scipy", "pymeshlab", "python"))
        print(f"meceng {__version__} ({stack})")
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="meceng", description="MecEng: LLMs building multibody models")
    parser.add_argument("--version", action=_VersionAction, help="show the versions and exit")
    sub = parser.add_subparsers(dest="command", required=True)

    tasks = sub.add_parser("tasks", help="list, show and print task models")
    tsub = tasks.add_subparsers(dest="tasks_command", required=True)
    p = tsub.add_parser("list", help="list task models")
    p.add_argument("--level", choices=LEVELS)
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_tasks_list)
    for name, func, helptext in (("show", cmd_tasks_show, "show one task instance"),
                                 ("reference", cmd_tasks_reference, "print the ground-truth program")):
        p = tsub.add_parser(name, help=helptext)
        p.add_argument("slug", help="task slug or paper id")
        p.add_argument("--seed", type=int, default=0)
        add_texts_argument(p)
        if name == "show":
            p.add_argument("--json", action="store_true")
        p.set_defaults(func=func)
    p = tsub.add_parser("prompt", help="print the prompts a model gets for one task instance")
    p.add_argument("slug", help="task slug or paper id")
    p.add_argument("--seed", type=int, default=0)
    add_texts_argument(p)
    p.add_argument("--select-template", choices=tuple(SELECT_TEMPLATES), default=DEFAULT_SELECT,
                   help="selection template (levels 1, 2, 3b; a part always gets PART1)")
    p.add_argument("--code-template", choices=tuple(CODE_TEMPLATES), default=DEFAULT_CODE,
                   help="code template (levels 1, 2, 3b; a part always gets PART1)")
    p.add_argument("--agent", choices=("pipeline", "loop"), default="pipeline",
                   help="loop: the code prompt with the agent's note on its tools, as --agent loop sends it")
    p.add_argument("--json", action="store_true", help="a list of {key, kind, stage, template, text}")
    p.set_defaults(func=cmd_tasks_prompt)

    p = sub.add_parser("evaluate", help="grade a program against a task instance")
    p.add_argument("slug")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--code", type=Path, required=True, help="the Python program to grade")
    add_texts_argument(p)
    p.add_argument("--components", default=None, help="comma-separated chosen components (optional)")
    p.add_argument("--timeout", type=float, default=60.0, help=TIMEOUT_HELP)
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_evaluate)

    p = sub.add_parser("drafts", help="an instance's repair drafts: its ground truth with one seeded fault each")
    p.add_argument("slug", help="task slug or paper id")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--json", action="store_true", help="every draft with its program and the grader's verdict")
    p.set_defaults(func=cmd_drafts)

    p = sub.add_parser("report", help="HTML, Markdown and PNG report from runs")
    p.add_argument("runs", nargs="+", type=Path, help="run folders, run.json files or sweep output folders")
    p.add_argument("--out", type=Path, default=Path("report"))
    p.add_argument("--models", type=Path, default=None,
                   help="sweep spec whose [[models]] give release (YYYY-MM-DD) and size_b, for Fig. 7")
    p.set_defaults(func=cmd_report)

    p = sub.add_parser("view", help="a static site to browse every task record of runs, with plots")
    p.add_argument("runs", nargs="+", type=Path, help="run folders, run.json files or sweep output folders")
    p.add_argument("--out", type=Path, default=Path("viewer"),
                   help="site folder (report/viewer: `meceng report --out report` then links to it)")
    p.add_argument("--workers", type=int, default=None, help="processes writing pages (default: up to 4)")
    p.add_argument("--index-only", action="store_true", help="write the index table only, no per-task pages")
    p.set_defaults(func=cmd_view)

    p = sub.add_parser("rescore", help="grade the saved programs of a run again, without any LLM call")
    p.add_argument("run_dir", type=Path)
    p.add_argument("--workers", type=positive_int, default=None,
                   help="programs run and graded at once (default: the machine's cores)")
    p.add_argument("--executor", choices=("fork", "subprocess"), default="fork",
                   help="fork: children of a warm fork server (default); subprocess: a cold interpreter each")
    p.add_argument("--reference-store", dest="store", type=Path, default=None,
                   help="a reference store (a sweep's references/ folder): ground truths made once are reused")
    p.set_defaults(func=cmd_rescore)

    p = sub.add_parser("doctor", help="check this machine and the servers before a sweep: system libraries, "
                       "the stack in the sandbox, one ground truth per task kind, model served, context")
    add_doctor_arguments(p)
    p.set_defaults(func=cmd_doctor)

    p = sub.add_parser("run", help="run the benchmark for one model")
    add_run_arguments(p)
    p.set_defaults(func=cmd_run)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into `head` and the like: stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0


def exit_now(code: int) -> None:
    """Leave with ``code`` once everything is flushed, skipping the interpreter's teardown.

    Nothing is left to do at that point, and the teardown of the extension modules (Exudyn,
    Netgen, PyMeshLab, matplotlib) is where a finished run once ended with glibc's
    "malloc_consolidate(): unaligned fastbin chunk detected" abort (exit 134) after run.json was
    written. That cause is found and fixed (see ``meceng.eval.parts.load_mesh_library``); the
    command-line entry points still skip the teardown so that a finished run's exit status says
    only how the run went.
    """
    import logging
    import os

    sys.stdout.flush()
    sys.stderr.flush()
    logging.shutdown()
    os._exit(code)


def console_main() -> None:
    """The ``meceng`` command (``main`` stays callable in-process, e.g. by tests)."""
    exit_now(main())

