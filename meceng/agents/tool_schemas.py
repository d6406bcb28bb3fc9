"""The agent's tools as the model sees them: name, description and JSON-schema parameters of each
(sent as native tool definitions), and the fixed notes their answers carry."""

from __future__ import annotations

from typing import Any

from meceng.inspect.bodies import QUANTITIES

_CODE = {"type": "string", "description": "the complete program, as you would answer it"}

TOOL_SCHEMAS: tuple[dict[str, Any], ...] = (
    {
        "name": "simulate",
        "description": ("Run a complete Exudyn program and report what it built and how it moved, in the "
                        "description's terms (global frame, SI units, the catalog's component names): every body "
                        "with mass, centre of mass, inertia, initial position, orientation (local axes in global "
                        "terms, rotation accumulated about its spin axis) and velocities; "
                        "every connector with the bodies it joins, where, its free and locked directions, its "
                        "parameters; every load with its vector; then the bodies' states at a few times and the "
                        "range of every coordinate over the run; then the program's own sensors (mbs.AddSensor), "
                        "stored at every step and shown at sensor_samples times of sensor_window with each "
                        "column's largest and smallest value: use them to measure what the task asks of the "
                        "motion. Long lists are cut and say how to ask for more."),
        "parameters": {"type": "object", "properties": {
            "code": _CODE,
            "bodies": {"type": "array", "items": {"type": "integer"},
                       "description": "object numbers (#n) of the bodies to show in full, with their connectors"},
            "times": {"type": "array", "items": {"type": "number"},
                      "description": "times (s) at which to report the states (default: half the end time "
                                     "and the end time; at most eight)"},
            "quantities": {"type": "array", "items": {"type": "string", "enum": list(QUANTITIES)},
                           "description": "which states to report (default: all)"},
            "sensor_window": {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2,
                              "description": "[t0, t1] in s: the time window of the sensor tables (default: the "
                                             "whole run)"},
            "sensor_samples": {"type": "integer", "minimum": 2, "maximum": 200,
                               "description": "how many evenly spaced times each sensor table shows (default 41)"}},
            "required": ["code"]},
    },
    {
        "name": "snapshot",
        "description": ("Draw the program's system at t = 0 and at a later time (default: the end time): "
                        "rigid bodies as inertia-equivalent boxes, mass points as dots, ground, joints with their "
                        "axes, springs and constraints as lines, contacts, forces as arrows; three orthogonal views "
                        "and an isometric one."),
        "parameters": {"type": "object", "properties": {
            "code": _CODE, "time": {"type": "number", "description": "the second picture's time in s"}},
            "required": ["code"]},
    },
    {
        "name": "self_check",
        "description": ("Check a program for problems that need no reference solution: errors, redundant "
                        "constraints, nodes starting at the same place, non-finite or exploding coordinates. "
                        "Answers in words: the degrees of freedom, the findings one a line, the energy balance "
                        "against the motion's own energy and what in the system dissipates or feeds energy."),
        "parameters": {"type": "object", "properties": {"code": _CODE}, "required": ["code"]},
    },
    {
        "name": "compare",
        "description": ("Run two complete programs for the same system and compare how they move, with no "
                        "reference solution: A, your program, and B, the same system built another way (joints "
                        "instead of constraints, another reference frame or body order). Their bodies are matched "
                        "by mass, inertia and motion; centres of mass, velocities, angular velocities and principal "
                        "axes are compared at about 200 times over the run, within 0.1 % of the motion's scale. "
                        "Answers in words: which bodies were matched, the largest deviation, and where and when the "
                        "motions part. Two programs that part cannot both be right."),
        "parameters": {"type": "object", "properties": {
            "code_a": {"type": "string", "description": "program A: your program, complete, as you would answer it"},
            "code_b": {"type": "string", "description": "program B: the same system built another way, complete"}},
            "required": ["code_a", "code_b"]},
    },
    {
        "name": "list_components",
        "description": "The catalog of simulation components with one line each.",
        "parameters": {"type": "object", "properties": {}},
    },
    {
        "name": "component_docs",
        "description": "Documentation and a working example for the named catalog components.",
        "parameters": {"type": "object", "properties": {"names": {"type": "array", "items": {"type": "string"}}},
                       "required": ["names"]},
    },
)

MESH_PART_SCHEMA: dict[str, Any] = {
    "name": "mesh_part",
    "description": ("Build, mesh and reduce a complete part program (as you would answer it) and report what "
                    "it made: stage, error, volume, mass, bounding box, every interface with its area, centre, mean "
                    "outward normal and number of faces, the eigenfrequencies of the fixed-interface normal modes "
                    "of its Hurty-Craig-Bampton reduction, and the number of nodes. The program must hard-code maxh."),
    "parameters": {"type": "object", "properties": {"code": _CODE}, "required": ["code"]},
}

PART_SNAPSHOT_SCHEMA: dict[str, Any] = {
    "name": "snapshot",
    "description": ("Mesh a complete part program and draw the part: three orthogonal views and an isometric one, "
                    "its interfaces coloured and named."),
    "parameters": {"type": "object", "properties": {"code": _CODE}, "required": ["code"]},
}

FREQUENCIES_NOTE = ("fixed-interface normal modes of the Hurty-Craig-Bampton reduction (every interface clamped), "
                    "lowest first, in Hz")
