"""Prompt templates for the two LLM steps (paper section 2.2).

Templates are named like the paper's ablation variants (CI* for component selection, MBS* for
code generation); a run records which one it used. Placeholders: ``{description}``, ``{menu}``
(the component list), ``{context}`` (documentation of the chosen components). The paper names the
variants but does not quote their texts; these are MecEng's own (docs/prompts.md).

The code templates serve levels 1-2 and the assemblies (3b) alike, so their file rule allows the
one file access an assembly needs, loading its parts (``fem.LoadFromFile('<part>.npz')``, which
the assembly's description requires): a flat "do not read files" contradicted every assembly
prompt (audit of issue 26). Levels 1-2 name no file, so for them the rule is unchanged in effect.
"""

from __future__ import annotations

import re

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
    "CI3": """Task: select simulation components for an Exudyn multibody model.

Mechanical system:
{description}

Catalog (name: purpose):
{menu}

Instructions:
1. Identify the bodies (mass points, rigid bodies or flexible parts) and how they are connected.
2. Identify loads, contacts and constraints.
3. Choose every catalog component needed for steps 1 and 2; do not invent names.
Output format (nothing else):
<components>
<component>Name</component>
</components>
""",
    "CI4": """{description}

From the list below, name the Exudyn components needed to simulate the system above.
{menu}

Format: <components><component>Name</component>...</components>
""",
    "CI5": """You are a careful simulation engineer. A colleague will write the Exudyn program using only the
documentation of the components you select, so a missing component makes the model impossible,
while an unnecessary one does no harm.

System description:
{description}

Components you can select:
{menu}

Answer strictly as:
<components>
<component>Name</component>
</components>
""",
    "CI6": """System: {description}
Components: {menu}
Which components are required? Use exactly the names above. Answer only with
<components><component>Name</component>...</components>
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
- Do not write files and do not read files, except the part files the description tells you to load;
  do not import os, sys, subprocess or similar modules, do not start a renderer or any visualization
  and do not plot.
- After the model is complete call mbs.Assemble(), then create
  simulationSettings = exu.SimulationSettings() with the end time and number of steps given in
  the description and call mbs.SolveDynamic(simulationSettings).
- Return the whole program in a single ```python code block.
""",
    "MBS2": """Write an Exudyn Python program for this system:
{description}

Exudyn documentation:
{context}

Use `import exudyn as exu`, `from exudyn.utilities import *`, `SC = exu.SystemContainer()`,
`mbs = SC.AddSystem()`; call `mbs.Assemble()` and then `mbs.SolveDynamic(simulationSettings)` with
the end time and number of steps given above. No file I/O except loading the part files the
description names, no graphics. Put the program in one
```python code block.
""",
    "MBS3": """Role: expert in multibody dynamics and the Exudyn simulation code.
Goal: a complete, runnable Python program that simulates the system below.

System description:
{description}

Component documentation (use these functions; follow their conventions exactly):
{context}

Requirements:
1. Program header: import exudyn as exu; from exudyn.utilities import *; import numpy as np;
   SC = exu.SystemContainer(); mbs = SC.AddSystem().
2. Order: create items in the order stated in the description; bodies in the order of their index.
3. Values: SI units; use exactly the numbers of the description; derive positions and rotations
   from the stated formulas.
4. Forbidden: writing files, reading files other than the part files the description tells you to
   load, imports of os/sys/subprocess/socket, renderer, visualization, plots.
5. Ending: mbs.Assemble(); simulationSettings = exu.SimulationSettings() with endTime and
   numberOfSteps from the description; mbs.SolveDynamic(simulationSettings).
6. Answer: one ```python code block with the whole program.
""",
    "MBS4": """{description}

{context}

Create the Exudyn model of the system described above (SC = exu.SystemContainer(),
mbs = SC.AddSystem()), adding items in the order given, then mbs.Assemble() and
mbs.SolveDynamic(simulationSettings) with the stated end time and steps. Do not write files or
open a renderer. Give the complete program in a single ```python block.
""",
}

DEFAULT_SELECT = "CI1"
DEFAULT_CODE = "MBS1"

#: Level 3a: the part is built, meshed and reduced, not simulated (paper section 2.3).
PART_SELECT_TEMPLATES: dict[str, str] = {
    "PART1": """\
You are an expert in CAD geometry with Netgen/NGSolve (netgen.occ) and in flexible multibody
modelling with Exudyn's FEM interface.

Part description:
{description}

Available components for geometry generation and FEM processing:
{menu}

Choose all components that are needed to build the exact geometry of the described part, mesh it,
import it into Exudyn's FEMinterface with its named interfaces and reduce it. Answer only with the
list of component names in the following XML-like format, one component per line, and nothing else:
<components>
<component>FirstComponentName</component>
<component>SecondComponentName</component>
</components>
""",
}

PART_CODE_TEMPLATES: dict[str, str] = {
    "PART1": """\
You are an expert in CAD geometry with Netgen/NGSolve (netgen.occ) and in flexible multibody
modelling with Exudyn's FEM interface. Write a complete Python program that builds the following
machine part, meshes it and prepares it as a reduced flexible body.

Part description:
{description}

Documentation of the components you may use:
{context}

Rules:
- Start the program with:
  from netgen.occ import *
  import ngsolve as ngs
  import numpy as np
  import exudyn as exu
  from exudyn.FEM import FEMinterface, HCBstaticModeSelection
- Build the solid exactly in the coordinate frame of the description (the part is compared without
  any alignment) and keep the final solid in a variable named `shape`.
- Name the interface faces exactly as the description says, after all boolean operations, fillets
  and chamfers.
- Mesh with ngs.Mesh(OCCGeometry(shape).GenerateMesh(maxh=...)) and HARD-CODE maxh as a number in that
  call; a program without a literal maxh is not run.
- Import the mesh with fem = FEMinterface(); fem.ImportMeshFromNGsolve(...) with the material and the
  interface names as boundaryNamesList, then compute the Hurty-Craig-Bampton modes.
- Do not read or write files, do not import os, sys, subprocess or similar modules, no visualization.
- Return the whole program in a single ```python code block.
""",
}

DEFAULT_PART_SELECT = "PART1"
DEFAULT_PART_CODE = "PART1"


def select_prompt(template: str, description: str, menu: str) -> str:
    templates = PART_SELECT_TEMPLATES if template in PART_SELECT_TEMPLATES else SELECT_TEMPLATES
    return templates[template].format(description=description, menu=menu)


def code_prompt(template: str, description: str, context: str, texts: str = "paper") -> str:
    """The code prompt; for an open text (``texts="open"``) in its neutral version (``neutral``)."""
    context = context or "(no components were chosen; use your knowledge of Exudyn)"
    templates = PART_CODE_TEMPLATES if template in PART_CODE_TEMPLATES else CODE_TEMPLATES
    text = templates[template].format(description=description, context=context)
    return neutral(text) if texts == "open" else text


#: What the code templates and the component documentation say that an open text leaves free
#: (issue 36): the creation order and the order of a connector's two items ("the ground first").
#: The paper's texts state that order and its grader compares it; an open text states neither, so
#: its prompt says each rule in a neutral version (the documentation and the rules about files,
#: solver settings and the code block stay). Patterns allow any line break and indentation.
OPEN_TEXT_NEUTRAL: tuple[tuple[str, str], ...] = (
    # MBS1's rule, MBS3's requirement 2 and MBS4's sentence on the creation order
    (r"- Create bodies, nodes, connectors and loads in exactly the order given in the description;\s+"
     r"bodies in the order of their index\.",
     "- Create the bodies, nodes, connectors and loads the described system needs, in any order."),
    (r"2\. Order: create items in the order stated in the description; bodies in the order of their index\.",
     "2. Items: the bodies, nodes, connectors and loads the described system needs, in any order."),
    (r"derive positions and rotations(\s+)from the stated formulas\.",
     r"derive positions and rotations\1from the stated geometry."),
    (r"adding items in the order given,", "adding the items it needs,"),
    # the Ground component's documentation: which of a connector's two items comes first
    (r":\s+list the two items in the order the description names them, the ground first where\s+"
     r"it gives no order\.", "."),
)


def neutral(text: str) -> str:
    """``text`` (a code prompt, component documentation) as an open-text task gets it: every rule
    of ``OPEN_TEXT_NEUTRAL`` in its neutral version."""
    for pattern, replacement in OPEN_TEXT_NEUTRAL:
        text = re.sub(pattern, replacement, text)
    return text


REPAIR_NOTE = """
The following program was written for this task. It contains a modelling error: the system it builds
differs from the description in one respect. Find the error, fix it, and give the whole corrected
program in a single ```python code block.

```python
{draft}
```
"""


def repair_prompt(template: str, description: str, context: str, draft: str, texts: str = "paper") -> str:
    """The repair benchmark's question: the task's code prompt, then the faulty program."""
    return code_prompt(template, description, context, texts) + REPAIR_NOTE.format(draft=draft.rstrip())


def gold_selection(names: tuple[str, ...] | list[str]) -> str:
    lines = "".join(f"<component>{n}</component>\n" for n in names)
    return f"<components>\n{lines}</components>"


def gold_code(program: str) -> str:
    return f"```python\n{program.rstrip()}\n```"
