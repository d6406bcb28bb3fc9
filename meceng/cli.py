"""Command line: ``meceng tasks|evaluate|run``.

Exit codes: 0 success, 1 the graded program failed (``evaluate``), 2 wrong usage or unknown task.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
from pathlib import Path
from typing import Any

from meceng.agents.llm import LLMSettings
from meceng.agents.prompts import DEFAULT_CODE, DEFAULT_SELECT
from meceng.tasks.registry import default_registry

LEVELS = ("1", "2", "3a", "3b")


def _levels(text: str) -> tuple[str, ...]:
    levels = tuple(x.strip() for x in text.split(",") if x.strip())
    bad = [lv for lv in levels if lv not in LEVELS]
    if bad or not levels:
        raise argparse.ArgumentTypeError(f"levels must be a comma-separated subset of {', '.join(LEVELS)}")
    return levels


def _positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be >= 1")
    return value


def _think(text: str) -> bool | str:
    lowered = text.lower()
    if lowered in ("true", "on", "yes", "1"):
        return True
    if lowered in ("false", "off", "no", "0"):
        return False
    if lowered in ("low", "medium", "high"):
        return lowered
    raise argparse.ArgumentTypeError("think must be on/off or low/medium/high")


def add_llm_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--model", default="gold", help="model name (Ollama name, or 'gold')")
    parser.add_argument("--backend", choices=("ollama", "openai", "gold"), default=None,
                        help="LLM backend; default: gold for --model gold, else ollama")
    parser.add_argument("--host", "--base-url", action="append", default=None, dest="host",
                        help="server URL (Ollama: http://127.0.0.1:11434; openai: http://HOST:PORT/v1); "
                             "repeat for several servers")
    parser.add_argument("--temperature", type=float, default=0.0)
    parser.add_argument("--llm-seed", type=int, default=42, help="sampling seed sent to the server")
    parser.add_argument("--think", type=_think, default=False, help="on/off or low/medium/high")
    parser.add_argument("--num-ctx", type=_positive_int, default=4096)
    parser.add_argument("--num-predict", type=_positive_int, default=2048)
    parser.add_argument("--batch-size", type=_positive_int, default=4,
                        help="parallel requests per server (its OLLAMA_NUM_PARALLEL)")
    parser.add_argument("--llm-timeout", type=float, default=600.0, help="seconds per LLM request")


def add_run_arguments(parser: argparse.ArgumentParser) -> None:
    add_llm_arguments(parser)
    parser.add_argument("--levels", type=_levels, default=("1", "2"), help="e.g. 1,2")
    parser.add_argument("--only", action="append", default=[],
                        help="task slugs or ids, comma-separated; repeatable")
    parser.add_argument("--variations", type=_positive_int, default=3, help="parameter variations per model")
    parser.add_argument("--seed", type=int, default=0, help="first instance seed")
    parser.add_argument("--out", type=Path, default=Path("runs"), help="directory for run folders")
    parser.add_argument("--name", default=None, help="run folder name (default: time stamp + model)")
    parser.add_argument("--workers", type=_positive_int, default=None, help="parallel program executions")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per program execution")
    parser.add_argument("--executor", choices=("fork", "subprocess"), default="fork",
                        help="fork: warm fork server (default); subprocess: a cold interpreter per program")
    parser.add_argument("--agent", choices=("pipeline", "loop"), default="pipeline",
                        help="pipeline: the paper's two LLM steps; loop: a tool-calling agent that tests and repairs")
    parser.add_argument("--max-rounds", type=_positive_int, default=6, help="model calls per task in --agent loop")
    parser.add_argument("--token-budget", type=_positive_int, default=30000,
                        help="completion tokens per task in --agent loop")
    parser.add_argument("--select-template", default=DEFAULT_SELECT)
    parser.add_argument("--code-template", default=DEFAULT_CODE)
    parser.add_argument("--no-progress", action="store_true")
    parser.add_argument("--resume", type=Path, default=None, metavar="RUN_DIR",
                        help="continue a killed run in RUN_DIR with its saved settings")


def llm_settings(args: argparse.Namespace, model: str | None = None, temperature: float | None = None,
                 think: bool | str | None = None) -> LLMSettings:
    model = model or args.model
    backend = args.backend or ("gold" if model == "gold" else "ollama")
    if model == "gold":
        backend = "gold"
    return LLMSettings(
        model=model, backend=backend, hosts=tuple(args.host or ("http://127.0.0.1:11434",)),
        temperature=args.temperature if temperature is None else temperature, seed=args.llm_seed,
        think=args.think if think is None else think, num_ctx=args.num_ctx, num_predict=args.num_predict,
        batch_size=args.batch_size, timeout_s=args.llm_timeout,
    )


def run_settings(args: argparse.Namespace, llm: LLMSettings, name: str | None = None) -> Any:
    import os

    from meceng.agents.prompts import CODE_TEMPLATES, SELECT_TEMPLATES
    from meceng.pipeline import RunSettings

    if args.select_template not in SELECT_TEMPLATES:
        raise SystemExit(f"error: unknown --select-template {args.select_template!r}; "
                         f"choose from {', '.join(SELECT_TEMPLATES)}")
    if args.code_template not in CODE_TEMPLATES:
        raise SystemExit(f"error: unknown --code-template {args.code_template!r}; "
                         f"choose from {', '.join(CODE_TEMPLATES)}")
    return RunSettings(
        llm=llm, levels=args.levels, only=tuple(x.strip() for part in args.only for x in part.split(",") if x.strip()),
        variations=args.variations, seed=args.seed, out=args.out, run_name=name or args.name,
        workers=args.workers or max(1, os.cpu_count() or 1), exec_timeout_s=args.timeout,
        select_template=args.select_template, code_template=args.code_template,
        progress=not args.no_progress, executor=args.executor, agent=args.agent, max_rounds=args.max_rounds,
        token_budget=args.token_budget,
    )


# ----------------------------------------------------------------------------- commands


def cmd_tasks_list(args: argparse.Namespace) -> int:
    registry = default_registry()
    models = registry.select([args.level] if args.level else None)
    if args.json:
        print(json.dumps([{"id": m.id, "slug": m.slug, "name": m.name, "level": m.level,
                           "components": list(m.components)} for m in models], indent=1))
        return 0
    from rich.console import Console
    from rich.table import Table

    table = Table("id", "level", "slug", "name")
    for m in models:
        table.add_row(str(m.id), m.level, m.slug, m.name)
    Console().print(table)
    return 0


def _instance(args: argparse.Namespace) -> Any:
    registry = default_registry()
    try:
        model = registry.get(args.slug)
    except KeyError as exc:
        print(f"error: {exc.args[0]}", file=sys.stderr)
        raise SystemExit(2) from None
    return model.instance(args.seed)


def cmd_tasks_show(args: argparse.Namespace) -> int:
    instance = _instance(args)
    data = instance.to_json()
    if args.json:
        print(json.dumps(data, indent=1))
        return 0
    print(f"{instance.task_id} {instance.name} (level {instance.level}, seed {instance.seed})\n")
    print(instance.description + "\n")
    print("parameters: " + ", ".join(f"{k} = {v}" for k, v in instance.params.items()))
    print("required components: " + ", ".join(instance.required_components))
    return 0


def cmd_tasks_reference(args: argparse.Namespace) -> int:
    print(_instance(args).reference_program, end="")
    return 0


def cmd_evaluate(args: argparse.Namespace) -> int:
    from meceng.pipeline import evaluate_program
    from meceng.tools.executor import ExecutionLimits

    instance = _instance(args)
    try:
        code = args.code.read_text()
    except OSError as exc:
        print(f"error: cannot read {args.code}: {exc.strerror}", file=sys.stderr)
        return 2
    selected = tuple(x.strip() for x in args.components.split(",") if x.strip()) if args.components else None
    verdict, candidate, _ = asyncio.run(
        evaluate_program(instance, code, selected, limits=ExecutionLimits(timeout_s=args.timeout)))
    data = {"task": instance.slug, "seed": instance.seed, **verdict.to_json(), "execution": candidate.summary()}
    if args.json:
        print(json.dumps(data, indent=1, default=str))
    else:
        for stage in verdict.stages:
            mark = {True: "pass", False: "FAIL", None: " -- "}[stage.passed]
            print(f"[{mark}] {stage.name:<22} {stage.detail}")
        print(f"overall: {'success' if verdict.overall else 'failure'}"
              + (f" (first failure: {verdict.first_failure})" if verdict.first_failure else ""))
        if verdict.error_categories:
            print("error categories: " + ", ".join(verdict.error_categories))
        if verdict.infrastructure_error:
            print(f"infrastructure error: {verdict.infrastructure_error}")
    return 0 if verdict.overall else 1


def resumed_settings(args: argparse.Namespace) -> Any:
    from meceng.pipeline import RunSettings

    run_dir: Path = args.resume
    try:
        data = json.loads((run_dir / "settings.json").read_text())
    except (OSError, ValueError) as exc:
        raise SystemExit(f"error: {run_dir} is not a run folder with a readable settings.json ({exc})") from None
    import dataclasses

    settings = RunSettings.from_json(data, out=run_dir.parent, run_name=run_dir.name)
    return dataclasses.replace(settings, progress=not args.no_progress)


def cmd_run(args: argparse.Namespace) -> int:
    from meceng.logs import configure_logging
    from meceng.pipeline import run_benchmark

    settings = resumed_settings(args) if args.resume else run_settings(args, llm_settings(args))
    configure_logging(None, console=True)
    try:
        path = asyncio.run(run_benchmark(settings))
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    configure_logging(None)
    print_summary(path)
    return 0


def print_summary(run_json: Path) -> None:
    run = json.loads(run_json.read_text())
    summary = run["summary"]
    print(f"{run_json}\n{summary['counted']} tasks graded, {summary['infrastructure_failures']} infrastructure "
          "failures")
    # one line per level: parts and assemblies have different stages, a mixed rate would mislead
    for level, block in summary["levels"].items():
        line = "  ".join(f"{k}: {v * 100:.1f}%" for k, v in block["rates"].items() if v is not None)
        print(f"level {level} ({block['counted']}): {line}")


def cmd_report(args: argparse.Namespace) -> int:
    import time

    from meceng.report import build_report

    t0 = time.perf_counter()
    try:
        files = build_report(args.runs, args.out, args.models)
    except (FileNotFoundError, ValueError, KeyError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"report written in {time.perf_counter() - t0:.1f} s: {files['html']} {files['markdown']}")
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from meceng.viewer.site import build_site

    try:
        stats = build_site(args.runs, args.out, workers=args.workers, pages=not args.index_only)
    except (FileNotFoundError, ValueError, KeyError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"viewer written in {stats.seconds:.1f} s: {stats.records} records, {stats.pages} pages, "
          f"{stats.plots} plots drawn; open {stats.index.resolve().as_uri()}")
    return 0


def cmd_rescore(args: argparse.Namespace) -> int:
    from meceng.pipeline import rescore

    run_dir: Path = args.run_dir if args.run_dir.is_dir() else args.run_dir.parent
    if not (run_dir / "run.json").exists():
        print(f"error: {run_dir} holds no run.json", file=sys.stderr)
        return 2
    path = asyncio.run(rescore(run_dir))
    print_summary(path)
    return 0


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
        if name == "show":
            p.add_argument("--json", action="store_true")
        p.set_defaults(func=func)

    p = sub.add_parser("evaluate", help="grade a program against a task instance")
    p.add_argument("slug")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--code", type=Path, required=True, help="the Python program to grade")
    p.add_argument("--components", default=None, help="comma-separated chosen components (optional)")
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_evaluate)

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
    p.set_defaults(func=cmd_rescore)

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

    A full gold sweep over every level (thousands of Netgen meshes and PyMeshLab distances in
    this process) once ended in glibc's "malloc_consolidate(): unaligned fastbin chunk detected"
    abort while Python tore the extension modules down — after run.json and the summary were
    written, so a finished run exited 134. The cause is not found yet; nothing is left to do at
    that point, so the command-line entry points exit without the teardown.
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


if __name__ == "__main__":
    console_main()
