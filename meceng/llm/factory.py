"""Makes the backend a run's settings name: the one place that knows every backend module."""

from __future__ import annotations

from meceng.llm.backend_gold import GoldBackend
from meceng.llm.types import BACKENDS, Backend, LLMSettings, api_key


def make_backend(settings: LLMSettings) -> Backend:
    if settings.backend == "gold":
        return GoldBackend()
    if settings.backend == "ollama":
        from meceng.llm.backend_ollama import OllamaBackend

        return OllamaBackend(settings)
    if settings.backend == "openai":
        from meceng.llm.backend_openai import OpenAIBackend

        return OpenAIBackend(settings, api_key=api_key(settings))
    if settings.backend == "anthropic":
        from meceng.llm.backend_anthropic import AnthropicBackend

        return AnthropicBackend(settings, api_key=api_key(settings))
    if settings.backend == "scripted":  # it needs the tasks' drafts, which the pipeline hands it
        raise ValueError("the scripted backend is made by the run (pipeline/scripted.py), not here")
    raise ValueError(f"unknown backend {settings.backend!r} (choose {', '.join(BACKENDS)})")
