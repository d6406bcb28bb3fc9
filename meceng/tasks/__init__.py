"""The task library: one module per task model (see :mod:`meceng.tasks.base`)."""

from meceng.tasks.base import Param, SimSettings, TaskInstance, TaskModel, slugify
from meceng.tasks.registry import TaskRegistry, default_registry

__all__ = ["Param", "SimSettings", "TaskInstance", "TaskModel", "TaskRegistry", "default_registry", "slugify"]
