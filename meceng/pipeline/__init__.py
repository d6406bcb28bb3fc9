"""The pipeline that wires the rooms: task instances -> LLM steps -> isolated execution -> verdicts
-> records (paper Fig. 2).

Modules, each one concern:

- ``settings``: ``RunSettings``, what defines a run;
- ``evaluation``: the ``Evaluator`` service that runs programs in isolation and grades them;
- ``converged``: the step count behaviour compares at, found once per instance, and the runs there;
- ``kinds``: what a rigid task, a part and an assembly add to the flow (catalog, scorer, record);
- ``flow``: the one task flow for every level, and an assembly as its parts' flows + its own;
- ``records``: the task record and its variants (lost to infrastructure, not started, failed);
- ``rundir``: the run folder (journal, programs, parts, run.json);
- ``run``: the run loop (``run_benchmark``) and what ``--resume`` keeps;
- ``rescore``: grading outside a run (``evaluate_program``, ``rescore``);
- ``preflight``: before the first LLM request, whether this machine can grade the levels;
- ``prompting``: the prompts a model gets for one instance (``meceng tasks prompt``, the prompt lint).
"""

from .evaluation import Evaluator, ReferenceCache
from .flow import FlowContext, run_flow, run_instance
from .kinds import AssemblyKind, Graded, PartKind, RigidKind, TaskKind
from .prompting import RenderedPrompt, instance_prompts
from .rescore import evaluate_program, rescore
from .run import run_benchmark
from .rundir import RunWriter, record_key, versions
from .settings import RunSettings

__all__ = [
    "AssemblyKind", "Evaluator", "FlowContext", "Graded", "PartKind", "ReferenceCache", "RenderedPrompt", "RigidKind",
    "RunSettings", "RunWriter", "TaskKind", "evaluate_program", "instance_prompts", "record_key", "rescore",
    "run_benchmark", "run_flow", "run_instance", "versions",
]
