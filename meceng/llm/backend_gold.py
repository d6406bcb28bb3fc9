"""The ``gold`` backend: answers with the ground truth, proving the harness end to end without a model."""

from __future__ import annotations

from meceng.llm.types import ChatRequest, ChatResponse, LLMError


class GoldBackend:
    """Answers with the ground truth: the required components and the reference program."""

    name = "gold"

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.gold is None:
            raise LLMError(f"no gold answer for {request.purpose} of {request.task_key}", transient=False)
        return ChatResponse(content=request.gold, done_reason="stop", endpoint="gold")

    async def aclose(self) -> None:
        return None
