#!/usr/bin/env python
"""MecEng's run against a real OpenAI-compatible server next to a bare asyncio client replaying
MecEng's exact requests at the same concurrency: does the harness keep the server as busy as a
client that does nothing else?

Two phases against one server:

1. ``run_benchmark`` (the OpenAI backend, ``--batch-size`` requests in flight at most) over the
   chosen tasks; every request body it sends is recorded with its time and completion tokens;
2. a bare client (aiohttp, nothing but the HTTP) sends the same bodies, ``--batch-size`` at a
   time, in the order MecEng sent them.

For each: generated tokens/s between the first request sent and the last answer read, requests/s,
and the server's mean busy slots, sampled every 0.2 s from what the server says (llama.cpp's
``/slots`` ``is_processing``, else ``/metrics``: llama.cpp ``llamacpp:requests_processing``, vLLM
``vllm:num_requests_running``, SGLang ``sglang:num_running_reqs``; llama-cpp-python's server says
nothing). The ratio MecEng / bare is printed: 1.0 means the harness costs the server nothing.

Next to a GPU server (vLLM, SGLang, llama-server):

    python scripts/bench_gpu_server.py --base-url http://127.0.0.1:8000/v1 --model NAME \\
        --levels 1,2 --variations 2 --batch-size 128 --num-predict 256

Without ``--base-url`` it starts the test suite's tiny llama.cpp server (llama-cpp-python, one
request at a time, the ``servers`` extra) and runs a few tasks: the figures then say what the
harness costs on a CPU machine, not what a GPU gives.
"""

from __future__ import annotations

import argparse
import asyncio
import re
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import aiohttp

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from meceng.cli.arguments import parse_levels, parse_only  # noqa: E402
from meceng.llm.backend_openai import OpenAIBackend  # noqa: E402
from meceng.llm.scheduler import Endpoint  # noqa: E402
from meceng.llm.types import ChatRequest, LLMSettings  # noqa: E402
from meceng.pipeline import RunSettings, run_benchmark  # noqa: E402

SAMPLE_S = 0.2


@dataclass
class Phase:
    """What one phase sent and got: (start, end, completion tokens) per request."""

    name: str
    requests: list[tuple[float, float, int]] = field(default_factory=list)
    busy: list[float] = field(default_factory=list)

    def figures(self) -> dict[str, float | None]:
        if not self.requests:
            return {"requests": 0, "tokens_per_s": None, "requests_per_s": None, "busy_slots": None}
        wall = max(end for _, end, _ in self.requests) - min(start for start, _, _ in self.requests)
        tokens = sum(t for *_, t in self.requests)
        latency = sum(end - start for start, end, _ in self.requests) / len(self.requests)
        return {"requests": len(self.requests), "wall_s": wall, "completion_tokens": tokens, "latency_s": latency,
                "tokens_per_s": tokens / wall if wall else None, "requests_per_s": len(self.requests) / wall,
                "busy_slots": sum(self.busy) / len(self.busy) if self.busy else None}


class RecordingBackend(OpenAIBackend):
    """The OpenAI backend as a run uses it, writing down each body it sends and when."""

    def __init__(self, settings: LLMSettings, phase: Phase) -> None:
        super().__init__(settings)
        self.phase, self.bodies = phase, []

    def request_body(self, host: str, request: ChatRequest) -> dict[str, Any]:
        body = super().request_body(host, request)
        self.bodies.append(body)
        return body

    async def _send(self, endpoint: Endpoint, request: ChatRequest) -> tuple[Any, float]:
        t0 = time.perf_counter()
        raw, wall = await super()._send(endpoint, request)
        tokens = int((raw.get("usage") or {}).get("completion_tokens") or 0)
        self.phase.requests.append((t0, time.perf_counter(), tokens))
        return raw, wall


async def busy_slots(session: aiohttp.ClientSession, root: str) -> float | None:
    """Requests the server is working on now, by what it says; None: it says nothing."""
    metrics = ("llamacpp:requests_processing", "vllm:num_requests_running", "sglang:num_running_reqs")
    try:
        async with session.get(f"{root}/slots") as response:
            if response.status == 200:
                slots = await response.json()
                if isinstance(slots, list):
                    return float(sum(1 for s in slots if s.get("is_processing")))
        async with session.get(f"{root}/metrics") as response:
            if response.status == 200:
                text = await response.text()
                for name in metrics:
                    values = re.findall(rf"^{re.escape(name)}(?:{{[^}}]*}})? ([0-9.eE+-]+)$", text, re.MULTILINE)
                    if values:
                        return sum(float(v) for v in values)
    except (aiohttp.ClientError, ValueError, TimeoutError):
        return None
    return None


async def sample(phase: Phase, root: str, stop: asyncio.Event) -> None:
    async with aiohttp.ClientSession(timeout=aiohttp.ClientTimeout(total=2)) as session:
        while not stop.is_set():
            value = await busy_slots(session, root)
            if value is None:
                return  # the server says nothing: no column, no polling cost
            if phase.requests or value:  # from the first request on
                phase.busy.append(value)
            await asyncio.sleep(SAMPLE_S)


async def meceng_phase(args: argparse.Namespace, out: Path) -> tuple[Phase, list[dict[str, Any]], int]:
    phase = Phase("MecEng")
    llm = LLMSettings(model=args.model, backend="openai", hosts=(args.base_url,), batch_size=args.batch_size,
                      num_predict=args.num_predict, timeout_s=args.timeout, api_defaults=args.api_defaults)
    backend = RecordingBackend(llm, phase)
    settings = RunSettings(llm=llm, levels=args.levels, only=args.only, variations=args.variations, out=out,
                           run_name="bench", workers=args.workers, progress=False)
    stop = asyncio.Event()
    sampler = asyncio.ensure_future(sample(phase, root_of(args.base_url), stop))
    try:
        run_json = await run_benchmark(settings, backend=backend)
    finally:
        stop.set()
        await sampler
        await backend.aclose()
    import json

    tasks = len(json.loads(run_json.read_text())["tasks"])
    return phase, backend.bodies, tasks


async def bare_phase(args: argparse.Namespace, bodies: list[dict[str, Any]]) -> Phase:
    """The same bodies, ``batch_size`` in flight, nothing else done between them."""
    phase = Phase("bare client")
    gate = asyncio.Semaphore(args.batch_size)
    connector = aiohttp.TCPConnector(limit=args.batch_size, limit_per_host=args.batch_size)
    stop = asyncio.Event()
    sampler = asyncio.ensure_future(sample(phase, root_of(args.base_url), stop))
    async with aiohttp.ClientSession(connector=connector, timeout=aiohttp.ClientTimeout(total=args.timeout)) as s:

        async def one(body: dict[str, Any]) -> None:
            async with gate:
                t0 = time.perf_counter()
                async with s.post(f"{args.base_url}/chat/completions", json=body) as response:
                    data = await response.json()
                tokens = int((data.get("usage") or {}).get("completion_tokens") or 0)
                phase.requests.append((t0, time.perf_counter(), tokens))

        await asyncio.gather(*(one(b) for b in bodies))
    stop.set()
    await sampler
    return phase


def root_of(base_url: str) -> str:
    return base_url[:-3] if base_url.rstrip("/").endswith("/v1") else base_url.rstrip("/")


def report(meceng: Phase, bare: Phase, tasks: int) -> str:
    a, b = meceng.figures(), bare.figures()

    def cell(value: float | None, spec: str) -> str:
        return "n/a" if value is None else format(value, spec)

    lines = [f"{'':<12} {'requests':>8} {'wall s':>8} {'s/request':>9} {'tokens':>8} {'tokens/s':>9} {'req/s':>7} "
             f"{'busy slots':>10}"]
    for phase, f in ((meceng, a), (bare, b)):
        lines.append(f"{phase.name:<12} {f['requests']:>8} {cell(f.get('wall_s'), '.1f'):>8} "
                     f"{cell(f.get('latency_s'), '.2f'):>9} "
                     f"{cell(f.get('completion_tokens'), 'd'):>8} {cell(f['tokens_per_s'], '.1f'):>9} "
                     f"{cell(f['requests_per_s'], '.2f'):>7} {cell(f['busy_slots'], '.1f'):>10}")
    ratio = a["tokens_per_s"] / b["tokens_per_s"] if a["tokens_per_s"] and b["tokens_per_s"] else None
    lines.append(f"MecEng / bare client, generated tokens/s: {cell(ratio, '.3f')}; "
                 f"{tasks} task records, {cell(tasks / a['wall_s'] if a.get('wall_s') else None, '.2f')} tasks/s")
    if a["busy_slots"] is None:
        lines.append("busy slots: the server says nothing (no /slots, no /metrics)")
    return "\n".join(lines)


def parse(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--base-url", default=None, help="an OpenAI-compatible server (…/v1); default: the tiny llama")
    p.add_argument("--model", default=None, help="the served model's name (default: the tiny llama's)")
    p.add_argument("--levels", type=parse_levels, default=("1",))
    p.add_argument("--only", action="append", default=[], help="task keys, comma-separated (default: 4 of level 1)")
    p.add_argument("--variations", type=int, default=1)
    p.add_argument("--batch-size", type=int, default=2)
    p.add_argument("--num-predict", type=int, default=16)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--timeout", type=float, default=600.0)
    p.add_argument("--api-defaults", action="store_true", help="send neither temperature nor seed")
    args = p.parse_args(argv)
    args.only = parse_only(args.only)
    if args.base_url is None and not args.only:
        args.only = ("free_fall_mass_point", "flying_mass_point", "single_mass_oscillator", "single_pendulum")
    return args


async def measure(args: argparse.Namespace) -> str:
    with tempfile.TemporaryDirectory(prefix="meceng-bench-gpu-") as folder:
        meceng, bodies, tasks = await meceng_phase(args, Path(folder))
    bare = await bare_phase(args, bodies)
    return report(meceng, bare, tasks)


def main(argv: list[str] | None = None) -> int:
    args = parse(argv)
    if args.base_url is not None:
        args.model = args.model or "default"
        print(asyncio.run(measure(args)))
        return 0
    from llama_server import SERVED_NAME, TRAINED_CONTEXT, LlamaServer, servers_missing, write_tiny_llama

    missing = servers_missing()
    if missing:
        print(missing)
        return 0
    with tempfile.TemporaryDirectory(prefix="meceng-tiny-llama-") as folder:
        model = write_tiny_llama(Path(folder) / "tiny.gguf")
        with LlamaServer(model, n_ctx=TRAINED_CONTEXT) as server:
            args.base_url, args.model = server.url, SERVED_NAME
            print(f"tiny llama.cpp server (llama-cpp-python) at {server.url}; {args.batch_size} in flight, "
                  f"{args.num_predict} tokens per answer")
            print(asyncio.run(measure(args)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
