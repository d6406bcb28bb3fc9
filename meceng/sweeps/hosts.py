"""Which servers of a sweep's grid points answer, before the sweep starts (``scripts/sweep.py``)."""

from __future__ import annotations

import asyncio
from collections.abc import Sequence
from typing import Any, Protocol

import httpx


class Point(Protocol):
    """A sweep's grid point as far as probing its servers goes (``meceng.sweeps.spec.GridPoint``)."""

    model: Any  # its ``hosts``

    def llm(self) -> Any: ...  # its ``backend``


async def _answers(host: str, path: str, ok: tuple[int, ...], timeout_s: float = 3.0) -> bool:
    try:
        async with httpx.AsyncClient(timeout=timeout_s) as client:
            response = await client.get(host.rstrip("/") + path)
            return response.status_code in ok
    except httpx.HTTPError:
        return False


def unreachable_hosts(points: Sequence[Point]) -> list[str]:
    """Ollama hosts that do not answer ``/api/version`` and OpenAI-compatible servers that do not
    answer ``/models`` (401/403 count as up: the key is checked when the run starts). Hosted
    APIs are not probed."""
    hosts = sorted({h for p in points if p.llm().backend == "ollama" for h in p.model.hosts})
    openai_hosts = sorted({h for p in points if p.llm().backend == "openai" for h in p.model.hosts
                           if "api.openai.com" not in h})

    async def probe() -> list[str]:
        results = await asyncio.gather(*(_answers(h, "/api/version", (200,)) for h in hosts),
                                       *(_answers(h, "/models", (200, 401, 403)) for h in openai_hosts))
        return [h for h, ok in zip(hosts + openai_hosts, results, strict=True) if not ok]

    return asyncio.run(probe()) if hosts or openai_hosts else []
