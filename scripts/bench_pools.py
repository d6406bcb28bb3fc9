#!/usr/bin/env python
"""The HTTP backends at a GPU server's batch size: requests/s achieved over what N slots of a fixed
latency allow (1.0: the harness never keeps the server waiting) and the harness's CPU per request,
for the OpenAI and the Ollama backend against ``bench_server.py`` in its own process.

Why it exists (issue 35): on httpx, a pool sized to 256 slots made httpcore scan every connection
for each idle one on every request event, 52 ms of CPU per request and 6 % of the server's
throughput; the OpenAI backend now runs on aiohttp as the Ollama backend does.

    python scripts/bench_pools.py [--slots 256] [--latency 2.0] [--waves 5]
"""

from __future__ import annotations

import argparse
import asyncio
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_scale import FakeServer

from meceng.llm.factory import make_backend
from meceng.llm.messages import user_messages
from meceng.llm.types import ChatRequest, LLMSettings


async def measure(url: str, backend: str, slots: int, latency: float, waves: int) -> tuple[float, float]:
    """(efficiency, harness CPU ms per request) of ``waves`` x ``slots`` requests."""
    host = url + "/v1" if backend == "openai" else url
    client = make_backend(LLMSettings(model="bench", backend=backend, hosts=(host,), batch_size=slots))
    requests = [ChatRequest(user_messages(f"request {k}"), "select", f"t@{k}") for k in range(slots * waves)]
    cpu, t0 = time.process_time(), time.perf_counter()
    try:
        await asyncio.gather(*(client.chat(r) for r in requests))
    finally:
        await client.aclose()
    wall, cpu = time.perf_counter() - t0, time.process_time() - cpu
    return (len(requests) / wall) / (slots / latency), 1000 * cpu / len(requests)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--slots", type=int, default=256)
    parser.add_argument("--latency", type=float, default=2.0, help="seconds the fake server takes per request")
    parser.add_argument("--waves", type=int, default=5)
    args = parser.parse_args(argv)
    with FakeServer("--slots", str(args.slots), "--fixed-latency", str(args.latency)) as server:
        for backend in ("openai", "ollama"):
            efficiency, cpu_ms = asyncio.run(measure(server.url, backend, args.slots, args.latency, args.waves))
            print(f"{backend:<7} {args.slots} slots of {args.latency:g} s, {args.waves} waves: "
                  f"efficiency {efficiency:.3f}, harness CPU {cpu_ms:.2f} ms/request")
    return 0


if __name__ == "__main__":
    sys.exit(main())
