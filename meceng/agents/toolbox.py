"""The tools an agent may call while it builds a model, and what they report.

Every tool runs the agent's own program in the same isolated executor as the evaluation and
reports only what that program produced: stage reached, error, a summary of its system and a few
sampled outputs. Nothing of the ground truth is ever returned; the only task information used is
what the description already states (end time and number of steps).
"""

from __future__ import annotations

import base64
import json
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from meceng.agents.balance import energy_balance, energy_words
from meceng.agents.compare import compare_programs
from meceng.agents.energy import ENERGY_CODE, ENERGY_MARK, parse_energy
from meceng.agents.prompts import neutral
from meceng.agents.tool_schemas import FREQUENCIES_NOTE, MESH_PART_SCHEMA, PART_SNAPSHOT_SCHEMA, TOOL_SCHEMAS
from meceng.catalog.component import Catalog
from meceng.inspect import snapshot as pictures
from meceng.inspect.answer import render
from meceng.inspect.bodies import QUANTITIES, Ask
from meceng.inspect.sensors import sensor_words
from meceng.inspect.view import build_view
from meceng.tasks.base import SimSettings, TaskInstance
from meceng.tools.execution import Execution, ExecutionLimits
from meceng.tools.executor import execute
from meceng.tools.meshcheck import check_mesh_size
from meceng.tools.recording import REFINE, recording, run_recorded
from meceng.tools.warm import WarmPool

MAX_TEXT = 1500
#: The most rows of a sensor the child sends back (a table shows at most 200, interpolated).
SENSOR_ROWS = 20000


@dataclass(frozen=True)
class ToolResult:
    """A tool's answer: text, and pictures (base64 PNG) for a model that takes images."""

    text: str
    images: tuple[str, ...] = ()


@dataclass
class Toolbox:
    """Tools bound to one task instance (its stated simulation time) and one executor."""

    instance: TaskInstance
    catalog: Catalog
    limits: ExecutionLimits = field(default_factory=ExecutionLimits)
    pool: WarmPool | None = None
    calls: Counter[str] = field(default_factory=Counter)
    files: dict[str, Path] | None = None  # the saved parts an assembly's program loads
    vision: bool = False  # snapshot answers with a picture (else with its description in words)

    @property
    def schemas(self) -> tuple[dict[str, Any], ...]:
        """A part is meshed, not simulated: it gets ``mesh_part`` and its own snapshot instead."""
        if self.instance.kind == "part":
            return (MESH_PART_SCHEMA, PART_SNAPSHOT_SCHEMA,
                    *(t for t in TOOL_SCHEMAS if t["name"] in ("list_components", "component_docs")))
        return TOOL_SCHEMAS

    async def call(self, name: str, arguments: dict[str, Any]) -> ToolResult:
        """Run a tool; unknown tools and bad arguments are answered, never raised."""
        self.calls[name] += 1
        if "_unparsed" in arguments:  # the backend could not read the call's arguments as JSON
            return ToolResult(json.dumps({"error": f"the arguments of {name} are not valid JSON (cut off by the "
                                                   f"answer limit?): {str(arguments['_unparsed'])[:200]}"}))
        try:
            if name not in {t["name"] for t in self.schemas}:
                raise LookupError(name)
            if name == "mesh_part":
                return ToolResult(json.dumps(await self.mesh_part(str(arguments["code"]))))
            if name == "simulate":
                return ToolResult(await self.simulate(str(arguments["code"]), _ask(arguments),
                                                      _times(arguments.get("times")),
                                                      window=_window(arguments.get("sensor_window")),
                                                      samples=int(arguments.get("sensor_samples") or 41)))
            if name == "snapshot":
                return await self.snapshot(str(arguments["code"]), arguments.get("time"))
            if name == "compare":
                return ToolResult(await self.compare(str(arguments["code_a"]), str(arguments["code_b"])))
            if name == "self_check":
                return ToolResult(self_check_words(await self.self_check(str(arguments["code"]))))
            if name == "list_components":
                return ToolResult(self.catalog.menu())
            if name == "component_docs":
                names = arguments.get("names") or []
                if isinstance(names, str):
                    names = [n.strip() for n in names.split(",")]
                unknown = [n for n in names if n not in self.catalog]
                text = self.catalog.context([n for n in names if n in self.catalog])
                if self.instance.texts == "open":  # the documentation as the open text's prompt has it
                    text = neutral(text)
                return ToolResult(text + (f"\n\nUnknown components: {', '.join(unknown)}" if unknown else ""))
        except KeyError as exc:
            return ToolResult(json.dumps({"error": f"missing argument {exc.args[0]!r} for tool {name}"}))
        except (TypeError, ValueError) as exc:
            return ToolResult(json.dumps({"error": f"bad arguments for tool {name}: {exc}"}))
        except LookupError:
            pass
        return ToolResult(json.dumps(
            {"error": f"unknown tool {name!r}; tools: {', '.join(t['name'] for t in self.schemas)}"}))

    async def _mesh(self, code: str) -> tuple[Execution | None, dict[str, Any]]:
        """The part program's own part: nothing of the ground truth (the finest allowed maxh is
        half the size the description states)."""
        stated = self.instance.part.maxh
        check = check_mesh_size(code, stated / 2)
        if check.code is None:
            return None, {"stage": "flagged", "error": check.error}
        limits = replace(self.limits, mode="part", n_modes=self.instance.part.n_modes,
                         timeout_s=max(self.limits.timeout_s, 300.0))
        run = await execute(check.code, "", limits, pool=self.pool)
        report: dict[str, Any] = {"stage": run.stage, "error": _trim(run.error)}
        if check.raised:
            report["note"] = f"maxh below {stated / 2:g} m was raised to {stated / 2:g} m"
        return run, report

    async def mesh_part(self, code: str) -> dict[str, Any]:
        run, report = await self._mesh(code)
        part = run.part if run is not None else None
        if part is not None:
            geometry = part.get("geometry") or {}
            report.update(
                volume=geometry.get("volume"), mass=part["mass"], bounding_box=part.get("bounding_box"),
                material={"youngsModulus": part["youngs_modulus"], "poissonsRatio": part["poissons_ratio"],
                          "density": part["density"]},
                interfaces=geometry.get("interfaces") or {n: None for n in part["interfaces"]},
                eigenfrequencies_hz=[round(f, 4) for f in part["eigenfrequencies"][:8]],
                eigenfrequencies_are=FREQUENCIES_NOTE, nodes=part["nodes"])
        return _rounded(report)

    async def _run(self, code: str, energy: bool = False, inspect_times: tuple[float, ...] | None = None,
                   sensors: bool = False, motion: bool = False) -> Execution:
        # only the time span of the description; none of the ground truth's solver extras, except for a
        # design task, whose text names them (they change the values its spec is on)
        sim = self.instance.sim
        if sim is None:
            raise LookupError("no simulation for a part")
        block = sim.block() if self.instance.design is not None else SimSettings(sim.end_time, sim.steps).block()
        solve = "mbs.SolveDynamic(simulationSettings)"
        if sensors:  # every step stored (sensors only observe: the motion is the same)
            block = block.replace(solve, f"simulationSettings.solution.sensors.writePeriod = "
                                         f"{sim.end_time / sim.steps!r}\n{solve}")
        if energy:
            block = ENERGY_CODE + block.replace(solve, (
                "_e0 = _meceng_energy(mbs)\n" + solve + "\n"
                f"print({ENERGY_MARK!r} + str([_e0, _meceng_energy(mbs)]))"))
        limits = (self.limits if inspect_times is None
                  else replace(self.limits, inspect_times=inspect_times, inspect_loads=True))
        if sensors:
            limits = replace(limits, sensor_rows=SENSOR_ROWS)
        if motion:  # the bodies' motion on the common grid (``self_check``: the largest kinetic energy)
            limits = recording(limits, sim.end_time)
        return await execute(code, block, limits, pool=self.pool, files=self.files)

    async def _recorded(self, code: str, finer: bool = False) -> Execution:
        """The program with its bodies' motion recorded (``compare``): the description's end time and
        steps, or ``REFINE`` times the steps for the program's own step error."""
        sim = self.instance.sim
        if sim is None:
            raise LookupError("no simulation for a part")
        block = SimSettings(sim.end_time, sim.steps * (REFINE if finer else 1)).block()
        return await run_recorded(code, block, sim.end_time, self.limits, pool=self.pool, files=self.files)

    async def compare(self, code_a: str, code_b: str) -> str:
        return await compare_programs(self._recorded, code_a, code_b, lambda text: _trim(text, 600))

    def _end_time(self) -> float:
        return self.instance.sim.end_time if self.instance.sim is not None else 0.0

    async def simulate(self, code: str, ask: Ask | None = None, times: tuple[float, ...] = (),
                       window: tuple[float, float] | None = None, samples: int = 41) -> str:
        end = self._end_time()
        run = await self._run(code, inspect_times=_clip(times, end) or (end / 2, end), sensors=True)
        if run.items is None:
            return _no_system(run)
        view = build_view(run.items, run.system, run.inspection, run.trajectory, run.times)
        text = render(view, run.stage, _trim(run.error, 600), ask or Ask(), end_time=end)
        return text + "\n\n" + sensor_words(run.sensors, window, samples, end)

    async def snapshot(self, code: str, time: Any = None) -> ToolResult:
        if self.instance.kind == "part":
            run, report = await self._mesh(code)
            if run is None or run.surface is None:
                return ToolResult(json.dumps(report))
            interfaces = ((run.part or {}).get("geometry") or {}).get("interfaces") or {}
            png = pictures.draw_part(run.surface, interfaces)
            text = pictures.describe_part(run.surface, interfaces)
            said = "the picture of your part from the top, the front, the side and isometric: " + text.splitlines()[0]
        else:
            end = self._end_time()
            at = _clip(_times(time), end)[:1] or (end,)
            run = await self._run(code, inspect_times=at)
            if run.items is None:
                return ToolResult(_no_system(run))
            view = build_view(run.items, run.system, run.inspection, run.trajectory, run.times)
            png = pictures.draw(view, (0.0, at[0]), f"the program's system (stage {run.stage})")
            text = pictures.describe(view, (0.0, at[0]))
            stamps = [view.times[pictures.sample_index(view, t)] if view.times else 0.0 for t in (0.0, at[0])]
            said = "the picture of your program's system: " + pictures.caption(view, stamps)
            if run.error:
                text = f"the program stopped at stage '{run.stage}': {_trim(run.error, 300)}\n" + text
                said = text.splitlines()[0] + "\n" + said
        if self.vision:
            return ToolResult(said, (base64.b64encode(png).decode(),))
        return ToolResult("the picture in words (this model takes no images):\n" + text)

    async def self_check(self, code: str) -> dict[str, Any]:
        run = await self._run(code, energy=True, motion=True)
        findings: list[str] = []
        energy = parse_energy(run.stdout_tail)
        if run.error:
            findings.append(f"the program stopped at stage '{run.stage}': {_trim(run.error, 300)}")
        if run.system.get("redundantConstraints"):
            findings.append(f"{run.system['redundantConstraints']} redundant constraint(s): the solver may fail")
        if run.items is not None:
            positions = [tuple(np.round(p, 9)) for p in _node_positions(run.items)]
            duplicates = [p for p, n in Counter(positions).items() if n > 1]
            if duplicates:
                findings.append(f"several nodes start at the same position {list(duplicates[0])}")
        if run.trajectory is not None:
            if not np.all(np.isfinite(run.trajectory)):
                findings.append("coordinates become NaN or infinite")
            elif run.trajectory.size and np.max(np.abs(run.trajectory)) > 1e3:
                findings.append(f"coordinates grow to {np.max(np.abs(run.trajectory)):.3g}: check units and loads")
        report: dict[str, Any] = {"stage": run.stage, "degrees_of_freedom": run.system.get("degreeOfFreedom"),
                                   "findings": findings or ["no problem found"]}
        if energy is not None:
            view = build_view(run.items, run.system, None) if run.items is not None else None
            balance = energy_balance(*energy, run.motion, view, run.items)
            report["energy"] = balance
            if balance["explained"] is False:
                findings.append(f"the energy changes by {100 * balance['relative_change']:.3g} % of the motion's "
                                "energy and no element of the system explains it (see energy below)")
                report["findings"] = findings
        return report


def self_check_words(report: dict[str, Any]) -> str:
    """The self-check in words, like the other tools' answers: stage, degrees of freedom, each
    finding on its own line, the energy balance against the motion's own energy with what in the
    system dissipates or feeds energy (``balance.energy_words``)."""
    lines = [f"stage: {report['stage']}; degrees of freedom {report.get('degrees_of_freedom')}", "findings:"]
    lines += [f"  - {finding}" for finding in report["findings"]]
    energy = report.get("energy")
    if energy is not None:
        lines += energy_words(energy)
    return "\n".join(lines)


def _no_system(run: Execution) -> str:
    """A program that stopped before ``Assemble``, in the words of every other answer (not JSON)."""
    return (f"stage: {run.stage}; error: {_trim(run.error)}\n"
            "no system to show: the program stopped before its system was assembled (mbs.Assemble()); "
            "fix the error above and call again")


def _trim(text: str | None, limit: int = MAX_TEXT) -> str | None:
    if text is None or len(text) <= limit:
        return text
    return text[: limit // 2] + " [...] " + text[-limit // 2:]


def _node_positions(items: dict[str, list[dict[str, Any]]]) -> list[list[float]]:
    out = []
    for node in items.get("nodes", []):
        ref = node.get("referenceCoordinates") or []
        ini = node.get("initialCoordinates") or [0.0] * len(ref)
        if len(ref) >= 3 and "Ground" not in str(node.get("nodeType", "")):
            out.append([float(r) + float(i) for r, i in zip(ref[:3], ini[:3], strict=False)])
    return out


def _rounded(value: Any) -> Any:
    """Six significant digits; round-off (below 1e-12) as 0: numbers a model reads, not noise."""
    if isinstance(value, float):
        return 0.0 if abs(value) < 1e-12 else float(f"{value:.6g}")
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_rounded(v) for v in value]
    return value


def _ask(arguments: dict[str, Any]) -> Ask:
    bodies = tuple(int(b) for b in arguments.get("bodies") or () if str(b).lstrip("#").isdigit()
                   for b in [str(b).lstrip("#")])
    asked = ["orientation" if q == "angles" else q for q in arguments.get("quantities") or ()]  # the old name
    quantities = tuple(q for q in asked if q in QUANTITIES) or QUANTITIES
    return Ask(bodies=bodies, quantities=quantities)


def _times(values: Any) -> tuple[float, ...]:
    if values is None:
        return ()
    if not isinstance(values, list | tuple):
        values = [values]
    return tuple(float(v) for v in values)


def _window(values: Any) -> tuple[float, float] | None:
    if values is None:
        return None
    if not isinstance(values, list | tuple) or len(values) != 2:
        raise ValueError("sensor_window is [t0, t1]")
    lo, hi = sorted(float(v) for v in values)
    return lo, hi


def _clip(times: tuple[float, ...], end: float) -> tuple[float, ...]:
    """Requested times inside the run, at most eight of them."""
    return tuple(sorted({min(max(t, 0.0), end) for t in times}))[:8]
