"""The ``designer`` model: a scripted engineer for design tasks (level 4), to measure what the tools
are worth when the system is written right and only the value is open.

It answers every request with the ground truth's system (``request.gold``) but never with its
design: on a design task its first program declares the task model's closed-form estimate (what an
engineer computes without simulating), adds one sensor that stores the coordinates at every step,
and runs it through the agent's ``simulate``. It reads the sensor table back from the tool's answer
(the text a model reads, parsed, nothing else), measures the requirement's quantity on it with the
task model's own measurement, and corrects its value: first through the estimate's own sensitivity
(the estimate's value for the measured quantity against its value for the target), then by the
secant through its two latest runs, each clipped to the allowed range. It answers, without the
sensor, once a run lands within a third of the tolerance, or after ``MAX_RUNS`` runs with its
closest one. A two-variable design corrects its first variable and keeps the estimate of the rest.

So the pipeline grades, for the same instances, the estimate alone (the loop's first program) and
the estimate corrected with the tools (its final one), through the real agent loop, tools and
records. Where the estimate or the measurement is missing the designer says why in its answer; a
task that is not a design task gets the ground truth, as from ``gold``.

The plans come from the task room, which this room may not import: the run hands them in
(``pipeline/scripted.py``).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from meceng.llm.types import ChatRequest, ChatResponse, LLMError, ToolCall

#: Runs the designer makes before it answers with its closest one (the loop's default allows 5).
MAX_RUNS = 5
#: It answers once a run lands within this fraction of the tolerance.
AIM = 1.0 / 3.0
PROBE_NAME = "designProbe"
_PROBE = f"""
def _designProbe(mbs, t, sensorNumbers, factors, configuration):  # the designer's: every coordinate, every step
    return list(mbs.systemData.GetODE2CoordinatesTotal())
mbs.AddSensor(SensorUserFunction(sensorNumbers=[], sensorUserFunction=_designProbe, storeInternal=True,
                                 name='{PROBE_NAME}'))
"""
_DESIGN_LINE = re.compile(r"^DESIGN = \{.*\}$", re.MULTILINE)
_ROW = re.compile(r"^  -?[0-9.]")


@dataclass(frozen=True)
class DesignPlan:
    """What the designer knows of one design instance: what the prompt says (the variables and their
    ranges, the target and its tolerance) and an engineer's tools (the estimate, the measurement)."""

    variables: tuple[tuple[str, float, float], ...]  # (name, low, high)
    target: float
    tolerance: float  # absolute
    estimate: Callable[[float], dict[str, float]]  # the closed-form design for a value of the quantity
    measure: Callable[[np.ndarray, np.ndarray, dict[str, float]], float]  # (times, coordinates, design)


def _clip(plan: DesignPlan, design: dict[str, float]) -> dict[str, float]:
    out = {}
    for name, low, high in plan.variables:
        value = float(design.get(name, 0.5 * (low + high)))
        out[name] = float(f"{min(max(value if math.isfinite(value) else 0.5 * (low + high), low), high):.6g}")
    return out


def sensor_table(text: str, name: str = PROBE_NAME) -> np.ndarray | None:
    """The rows (t, column 0, ...) of sensor ``name``'s table in a ``simulate`` answer, or None."""
    lines = text.splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith("- #") and f" {name}:" in line), None)
    if start is None:
        return None
    rows = []
    header = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("  t, ")), None)
    if header is None:
        return None
    for line in lines[header + 1:]:
        if not _ROW.match(line):
            break
        rows.append([float(x) for x in line.split(",")])
    return np.asarray(rows, dtype=float) if len(rows) >= 2 else None


def program_with(gold: str, design: dict[str, float], probe: bool) -> str:
    """The gold system (its answer, fenced or not) with ``design`` declared (and, while measuring, the
    probe before Assemble)."""
    fenced = re.search(r"```python\n(.*?)```", gold, re.DOTALL)
    code = fenced.group(1) if fenced else gold
    code = _DESIGN_LINE.sub(lambda _: f"DESIGN = {json.dumps(design)}", code, count=1)
    if probe:
        head, assemble, tail = code.partition("mbs.Assemble()")
        code = head + _PROBE.lstrip("\n") + assemble + tail if assemble else code
    return code


def _runs(messages: tuple[dict[str, Any], ...]) -> list[tuple[dict[str, float], str]]:
    """The designer's earlier runs in this conversation: (the design it declared, the tool's answer)."""
    out: list[tuple[dict[str, float], str]] = []
    pending: dict[str, float] | None = None
    for message in messages:
        if message.get("role") == "assistant":
            for call in message.get("tool_calls") or []:
                function = call.get("function", call)
                arguments = function.get("arguments", {})
                if isinstance(arguments, str):
                    arguments = json.loads(arguments)
                match = _DESIGN_LINE.search(str(arguments.get("code", "")))
                pending = json.loads(match.group(0).partition("=")[2]) if match else None
        elif message.get("role") == "tool" and pending is not None:
            out.append((pending, str(message.get("content", ""))))
            pending = None
    return out


class DesignerBackend:
    """The scripted engineer: estimate first, then correct with ``simulate``'s sensor readings."""

    name = "designer"

    def __init__(self, plans: Mapping[str, DesignPlan]) -> None:
        self.plans = plans  # task key -> its plan (design tasks only)

    def next_design(self, plan: DesignPlan, measured: list[tuple[dict[str, float], float]]) -> dict[str, float]:
        """The design to run next, from the runs so far (design, measured value; nan: not measured)."""
        first = plan.variables[0][0]
        low, high = plan.variables[0][1], plan.variables[0][2]
        if not measured:
            return _clip(plan, plan.estimate(plan.target))
        design, value = measured[-1]
        x = design[first]
        if not math.isfinite(value):  # the quantity never showed: a tenth of the range further along
            step = (measured[-1][0][first] - measured[-2][0][first]) if len(measured) > 1 else 0.1 * (high - low)
            return _clip(plan, {**design, first: x + (step or 0.1 * (high - low))})
        finite = [(d[first], v) for d, v in measured if math.isfinite(v)]
        if len(finite) >= 2 and finite[-1][1] != finite[-2][1] and finite[-1][0] != finite[-2][0]:
            (x0, v0), (x1, v1) = finite[-2], finite[-1]
            return _clip(plan, {**design, first: x1 + (plan.target - v1) * (x1 - x0) / (v1 - v0)})
        # one run: the estimate's own sensitivity, what it would change to move its value by the miss
        shift = plan.estimate(plan.target)[first] - plan.estimate(value)[first]
        if not math.isfinite(shift) or shift == 0.0:
            shift = 0.05 * (high - low) * (1 if value < plan.target else -1)
        return _clip(plan, {**design, first: x + shift})

    def respond(self, request: ChatRequest, plan: DesignPlan) -> ChatResponse:
        gold = request.gold or ""
        measured: list[tuple[dict[str, float], float]] = []
        for design, answer in _runs(request.messages):
            rows = sensor_table(answer)
            try:
                value = float(plan.measure(rows[:, 0], rows[:, 1:], design)) if rows is not None else float("nan")
            except (ValueError, IndexError, FloatingPointError):
                value = float("nan")
            measured.append((design, value))
        done = [(d, v) for d, v in measured if math.isfinite(v)]
        close = [(d, v) for d, v in done if abs(v - plan.target) <= AIM * plan.tolerance]
        if close or len(measured) >= MAX_RUNS:
            best = close[-1] if close else min(done, key=lambda dv: abs(dv[1] - plan.target), default=None)
            design = best[0] if best else _clip(plan, plan.estimate(plan.target))
            said = (f"measured {best[1]:.6g} against the target {plan.target:.6g}" if best
                    else "no run measured the quantity")
            code = program_with(gold, design, probe=False)
            return ChatResponse(content=f"{said}.\n```python\n{code.rstrip()}\n```", endpoint="designer: answer")
        design = self.next_design(plan, measured)
        code = program_with(gold, design, probe=True)
        call = ToolCall("simulate", {"code": code, "sensor_samples": 200}, id=f"designer-{len(measured)}")
        words = ("my estimate" if not measured else
                 f"run {len(measured)} measured {measured[-1][1]:.6g} against {plan.target:.6g}; trying {design}")
        return ChatResponse(content=words, tool_calls=(call,), done_reason="tool_calls",
                            endpoint=f"designer: run {len(measured) + 1}")

    async def chat(self, request: ChatRequest) -> ChatResponse:
        if request.gold is None:
            raise LLMError(f"no gold answer for {request.purpose} of {request.task_key}", transient=False)
        plan = self.plans.get(request.task_key)
        if request.purpose != "code" or plan is None or not _DESIGN_LINE.search(request.gold):
            return ChatResponse(content=request.gold, done_reason="stop", endpoint="designer: gold")
        if not request.tools:  # no tools to correct with (a one-shot run): the estimate alone
            code = program_with(request.gold, _clip(plan, plan.estimate(plan.target)), probe=False)
            return ChatResponse(content=f"```python\n{code.rstrip()}\n```", endpoint="designer: estimate")
        return self.respond(request, plan)

    async def aclose(self) -> None:
        return None
