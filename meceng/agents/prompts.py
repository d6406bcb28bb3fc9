"""Prompt templates for the two LLM steps (paper section 2.2).

Templates are named like the paper's ablation variants (CI* for component selection, MBS* for
code generation); a run records which one it used. Placeholders: ``{description}``, ``{menu}``
(the component list), ``{context}`` (documentation of the chosen components).
"""

from __future__ import annotations

SELECT_TEMPLATES: dict[str, str] = {
    "CI1": """\
You are an expert in multibody dynamics and in the Python multibody simulation code Exudyn.

Task description:
{description}

Available simulation components:
{menu}

Choose all simulation components that are needed to build an Exudyn simulation model of the
described system. Answer only with the list of component names in the following XML-like format,
one component per line, and nothing else:
<components>
<component>FirstComponentName</component>
<component>SecondComponentName</component>
</components>
""",
    "CI2": """\
Which of the following Exudyn simulation components are required to model this system?

System:
{description}

Components:
{menu}

Reply with <components><component>Name</component>...</components> and no other text.
""",
}

CODE_TEMPLATES: dict[str, str] = {
    "MBS1": """\
You are an expert in multibody dynamics and in the Python multibody simulation code Exudyn.
Write a complete Python program that builds an Exudyn simulation model of the following system.

Task description:
{description}

Documentation of the simulation components you may use:
{context}

Rules:
- Start the program with:
  import exudyn as exu
  from exudyn.utilities import *
  import numpy as np
  SC = exu.SystemContainer()
  mbs = SC.AddSystem()
- Create bodies, nodes, connectors and loads in exactly the order given in the description;
  bodies in the order of their index.
- Use the functions shown in the documentation, SI units and the values given in the description.
- Do not read or write files, do not import os, sys, subprocess or similar modules, do not start a
  renderer or any visualization and do not plot.
- After the model is complete call mbs.Assemble(), then create
  simulationSettings = exu.SimulationSettings() with the end time and number of steps given in
  the description and call mbs.SolveDynamic(simulationSettings).
- Return the whole program in a single ```python code block.
""",
}

DEFAULT_SELECT = "CI1"
DEFAULT_CODE = "MBS1"


def select_prompt(template: str, description: str, menu: str) -> str:
    return SELECT_TEMPLATES[template].format(description=description, menu=menu)


def code_prompt(template: str, description: str, context: str) -> str:
    context = context or "(no components were chosen; use your knowledge of Exudyn)"
    return CODE_TEMPLATES[template].format(description=description, context=context)


def gold_selection(names: tuple[str, ...] | list[str]) -> str:
    lines = "".join(f"<component>{n}</component>\n" for n in names)
    return f"<components>\n{lines}</components>"


def gold_code(program: str) -> str:
    return f"```python\n{program.rstrip()}\n```"
