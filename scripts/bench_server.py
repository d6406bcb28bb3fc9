#!/usr/bin/env python
"""A fake LLM server for the throughput benchmark, in its own process so that none of its CPU is
counted as the harness's: Ollama's ``/api/chat`` wire format (and, with ``--fixed-latency``,
OpenAI's ``/v1/chat/completions``), ``--slots`` requests served at once
(more wait in the server's queue, as with continuous batching at its limit), and a latency drawn per
request from a realistic distribution — selection short, code long, a heavy tail. It answers with the
ground truth, so the harness grades every task as it would a perfect model.

    python scripts/bench_server.py --slots 64 --levels 1,2 --variations 20 --seed 3000

Prints ``listening http://127.0.0.1:PORT`` once it serves; stops on SIGTERM or SIGINT.
"""

from __future__ import annotations

import argparse
import asyncio
import hashlib
import json
import math
import signal
import sys

from aiohttp import web

from meceng.agents.prompts import gold_code, gold_selection
from meceng.tasks.registry import default_registry


def latency(purpose: str, key: str, scale: float) -> float:
    """Seconds for one request, the same for the same request in every run: log-normal around a
    median of 1.5 s (selection) or 6 s (code), 3 % of the requests 4-10 times longer, and none
    longer than 60 s (an answer limit of 2048 tokens at ~35 tokens/s)."""
    digest = hashlib.sha256(f"{purpose}|{key}".encode()).digest()
    u1, u2, u3, u4 = (int.from_bytes(digest[i:i + 4], "big") / 2**32 for i in (0, 4, 8, 12))
    normal = math.sqrt(-2 * math.log(max(u1, 1e-12))) * math.cos(2 * math.pi * u2)
    median, sigma = (1.5, 0.4) if purpose == "select" else (6.0, 0.5)
    seconds = median * math.exp(sigma * normal)
    if u3 < 0.03:
        seconds *= 4 + 6 * u4
    return scale * min(seconds, 60.0)


def _reply(model: str, prompt: str, answer: str) -> web.Response:
    return web.json_response({
        "model": model, "created_at": "2026-11-24T00:00:00Z",
        "message": {"role": "assistant", "content": answer}, "done": True, "done_reason": "stop",
        "total_duration": 1, "load_duration": 0, "prompt_eval_count": len(prompt) // 4,
        "prompt_eval_duration": 1, "eval_count": len(answer) // 4, "eval_duration": 1,
    })


def build_app(slots: int, levels: tuple[str, ...], variations: int, seed: int, scale: float,
              fixed_latency: float | None = None, only: tuple[str, ...] | None = None,
              answer_latency: float | None = None) -> web.Application:
    """``fixed_latency``: every request takes exactly that long and is answered 'ok' (for measuring
    the client's scheduler alone); otherwise the ground truth of the tasks of ``levels`` among
    ``only``, after ``answer_latency`` seconds or, when None, a drawn latency."""
    gate = asyncio.Semaphore(slots)
    by_description: list = []
    if fixed_latency is None:
        registry = default_registry()
        instances = registry.instances(registry.select(levels, only), seed, variations)
        by_description = sorted(instances, key=lambda i: -len(i.description))

    ok = json.dumps(json.loads(_reply("bench", "", "ok").body)).encode()  # type: ignore[arg-type]
    ok_openai = json.dumps({  # the same answer on the OpenAI-compatible route
        "id": "chatcmpl-bench", "object": "chat.completion", "created": 0, "model": "bench",
        "choices": [{"index": 0, "message": {"role": "assistant", "content": "ok"}, "finish_reason": "stop"}],
        "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2}}).encode()

    async def chat(request: web.Request) -> web.Response:
        raw = await request.read()
        if fixed_latency is not None:  # as lean as a server can be: the client's cost is what is measured
            async with gate:
                await asyncio.sleep(fixed_latency)
            body = ok_openai if request.path.startswith("/v1/") else ok
            return web.Response(body=body, content_type="application/json")
        body = json.loads(raw)
        prompt = body["messages"][-1]["content"]
        instance = next((i for i in by_description if i.description in prompt), None)
        if instance is None:
            return web.json_response({"error": "unknown task"}, status=400)
        purpose = "select" if "<components>" in prompt else "code"
        async with gate:
            await asyncio.sleep(latency(purpose, instance.key, scale) if answer_latency is None else answer_latency)
        answer = (gold_selection(instance.required_components) if purpose == "select"
                  else gold_code(instance.reference_program))
        return _reply(body.get("model", "bench"), prompt, answer)

    app = web.Application(client_max_size=16 * 2**20)
    app.router.add_post("/api/chat", chat)
    app.router.add_post("/v1/chat/completions", chat)  # OpenAI's wire format, answered only with --fixed-latency
    return app


async def serve(args: argparse.Namespace) -> None:
    app = build_app(args.slots, tuple(args.levels.split(",")), args.variations, args.seed, args.scale,
                    args.fixed_latency, tuple(args.only.split(",")) if args.only else None, args.latency)
    runner = web.AppRunner(app, access_log=None)
    await runner.setup()
    site = web.TCPSite(runner, "127.0.0.1", args.port, backlog=4096)
    await site.start()
    port = site._server.sockets[0].getsockname()[1]  # type: ignore[union-attr]
    sys.stdout.write(f"listening http://127.0.0.1:{port}\n")
    sys.stdout.flush()
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for sig in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(sig, stop.set)
    await stop.wait()
    await runner.cleanup()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--port", type=int, default=0)
    parser.add_argument("--slots", type=int, default=64)
    parser.add_argument("--levels", default="1,2")
    parser.add_argument("--variations", type=int, default=20)
    parser.add_argument("--seed", type=int, default=3000)
    parser.add_argument("--scale", type=float, default=1.0, help="multiplies every latency")
    parser.add_argument("--fixed-latency", type=float, default=None, help="seconds per request, answer 'ok'")
    parser.add_argument("--only", default="", help="comma-separated task ids or slugs among --levels")
    parser.add_argument("--latency", type=float, default=None,
                        help="seconds per request, answering the ground truth (instead of a drawn latency)")
    asyncio.run(serve(parser.parse_args()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
