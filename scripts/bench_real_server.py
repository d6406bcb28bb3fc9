#!/usr/bin/env python
"""The harness's overhead per request against a real OpenAI-compatible server (llama.cpp's, through
llama-cpp-python, serving the tests' tiny random llama) beside the fake one (``bench_server.py``),
both in their own process and both through the OpenAI backend, with MecEng's real selection
prompts (~20 kB each).

The overhead is the harness process's CPU per request (building the body, HTTP, reading the answer,
scheduling): what a run pays on top of the server's time. Against the real server the wall time per
request is printed too: that is the server's (one request at a time), not the harness's.

    python scripts/bench_real_server.py [--requests 24]

Needs the ``servers`` extra; without it, says so and measures nothing.
"""

from __future__ import annotations

import argparse
import asyncio
import resource
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE))

from bench_scale import FakeServer  # noqa: E402
from llama_server import SERVED_NAME, LlamaServer, servers_missing, write_tiny_llama  # noqa: E402

from meceng.agents.prompts import DEFAULT_SELECT, select_prompt  # noqa: E402
from meceng.catalog.catalogs import rigid_catalog  # noqa: E402
from meceng.llm.backend_openai import OpenAIBackend  # noqa: E402
from meceng.llm.messages import user_messages  # noqa: E402
from meceng.llm.types import ChatRequest, LLMSettings  # noqa: E402
from meceng.tasks.registry import default_registry  # noqa: E402


def selection_requests(count: int) -> list[ChatRequest]:
    """The selection requests of ``count`` level 1-2 task instances, as a run sends them."""
    registry = default_registry()
    instances = registry.instances(registry.select(("1", "2"), None), 0, 1)[:count]
    menu = rigid_catalog().menu()
    return [ChatRequest(user_messages(select_prompt(DEFAULT_SELECT, i.description, menu)), "select", i.key)
            for i in instances]


def _cpu_s() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


async def _measure(url: str, requests: list[ChatRequest], slots: int) -> dict[str, float]:
    backend = OpenAIBackend(LLMSettings(model=SERVED_NAME, backend="openai", hosts=(url,), num_predict=16,
                                        batch_size=slots, timeout_s=300.0))
    try:
        await backend.chat(requests[0])  # connections open, the server warm: not counted
        cpu, t0 = _cpu_s(), time.perf_counter()
        answers = await asyncio.gather(*(backend.chat(r) for r in requests))
        wall, cpu = time.perf_counter() - t0, _cpu_s() - cpu
    finally:
        await backend.aclose()
    assert all(a.content for a in answers), "a request came back empty"
    return {"cpu_ms_per_request": 1000 * cpu / len(requests), "wall_s_per_request": wall / len(requests)}


def real_server_overhead(count: int = 24, slots: int = 4) -> dict[str, Any] | None:
    """Harness CPU (and wall) per request against llama.cpp's server and against the fake one; None
    when the servers extra is missing."""
    if servers_missing() is not None:
        return None
    requests = selection_requests(count)
    with tempfile.TemporaryDirectory(prefix="meceng-bench-") as tmp:
        model = write_tiny_llama(Path(tmp) / "tiny.gguf")
        with LlamaServer(model, n_ctx=8192) as server:
            real = asyncio.run(_measure(server.url, requests, slots))
    with FakeServer("--slots", str(slots), "--fixed-latency", "0.05") as fake:
        fake_figures = asyncio.run(_measure(fake.url + "/v1", requests, slots))
    return {"requests": count, "slots": slots, "real": real, "fake": fake_figures}


def report(figures: dict[str, Any] | None) -> str:
    if figures is None:
        return f"skipped: {servers_missing()}"
    real, fake = figures["real"], figures["fake"]
    return (f"harness CPU per request ({figures['requests']} selection requests, {figures['slots']} in flight, "
            f"OpenAI backend): llama.cpp server {real['cpu_ms_per_request']:.2f} ms, fake server "
            f"{fake['cpu_ms_per_request']:.2f} ms; wall per request {real['wall_s_per_request']:.3f} s on the "
            f"real server (its model time, one request at a time), {fake['wall_s_per_request']:.3f} s on the fake "
            f"(0.05 s latency, {figures['slots']} slots)")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--requests", type=int, default=24)
    args = parser.parse_args(argv)
    print(report(real_server_overhead(args.requests)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
