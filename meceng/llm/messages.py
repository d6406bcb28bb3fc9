"""The agent's conversation in one format, written by the agent loop; every backend translates it
to its own wire format (Ollama, OpenAI and Anthropic differ in how calls, results and pictures look)."""

from __future__ import annotations

from typing import Any

from meceng.llm.types import ChatResponse, ToolCall


def assistant_message(response: ChatResponse) -> dict[str, Any]:
    """The model's turn as the conversation keeps it: text, tool calls (with their ids) and, for
    Anthropic, the signed thinking that must go back with a tool-use turn."""
    message: dict[str, Any] = {"role": "assistant", "content": response.content}
    if response.tool_calls:
        message["tool_calls"] = [call.to_json() for call in response.tool_calls]
    if response.signature:
        message["thinking"], message["signature"] = response.thinking, response.signature
    return message


def tool_message(call: ToolCall, result: str, images: tuple[str, ...] = ()) -> dict[str, Any]:
    """A tool's answer to one call; ``images`` are base64-encoded PNGs (a ``snapshot``), which each
    backend sends the way its API carries pictures."""
    message: dict[str, Any] = {"role": "tool", "tool_call_id": call.id, "name": call.name, "content": result}
    if images:
        message["images"] = list(images)
    return message


IMAGE_MEDIA_TYPE = "image/png"  # what a tool's ``images`` are (base64 of the file's bytes)


def pictures_after_tool_results(messages: tuple[dict[str, Any], ...]) -> list[dict[str, Any]]:
    """The conversation for an API whose tool messages carry text only: the pictures of each run of
    tool answers move to one user message right after that run, with a line saying which calls they
    belong to.

    OpenAI's Chat Completions takes images in user messages only, and every tool answer must
    directly follow the assistant turn that called it, so the pictures cannot sit between the
    answers; Ollama's API takes ``images`` on any message, but some of its vision models' templates
    (Qwen3-VL's renderer) write a tool message's text without its images. A conversation without
    pictures comes back as it was, message for message."""
    out: list[dict[str, Any]] = []
    pictured: list[dict[str, Any]] = []
    for message in messages:
        if message["role"] != "tool" and pictured:
            out.append(_pictures_message(pictured))
            pictured = []
        if message["role"] == "tool" and message.get("images"):
            pictured.append(message)
            message = {k: v for k, v in message.items() if k != "images"}
        out.append(message)
    if pictured:
        out.append(_pictures_message(pictured))
    return out


def _pictures_message(answers: list[dict[str, Any]]) -> dict[str, Any]:
    """One user message with the pictures of these tool answers, in order, and a caption naming them."""
    named = []
    for answer in answers:
        count = len(answer["images"])
        call = f" {answer['tool_call_id']}" if answer.get("tool_call_id") else ""
        named.append(f"{answer['name']}{call} ({count} picture{'s' if count > 1 else ''})")
    return {"role": "user", "content": "Pictures returned by the tool calls above, in order: " + "; ".join(named),
            "images": [image for answer in answers for image in answer["images"]]}


def user_messages(*texts: str) -> tuple[dict[str, str], ...]:
    return tuple({"role": "user", "content": t} for t in texts)
