"""One program graded: what every task kind's scorer returns."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from meceng.eval.chain import Verdict
from meceng.tools.execution import Execution


@dataclass(frozen=True)
class Graded:
    """One program graded: the verdict, both executions, and facts the kind keeps for its record."""

    verdict: Verdict
    candidate: Execution
    reference: Execution
    facts: dict[str, Any] = field(default_factory=dict)
