"""The subcommands of ``meceng``: each reads its parsed arguments, calls the library and prints what a
person running it wants to see. Exit codes: 0 success, 1 the graded program failed (``evaluate``),
2 wrong usage or unknown task."""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import sys
from pathlib import Path
from typing import Any

from meceng.cli.arguments import llm_settings, resumed_settings, run_settings
from meceng.tasks.registry import UnknownTaskError, default_registry


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
    except UnknownTaskError as exc:
        print(f"error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None
    texts = getattr(args, "texts", "paper")
    if texts == "paper":
        return model.instance(args.seed)
    if not getattr(model, "open_description", ""):  # parts, assemblies, and models still without one
        what = "a level-3 task" if model.level in ("3a", "3b") else "a task model without one yet"
        print(f"error: {model.slug} has no {texts} text ({what}); use --texts paper", file=sys.stderr)
        raise SystemExit(2)
    return model.instance(args.seed, texts=texts)


def cmd_tasks_show(args: argparse.Namespace) -> int:
    instance = _instance(args)
    data = instance.to_json()
    if instance.design is not None:  # how hard it is: the band of passing designs, the estimate's verdict
        from meceng.tasks.design_check import hardness

        data["design"].update(hardness(instance))
    if args.json:
        print(json.dumps(data, indent=1))
        return 0
    text = "" if instance.texts == "paper" else f", {instance.texts} text"
    print(f"{instance.task_id} {instance.name} (level {instance.level}, seed {instance.seed}{text})\n")
    print(instance.description + "\n")
    print("parameters: " + ", ".join(f"{k} = {v}" for k, v in instance.params.items()))
    print("required components: " + ", ".join(instance.required_components))
    if instance.design is not None:
        _print_design(data["design"])
    return 0


def _print_design(design: dict[str, Any]) -> None:
    spec, band, estimate = design["spec"], design.get("band"), design["estimate"]
    print(f"design: {', '.join(f'{k} in {v}' for k, v in design['variables'].items())} on the system "
          f"{design['system']}; spec ({spec['kind']}): {spec['quantity']} = {spec['target']:g} {spec['unit']} "
          f"± {spec['tolerance']:.3g}")
    if band:
        print(f"passing band (measured over {band['seeds']} instances): {band['band_percent']['min']}-"
              f"{band['band_percent']['max']} % of the range (median {band['band_percent']['median']} %); "
              f"the closed-form estimate passed {band['estimate']['passed']} of {band['estimate']['of']}")
    verdict = "passes" if estimate["passed"] else "fails"
    print(f"closed-form estimate ({estimate['method']}): {estimate['design']} -> {estimate['value']:.5g} "
          f"{spec['unit']}, {estimate['error_in_tolerances']:g} tolerances off: {verdict}")


def cmd_tasks_reference(args: argparse.Namespace) -> int:
    print(_instance(args).reference_program, end="")
    return 0


def cmd_tasks_prompt(args: argparse.Namespace) -> int:
    """The prompts exactly as a run sends them (the code prompt as after choosing the required
    components), each under a header line that is not part of it."""
    from meceng.pipeline import RunSettings, instance_prompts

    settings = RunSettings(select_template=args.select_template, code_template=args.code_template,
                           agent=args.agent)
    prompts = instance_prompts(_instance(args), settings)
    if args.json:
        print(json.dumps([vars(p) for p in prompts], indent=1))
        return 0
    for prompt in prompts:
        what = "component selection" if prompt.stage == "select" else "program"
        print(f"===== {prompt.key} ({prompt.kind}): {what} prompt, template {prompt.template} =====")
        print(prompt.text.rstrip("\n") + "\n")
    return 0


def cmd_evaluate(args: argparse.Namespace) -> int:
    from meceng.pipeline.rescore import evaluate_graded
    from meceng.tools.execution import ExecutionLimits

    instance = _instance(args)
    try:
        code = args.code.read_text()
    except OSError as exc:
        print(f"error: cannot read {args.code}: {exc.strerror}", file=sys.stderr)
        return 2
    selected = tuple(x.strip() for x in args.components.split(",") if x.strip()) if args.components else None
    graded = asyncio.run(evaluate_graded(instance, code, selected, limits=ExecutionLimits(timeout_s=args.timeout)))
    verdict, candidate = graded.verdict, graded.candidate
    data = {"task": instance.slug, "seed": instance.seed, "texts": instance.texts, **verdict.to_json(),
            **({"design": graded.facts["design"]} if "design" in graded.facts else {}),
            "execution": candidate.summary()}
    if args.json:
        print(json.dumps(data, indent=1, default=str))
    else:
        for stage in verdict.stages:
            mark = {True: "pass", False: "FAIL", None: " -- "}[stage.passed]
            print(f"[{mark}] {stage.name:<22} {stage.detail}" if stage.required else
                  f"[ -- ] {stage.name:<22} {stage.detail}")
        print(f"overall: {'success' if verdict.overall else 'failure'}"
              + (" (open text: graded by behaviour)" if verdict.graded_by == "behaviour" else "")
              + (f" (first failure: {verdict.first_failure})" if verdict.first_failure else ""))
        if verdict.error_categories:
            print("error categories: " + ", ".join(verdict.error_categories))
        if verdict.infrastructure_error:
            print(f"infrastructure error: {verdict.infrastructure_error}")
        if "design" in graded.facts:
            print(f"design: {graded.facts['design']['detail']}")
        if candidate.cpu_time is not None:  # what the limit counts, beside what the clock saw
            print(f"program time: {candidate.cpu_time:.1f} s CPU (limit {args.timeout:g} s), "
                  f"{candidate.wall_time:.1f} s wall")
        if verdict.behaviour is not None and verdict.graded_by == "paper":
            # beside the paper's verdict; the exit status stays the paper's (an open text's is behaviour)
            mark = {True: "pass", False: "FAIL", None: " -- "}[verdict.behaviour["passed"]]
            print(f"behaviour: [{mark}] {verdict.behaviour['detail']}")
    return 0 if verdict.overall else 1


def cmd_drafts(args: argparse.Namespace) -> int:
    from meceng.pipeline.drafts import drafts_of

    instance = _instance(args)
    if instance.kind == "assembly":
        print(f"error: {instance.slug} is an assembly: drafts exist for levels 1, 2 and 3a", file=sys.stderr)
        return 2
    graded = asyncio.run(drafts_of(instance))
    if args.json:
        print(json.dumps({"task": instance.slug, "seed": instance.seed,
                          "drafts": [g.to_json() for g in graded]}, indent=1))
        return 0
    print(f"{instance.slug}@{instance.seed}: {len(graded)} drafts, {sum(g.fails for g in graded)} fail the grader")
    for g in graded:
        verdict = (f"fails at {g.first_failure}" + (f" ({', '.join(g.categories)})" if g.categories else "")
                   if g.fails else "passes (not used)")
        agree = ("" if not g.fails or g.agrees is None  # None: graded by behaviour, no category to agree with
                 else "  label = grader" if g.agrees else "  LABEL ≠ GRADER")
        print(f"- {g.draft.id:<18} [{g.draft.label}] line {g.draft.line}: {g.draft.fault}\n"
              f"  {verdict}{agree}")
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    from meceng.logs import configure_logging
    from meceng.pipeline import run_benchmark
    from meceng.pipeline.preflight import StackUnusable

    try:
        settings = resumed_settings(args) if args.resume else run_settings(args, llm_settings(args))
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    configure_logging(None, console=True)
    try:
        path = asyncio.run(run_benchmark(settings))
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except StackUnusable as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 3
    configure_logging(None)
    print_summary(path)
    return 0


def print_summary(run_json: Path) -> None:
    run = json.loads(run_json.read_text())
    summary = run["summary"]
    print(f"{run_json}\n{summary['counted']} tasks graded, {summary['infrastructure_failures']} infrastructure "
          "failures")
    texts = run.get("texts") or run.get("settings", {}).get("pipeline", {}).get("texts", "paper")
    if texts != "paper":
        print(f"task texts: {texts} (graded by behaviour: topology, graph content and solution not required)")
    if run.get("without_text"):
        left = run["without_text"]
        print(f"left out, no {texts} text yet: {len(left)} task models ({', '.join(left)})")
    # one line per level: parts and assemblies have different stages, a mixed rate would mislead
    for level, block in summary["levels"].items():
        line = "  ".join(f"{k}: {v * 100:.1f}%" for k, v in block["rates"].items() if v is not None)
        unfit_here = block.get("context_exceeded") or 0
        lost_here = (block.get("infrastructure_failures") or 0) - unfit_here
        if not block["counted"]:
            line = "nothing graded"
        print(f"level {level} ({block['counted']}): {line}"
              + (f"  [{lost_here} lost to the server]" if lost_here else "")
              + (f"  [{unfit_here} did not fit the server's context]" if unfit_here else ""))
    limits = summary.get("limits")
    if limits and (limits["cpu_limit"] or limits["wall_bound"]):
        print(f"program executions: {limits['executions']}; {limits['cpu_limit']} reached the CPU limit (the "
              f"programs' timeouts), {limits['wall_bound']} the wall-clock bound (the machine's, not graded)")
    behaviour = summary.get("behaviour")
    # an open text's overall is behaviour, and so is a design task's (level 4): nothing to set beside it
    paper_levels = [lv for lv in summary.get("levels", {}) if lv != "4"]
    if behaviour and behaviour.get("graded") and texts == "paper" and paper_levels:
        differ = behaviour["paper_only"] + behaviour["behaviour_only"]
        print(f"behaviour (levels 1, 2, 3b): {behaviour['passed']}/{behaviour['graded']} passed "
              f"({100 * behaviour['rate']:.1f}%); the paper's verdict differs on {differ} "
              f"({behaviour['behaviour_only']} pass behaviour only, {behaviour['paper_only']} the paper only)")
    totals = summary.get("tokens", {}).get("totals")
    if totals:
        print(f"tokens: {totals['prompt']:,} prompt, {totals['completion']:,} completion "
              f"(of which {totals['reasoning']:,} reasoning)")
    repair = summary.get("repair")
    if repair:
        labels = ", ".join(f"{label} {k}/{n}" for label, (k, n) in repair["by_label"].items())
        print(f"repair (tools {'on' if repair['tools'] else 'off'}): {repair['repaired']}/{repair['tasks']} drafts "
              f"repaired — {labels}")
    print_consensus(run["tasks"])
    lost = [t for t in run["tasks"] if t.get("first_failure") == "infrastructure"]
    unfit = [t["context_exceeded"] for t in lost if t.get("context_exceeded")]
    if unfit:
        print(overflow_summary(unfit, run_json.parent))
    lost = [t for t in lost if not t.get("context_exceeded")]
    if lost:
        count = len(lost)
        print(f"{count} task{'s' if count != 1 else ''} lost to the server, left out of the rates; the first: "
              f"{lost[0]['slug']} seed {lost[0]['seed']}: {lost[0].get('infrastructure_error')}\n"
              f"redo them once that is fixed: meceng run --resume {run_json.parent}")


def print_consensus(tasks: list[dict[str, Any]]) -> None:
    """A consensus run's line: its answers against single samples, and its mean confidence."""
    from meceng.eval.calibration import accuracy, consensus_records

    records = consensus_records(tasks)
    if records:
        rates = accuracy(tasks)
        mean = sum(float(t["consensus"]["confidence"]) for t in records) / len(records)
        print(f"consensus: {100 * (rates['consensus'].value or 0):.1f}% of answers pass against "
              f"{100 * (rates['single'].value or 0):.1f}% of single samples ({rates['single'].n}); mean confidence "
              f"{mean:.2f} (meceng report: accuracy per confidence bin)")


def overflow_summary(unfit: list[dict[str, Any]], run_dir: Path) -> str:
    """What the prompts that did not fit the server's context need, said once for all of them."""
    count = len(unfit)
    prompts = [u["prompt_tokens"] for u in unfit if u.get("prompt_tokens")]
    contexts = sorted({u["context"] for u in unfit if u.get("context")})
    limit = max(u["answer_limit"] for u in unfit)
    largest = f"the largest {max(prompts):,} prompt tokens + {limit:,} answer limit" if prompts else \
        f"their prompt tokens + {limit:,} answer limit"
    need = f"at least {max(prompts) + limit:,} tokens" if prompts else "a larger context"
    return (f"{count} task{'s' if count != 1 else ''} not graded: the prompt did not fit the server's context of "
            f"{', '.join(f'{c:,}' for c in contexts) or '?'} tokens ({largest}); left out of the rates, "
            f"and a plain --resume keeps them (that server would refuse them again).\n"
            f"grade them on a server with a context of {need}: "
            f"meceng run --resume {run_dir} --host URL")


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
    from meceng.pipeline.preflight import StackUnusable

    if not args.run_dir.exists():
        print(f"error: {args.run_dir} does not exist (a run's folder or its run.json)", file=sys.stderr)
        return 2
    run_dir: Path = args.run_dir if args.run_dir.is_dir() else args.run_dir.parent
    if not (run_dir / "run.json").exists():
        print(f"error: {run_dir} holds no run.json", file=sys.stderr)
        return 2
    workers = args.workers or max(1, os.cpu_count() or 1)
    try:
        path = asyncio.run(rescore(run_dir, workers=workers, executor=args.executor, store=args.store,
                                   progress=True))
    except StackUnusable as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 3
    print_summary(path)
    return 0


