"""The self-validating agent: the model writes a program, calls the simulator as a tool, reads
what it reports and repairs the program before it answers.

The conversation runs through the backend's native tool calling (Ollama and OpenAI ``tools`` /
``tool_calls``, Anthropic ``tool_use`` / ``tool_result`` blocks); the loop writes one message format
(``assistant_message``, ``tool_message``) and the backend translates it. It is bounded by ``max_rounds`` model
calls and a completion-token budget. The first program the model produced and the final one are
both kept, so the benchmark can count what the loop adds.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from meceng.agents.parsing import extract_code
from meceng.agents.prompts import DEFAULT_CODE, gold_code
from meceng.agents.steps import Selection, generation_prompt
from meceng.agents.toolbox import Toolbox
from meceng.catalog.component import Catalog
from meceng.llm.messages import assistant_message, tool_message
from meceng.llm.types import Backend, ChatRequest, ContextExceeded, LLMError
from meceng.tasks.base import TaskInstance

AGENT_NOTE = """
You can call tools before you answer: `simulate(code)` runs a complete program and reports what it
built (every body, connector and load in global coordinates) and how it moved; `snapshot(code)`
draws the system at t = 0 and at the end (the tool draws it: your program itself still has no
visualization); `self_check(code)` looks for problems; `compare(code_a, code_b)` runs two programs
and says whether they move alike, and where and when they part; `list_components()` and
`component_docs(names)` give documentation. Test your program, compare what it built with the
description, repair it if needed, and then give the final program in a single ```python code block
without calling a tool. There is no reference solution to check against; one check that needs none
is to build the system a second, independent way (joints instead of constraints, another reference
frame or body order) and `compare` the two: two programs that part cannot both be right.
"""

PART_AGENT_NOTE = """
You can call tools before you answer: `mesh_part(code)` builds, meshes and reduces a complete part
program and reports its volume, mass, bounding box, interfaces (area, centre, outward normal, faces)
and the eigenfrequencies of its fixed-interface modes; `snapshot(code)` draws the part;
`list_components()` and `component_docs(names)` give documentation. Check the part against the
description, repair it if needed, and then give the final program in a single ```python code block
without calling a tool.
"""

#: A design task's addition: how to measure the requirement's quantity with the tools (never its verdict).
DESIGN_AGENT_NOTE = """This is a design task: the tools never say whether a value meets the requirement, but
`simulate` shows your program's own sensors, stored at every step (add them before mbs.Assemble(), e.g.
mbs.AddSensor(SensorBody(bodyNumber=oBody, outputVariableType=exu.OutputVariableType.Position,
storeInternal=True))), in a time window and at a resolution you choose (sensor_window, sensor_samples):
measure the quantity the requirement is on, and change your values until it is met.
"""


@dataclass
class AgentResult:
    first_code: str | None
    final_code: str | None
    error: str | None
    stop_reason: str
    rounds: int
    tool_calls: dict[str, int]
    completion_tokens: int
    prompt_tokens: int
    transcript: list[dict[str, Any]] = field(default_factory=list)
    infrastructure_error: str | None = None
    reasoning_tokens: int = 0  # of completion_tokens, where the API reports them
    context_exceeded: dict[str, Any] | None = None  # the first prompt did not fit the server's context

    def to_json(self) -> dict[str, Any]:
        return {
            "first_code": self.first_code, "final_code": self.final_code, "error": self.error,
            "stop_reason": self.stop_reason, "rounds": self.rounds, "tool_calls": self.tool_calls,
            "completion_tokens": self.completion_tokens, "prompt_tokens": self.prompt_tokens,
            "reasoning_tokens": self.reasoning_tokens, "transcript": self.transcript,
            "infrastructure_error": self.infrastructure_error,
        }


def agent_prompt(instance: TaskInstance, catalog: Catalog, names: tuple[str, ...] | list[str], template: str,
                 question: str | None = None) -> str:
    """The agent's first message: the code prompt (or ``question``, a repair task's) with the note
    on its tools appended."""
    note = PART_AGENT_NOTE if instance.kind == "part" else AGENT_NOTE
    if instance.design is not None:
        note += DESIGN_AGENT_NOTE
    return (question or generation_prompt(instance, catalog, names, template)) + note


async def run_agent(
    backend: Backend,
    instance: TaskInstance,
    catalog: Catalog,
    selection: Selection,
    toolbox: Toolbox,
    *,
    template: str = DEFAULT_CODE,
    max_rounds: int = 6,
    token_budget: int = 30000,
    prompt: str | None = None,
) -> AgentResult:
    """``prompt`` replaces the template's question (a repair task's); the tools' note follows it."""
    prompt = agent_prompt(instance, catalog, selection.names, template, question=prompt)
    messages: list[dict[str, Any]] = [{"role": "user", "content": prompt}]
    transcript: list[dict[str, Any]] = [{"role": "user", "content": prompt}]
    first_code: str | None = None
    last_code: str | None = None
    completion = prompt_tokens = reasoning = 0
    stop = "max_rounds"
    error: str | None = None
    rounds = 0
    for rounds in range(1, max_rounds + 1):
        request = ChatRequest(tuple(messages), "code", instance.key, gold=gold_code(instance.reference_program),
                              tools=toolbox.schemas)
        try:
            response = await backend.chat(request)
        except ContextExceeded as exc:
            if rounds == 1:  # the task itself does not fit: nothing the model did
                return AgentResult(None, None, str(exc), "infrastructure", rounds, dict(toolbox.calls), 0, 0,
                                   transcript, infrastructure_error=str(exc), context_exceeded=exc.to_json())
            stop = "context_full"  # the conversation the model led outgrew the context, like the token budget
            break
        except LLMError as exc:
            return AgentResult(first_code, last_code, str(exc), "infrastructure", rounds, dict(toolbox.calls),
                               completion, prompt_tokens, transcript, infrastructure_error=str(exc),
                               reasoning_tokens=reasoning)
        completion += response.completion_tokens
        prompt_tokens += response.prompt_tokens
        reasoning += response.reasoning_tokens
        entry: dict[str, Any] = {"role": "assistant", "content": response.content,
                                 "tool_calls": [c.to_json() for c in response.tool_calls], "meta": response.meta()}
        transcript.append(entry)
        if not response.tool_calls:
            extracted = extract_code(response.content)
            if extracted.code is not None:
                first_code = first_code or extracted.code
                last_code = extracted.code
                stop, error = "answered", None
            else:
                stop, error = "answered", extracted.error
            break
        messages.append(assistant_message(response))
        for call in response.tool_calls:
            # compare's program A is the program in progress (B is the model's second way of building it)
            code = (call.arguments.get("code") or call.arguments.get("code_a")) if isinstance(call.arguments, dict) \
                else None
            if isinstance(code, str) and code.strip():
                first_code = first_code or code
                last_code = code
            result = await toolbox.call(call.name, call.arguments if isinstance(call.arguments, dict) else {})
            messages.append(tool_message(call, result.text, result.images))
            entry = {"role": "tool", "name": call.name, "content": result.text}
            if result.images:  # the record keeps the picture's size, not the picture
                entry["images"] = [f"PNG, {len(image) * 3 // 4} bytes" for image in result.images]
            transcript.append(entry)
        if completion >= token_budget:
            stop = "token_budget"
            break
    if last_code is None and error is None:
        error = "the agent produced no program"
    return AgentResult(first_code, last_code, error, stop, rounds, dict(toolbox.calls), completion, prompt_tokens,
                       transcript, reasoning_tokens=reasoning)
