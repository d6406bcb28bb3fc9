"""Several models behind one backend, for a consensus run across models (issue 37).

``--agent consensus --consensus-models a,b,c`` draws its K samples from M models: sample ``k`` is
asked of model ``k mod M`` (both of its requests, selection and program), so with K a multiple of M
every model writes K/M samples, and with K < M only the first K models are asked. The rule is
deterministic, so a resumed run asks each sample of the same model again and the record can name
the model of every sample without asking the server. Each model keeps its own settings (backend,
servers, think, token limits) and, in the run, its own response-cache keys.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from meceng.llm.types import Backend, ChatRequest, ChatResponse, LLMSettings


def member_of_sample(count: int, sample: int | None) -> int:
    """Which of ``count`` models writes sample ``sample`` (None: a request that is no sample, the first)."""
    return (sample or 0) % count


def model_of_sample(models: Sequence[LLMSettings], sample: int | None) -> LLMSettings:
    """The model that writes sample ``sample``."""
    return models[member_of_sample(len(models), sample)]


class EnsembleBackend:
    """Routes each request to the backend of its sample's model (``model_of_sample``)."""

    name = "ensemble"

    def __init__(self, members: Sequence[tuple[LLMSettings, Backend]]) -> None:
        if not members:
            raise ValueError("a consensus run across models needs at least one model")
        self.members = tuple(members)

    @property
    def models(self) -> tuple[LLMSettings, ...]:
        return tuple(settings for settings, _ in self.members)

    def wrapped(self, wrap: Callable[[Backend, LLMSettings], Backend]) -> EnsembleBackend:
        """The same ensemble with every member wrapped (the run's response cache, keyed per model)."""
        return EnsembleBackend([(settings, wrap(backend, settings)) for settings, backend in self.members])

    async def chat(self, request: ChatRequest) -> ChatResponse:
        return await self.members[member_of_sample(len(self.members), request.sample)][1].chat(request)

    async def aclose(self) -> None:
        for _, backend in self.members:
            await backend.aclose()
