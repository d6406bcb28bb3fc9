"""What a server says about itself before a run: reachable, the model served, its context.

For ``meceng doctor``: each backend's own listing routes, nothing sent to the model. Ollama:
``/api/version``, ``/api/tags``, ``/api/show`` (the model's trained ``context_length``; a run asks
for ``num_ctx`` per request). OpenAI-compatible servers: ``/models`` (vLLM's and SGLang's entries
carry ``max_model_len``, llama.cpp's a ``meta.n_ctx_train``) and, where there is one, llama.cpp's
``/props`` (the context of one slot, ``default_generation_settings.n_ctx``, and ``total_slots``).
Anthropic: the Models API (``/v1/models/{model}``) through the SDK.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass
from typing import Any

import httpx

from meceng.llm.types import LOCAL_BACKENDS, LLMSettings, api_key

TIMEOUT_S = 5.0


@dataclass(frozen=True)
class ServerInfo:
    """One host as ``meceng doctor`` shows it; ``context``/``slots`` are None where the API is silent."""

    host: str
    reachable: bool
    served: bool
    detail: str
    models: tuple[str, ...] = ()
    context: int | None = None
    slots: int | None = None

    @property
    def ok(self) -> bool:
        return self.reachable and self.served


async def probe(settings: LLMSettings) -> list[ServerInfo]:
    """Every host of ``settings``, asked at once; the gold backend has none."""
    if settings.backend in LOCAL_BACKENDS:
        return []
    ask = {"ollama": _ollama, "openai": _openai, "anthropic": _anthropic}[settings.backend]
    return list(await asyncio.gather(*(ask(settings, host.rstrip("/")) for host in settings.hosts)))


def _down(host: str, exc: BaseException) -> ServerInfo:
    return ServerInfo(host, False, False, f"no answer: {type(exc).__name__}: {exc}"[:300])


async def _ollama(settings: LLMSettings, host: str) -> ServerInfo:
    try:
        async with httpx.AsyncClient(base_url=host, timeout=TIMEOUT_S) as client:
            version = (await client.get("/api/version")).json().get("version", "?")
            names = tuple(m.get("name", "") for m in (await client.get("/api/tags")).json().get("models", ()))
            wanted = {settings.model, f"{settings.model}:latest"}
            served = bool(wanted & set(names))
            trained = None
            if served:
                shown = await client.post("/api/show", json={"model": settings.model})
                info = shown.json().get("model_info", {}) if shown.status_code == 200 else {}
                trained = next((int(v) for k, v in info.items() if k.endswith(".context_length")), None)
    except (httpx.HTTPError, ValueError) as exc:
        return _down(host, exc)
    detail = f"Ollama {version}; " + (
        f"{settings.model} served; a run asks num_ctx {settings.num_ctx:,} per request"
        + (f" (the model was trained for {trained:,})" if trained else "")
        if served else f"{settings.model} not pulled (has: {', '.join(names[:8]) or 'none'})")
    return ServerInfo(host, True, served, detail, names, settings.num_ctx if served else None)


async def _openai(settings: LLMSettings, host: str) -> ServerInfo:
    key = api_key(settings)
    headers = {"Authorization": f"Bearer {key}"} if key else {}
    try:
        async with httpx.AsyncClient(timeout=TIMEOUT_S, headers=headers) as client:
            listing = await client.get(f"{host}/models")
            if listing.status_code in (401, 403):
                return ServerInfo(host, True, False, f"/models refused the key ({listing.status_code})")
            entries = listing.json().get("data", [])
            props = await _props(client, host)
    except (httpx.HTTPError, ValueError, AttributeError) as exc:
        return _down(host, exc)
    names = tuple(str(e.get("id", "")) for e in entries)
    entry = next((e for e in entries if e.get("id") == settings.model), None)
    context, said = _openai_context(entry, props)
    slots = props.get("total_slots") if props else None
    if entry is None:
        return ServerInfo(host, True, False, f"{settings.model} not served (serves: {', '.join(names) or 'none'})",
                          names, context, slots)
    detail = f"{settings.model} served; context {said}" + (f"; {slots} slots" if slots else "")
    return ServerInfo(host, True, True, detail, names, context, slots)


async def _props(client: httpx.AsyncClient, host: str) -> dict[str, Any]:
    """llama.cpp's ``/props`` (at the server's root, beside ``/v1``); {} from any other server."""
    root = host[:-3] if host.endswith("/v1") else host
    try:
        response = await client.get(f"{root}/props")
        return response.json() if response.status_code == 200 else {}
    except (httpx.HTTPError, ValueError):
        return {}


def _openai_context(entry: dict[str, Any] | None, props: dict[str, Any]) -> tuple[int | None, str]:
    slot = (props.get("default_generation_settings") or {}).get("n_ctx")
    if slot:
        return int(slot), f"{int(slot):,} tokens per slot (llama.cpp /props)"
    if entry and entry.get("max_model_len"):
        return int(entry["max_model_len"]), f"{int(entry['max_model_len']):,} tokens (max_model_len)"
    trained = ((entry or {}).get("meta") or {}).get("n_ctx_train")
    if trained:
        return None, f"not said (the model was trained for {int(trained):,})"
    return None, "not said by the server"


async def _anthropic(settings: LLMSettings, host: str) -> ServerInfo:
    import anthropic

    key = api_key(settings)
    if not key:
        return ServerInfo(host, False, False, f"no API key: set {settings.api_key_env or 'ANTHROPIC_API_KEY'}")
    client = anthropic.AsyncAnthropic(api_key=key, base_url=host, max_retries=0, timeout=TIMEOUT_S)
    try:
        model = (await client.models.retrieve(settings.model)).model_dump()
    except anthropic.NotFoundError:
        return ServerInfo(host, True, False, f"{settings.model} not offered by the API")
    except anthropic.APIStatusError as exc:
        return ServerInfo(host, True, False, f"the Models API answered {exc.status_code}")
    except anthropic.APIConnectionError as exc:
        return _down(host, exc)
    finally:
        await client.close()
    context = model.get("max_input_tokens") or model.get("context_window")
    said = f"context {int(context):,} tokens" if context else "context not said by the API"
    return ServerInfo(host, True, True, f"{settings.model} offered; {said}", (settings.model,),
                      int(context) if context else None)
