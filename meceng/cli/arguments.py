"""Argument types and groups shared by ``meceng run`` and ``scripts/sweep.py``, and the run settings
they make."""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
from pathlib import Path
from typing import TYPE_CHECKING

from meceng.agents.prompts import CODE_TEMPLATES, DEFAULT_CODE, DEFAULT_SELECT, SELECT_TEMPLATES
from meceng.llm.types import BACKENDS, DEFAULT_HOSTS, LLMSettings, backend_for

if TYPE_CHECKING:
    from meceng.pipeline import RunSettings

LEVELS = ("1", "2", "3a", "3b", "4")
#: --agent consensus's sampling temperature when none is given (its samples must differ to vote)
CONSENSUS_TEMPERATURE = 0.7


def parse_levels(text: str) -> tuple[str, ...]:
    levels = tuple(x.strip() for x in text.split(",") if x.strip())
    bad = [lv for lv in levels if lv not in LEVELS]
    if bad or not levels:
        raise argparse.ArgumentTypeError(f"levels must be a comma-separated subset of {', '.join(LEVELS)}")
    return levels


def parse_only(values: list[str] | None) -> tuple[str, ...]:
    """``--only`` given once or more, each comma-separated, as task keys; a key that names no task
    model is refused here (``UnknownTaskError``, a ``ValueError``), before anything starts."""
    from meceng.tasks.registry import default_registry

    only = tuple(x.strip() for part in values or () for x in part.split(",") if x.strip())
    default_registry().check(only)
    return only


def parse_models(text: str) -> tuple[str, ...]:
    """``--consensus-models a,b,c``: model names, at least two (one model is a plain consensus run)."""
    models = tuple(x.strip() for x in text.split(",") if x.strip())
    if len(models) < 2:
        raise argparse.ArgumentTypeError("name two models or more, comma-separated")
    return models


def positive_int(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("must be >= 1")
    return value


def parse_think(text: str) -> bool | str:
    lowered = text.lower()
    if lowered in ("true", "on", "yes", "1"):
        return True
    if lowered in ("false", "off", "no", "0"):
        return False
    if lowered in ("low", "medium", "high"):
        return lowered
    raise argparse.ArgumentTypeError("think must be on/off or low/medium/high")


def add_texts_argument(parser: argparse.ArgumentParser) -> None:
    """``--texts paper|open``: which task text the model reads (issue 36)."""
    from meceng.tasks.base import TEXTS

    parser.add_argument("--texts", choices=TEXTS, default="paper",
                        help="paper: the paper's task texts, which say how to write the program (graded by the "
                             "paper's stages); open: the system in an engineer's words, levels 1 and 2 only "
                             "(graded by behaviour)")


def add_llm_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--model", default="gold", help="model name (Ollama name, or 'gold')")
    parser.add_argument("--backend", choices=BACKENDS, default=None,
                        help="LLM backend; default: gold for --model gold, else ollama")
    parser.add_argument("--host", "--base-url", action="append", default=None, dest="host",
                        help="server URL (default per backend: ollama http://127.0.0.1:11434, openai "
                             "https://api.openai.com/v1 or http://HOST:PORT/v1 for vLLM/SGLang, anthropic "
                             "https://api.anthropic.com); repeat for several servers")
    parser.add_argument("--api-defaults", action="store_true",
                        help="send neither temperature nor seed: the API's default sampling (paper, Tables 2 "
                             "and 6); always so for anthropic, whose API refuses sampling parameters")
    parser.add_argument("--api-key-env", default=None, metavar="VARIABLE",
                        help="environment variable holding the API key (default OPENAI_API_KEY, "
                             "ANTHROPIC_API_KEY); the key itself is never written anywhere")
    parser.add_argument("--vision", action="store_true",
                        help="the model takes images: in --agent loop a picture of the program's system goes to "
                             "it (Anthropic image blocks, OpenAI image_url parts, Ollama images) instead of a text "
                             "description; the gold backend ignores it")
    parser.add_argument("--temperature", type=float, default=None, help="sampling temperature (default 0)")
    parser.add_argument("--llm-seed", type=int, default=42, help="sampling seed sent to the server")
    parser.add_argument("--think", type=parse_think, default=False, help="on/off or low/medium/high")
    parser.add_argument("--num-ctx", type=positive_int, default=4096)
    parser.add_argument("--num-predict", type=positive_int, default=2048)
    parser.add_argument("--batch-size", type=positive_int, default=4,
                        help="parallel requests per server (its OLLAMA_NUM_PARALLEL)")
    parser.add_argument("--llm-timeout", type=float, default=600.0, help="seconds per LLM request")


#: what ``--timeout`` limits (issue 45): CPU time, so that a verdict does not follow the machine's load
TIMEOUT_HELP = ("CPU seconds a program may use (default %(default)g): its own CPU time, all threads, enforced by "
                "the kernel in whole seconds; reaching it is the program's timeout. The wall clock stops a run at "
                "3x this plus 10 s; a run stopped there with CPU time to spare (a busy machine, a sleeping "
                "program) is an infrastructure failure, not graded and done again by --resume")


def add_run_arguments(parser: argparse.ArgumentParser) -> None:
    add_llm_arguments(parser)
    parser.add_argument("--levels", type=parse_levels, default=("1", "2"), help="e.g. 1,2")
    parser.add_argument("--only", action="append", default=[],
                        help="task slugs or ids, comma-separated; repeatable")
    add_texts_argument(parser)
    parser.add_argument("--variations", type=positive_int, default=3, help="parameter variations per model")
    parser.add_argument("--seed", type=int, default=0, help="first instance seed")
    parser.add_argument("--out", type=Path, default=Path("runs"), help="directory for run folders")
    parser.add_argument("--name", default=None, help="run folder name (default: time stamp + model)")
    parser.add_argument("--workers", type=positive_int, default=None, help="parallel program executions")
    parser.add_argument("--timeout", type=float, default=60.0, help=TIMEOUT_HELP)
    parser.add_argument("--executor", choices=("fork", "subprocess"), default="fork",
                        help="fork: warm fork server (default); subprocess: a cold interpreter per program")
    parser.add_argument("--agent", choices=("pipeline", "loop", "repair", "consensus"), default="pipeline",
                        help="pipeline: the paper's two LLM steps; loop: a tool-calling agent that tests and repairs; "
                             "repair: the repair benchmark (find and fix the seeded fault of a draft); consensus: "
                             "--samples independent programs per task grouped by behaviour, the largest group's "
                             "program as the answer and its share as the confidence (levels 1-2; temperature 0.7 "
                             "unless --temperature)")
    parser.add_argument("--samples", type=positive_int, default=5,
                        help="--agent consensus: independent programs per task")
    parser.add_argument("--consensus-models", type=parse_models, default=(), metavar="A,B,...",
                        help="--agent consensus across models: sample k is written by model k mod M of this list "
                             "(each with the run's --backend/--host settings; --model is then not used)")
    parser.add_argument("--tools", choices=("on", "off"), default="on",
                        help="--agent repair: with the agent's tools (simulate, snapshot, ...) or a single answer")
    parser.add_argument("--drafts-per-task", type=positive_int, default=1,
                        help="--agent repair: failing drafts per task instance")
    parser.add_argument("--max-rounds", type=positive_int, default=6, help="model calls per task in --agent loop")
    parser.add_argument("--token-budget", type=positive_int, default=30000,
                        help="completion tokens per task in --agent loop")
    parser.add_argument("--select-template", default=DEFAULT_SELECT)
    parser.add_argument("--code-template", default=DEFAULT_CODE)
    parser.add_argument("--no-progress", action="store_true")
    parser.add_argument("--resume", type=Path, default=None, metavar="RUN_DIR",
                        help="continue a killed run in RUN_DIR with its saved settings (--host, if given, "
                             "replaces the saved servers and asks again the prompts that did not fit the old "
                             "server's context)")


def llm_settings(args: argparse.Namespace, model: str | None = None, temperature: float | None = None,
                 think: bool | str | None = None) -> LLMSettings:
    model = model or args.model
    backend = backend_for(model, args.backend)
    if temperature is None:
        temperature = args.temperature
    if temperature is None:  # independent samples need sampling: consensus draws at 0.7 by default
        temperature = CONSENSUS_TEMPERATURE if getattr(args, "agent", None) == "consensus" else 0.0
    settings = LLMSettings(
        model=model, backend=backend, hosts=tuple(args.host or (DEFAULT_HOSTS[backend],)),
        api_defaults=args.api_defaults, api_key_env=args.api_key_env, temperature=temperature, seed=args.llm_seed,
        think=args.think if think is None else think, num_ctx=args.num_ctx, num_predict=args.num_predict,
        batch_size=args.batch_size, timeout_s=args.llm_timeout, vision=args.vision,
    )
    if settings.api_defaults and args.temperature is not None:  # it would be dropped without a word
        why = ("Anthropic's API (version 2026-10-21) takes no sampling parameters" if backend == "anthropic"
               else "--api-defaults sends no temperature")
        raise ValueError(f"--temperature {args.temperature:g} cannot be sent: {why}")
    return settings


def run_settings(args: argparse.Namespace, llm: LLMSettings, name: str | None = None) -> RunSettings:
    from meceng.pipeline import RunSettings

    if args.select_template not in SELECT_TEMPLATES:
        raise SystemExit(f"error: unknown --select-template {args.select_template!r}; "
                         f"choose from {', '.join(SELECT_TEMPLATES)}")
    if args.code_template not in CODE_TEMPLATES:
        raise SystemExit(f"error: unknown --code-template {args.code_template!r}; "
                         f"choose from {', '.join(CODE_TEMPLATES)}")
    only = parse_only(args.only)
    # a consensus run across models: each model's settings as --model's would be, the first one the run's
    models = tuple(llm_settings(args, model=m) for m in getattr(args, "consensus_models", ()))
    return RunSettings(
        llm=models[0] if models else llm, consensus_models=models, levels=args.levels, only=only,
        variations=args.variations, seed=args.seed, out=args.out, run_name=name or args.name,
        workers=args.workers or max(1, os.cpu_count() or 1), exec_timeout_s=args.timeout,
        select_template=args.select_template, code_template=args.code_template,
        progress=not args.no_progress, executor=args.executor, agent=args.agent, max_rounds=args.max_rounds,
        repair_tools=args.tools == "on", drafts_per_task=args.drafts_per_task,
        token_budget=args.token_budget, texts=args.texts, samples=args.samples,
    )


def resumed_settings(args: argparse.Namespace) -> RunSettings:
    from meceng.pipeline import RunSettings

    run_dir: Path = args.resume
    try:
        data = json.loads((run_dir / "settings.json").read_text())
    except (OSError, ValueError) as exc:
        raise SystemExit(f"error: {run_dir} is not a run folder with a readable settings.json ({exc})") from None

    settings = RunSettings.from_json(data, out=run_dir.parent, run_name=run_dir.name)
    if args.host:  # where the server is now: not part of what the run measures
        hosts = tuple(args.host)  # every model's of a consensus run across models
        settings = dataclasses.replace(settings, llm=dataclasses.replace(settings.llm, hosts=hosts),
                                       consensus_models=tuple(dataclasses.replace(m, hosts=hosts)
                                                              for m in settings.consensus_models),
                                       retry_overflow=True)
    return dataclasses.replace(settings, progress=not args.no_progress)
