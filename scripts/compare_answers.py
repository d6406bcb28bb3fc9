"""The ``compare`` tool's answers, printed as a model reads them, and what a call costs.

For the rigid double pendulum (seed 0, docs/agent.md's ``simulate`` example): its ground truth against
the same system with the links created in the other order (``tasks/alternatives.py``: the two
agree), and against a copy-paste fault (the second link's inertia made with the first link's
length: they part). Each call is timed (wall seconds, cold interpreters: no warm pool); a parting
call runs both programs twice more with twice the steps (the step-error check), an agreeing one
does not.

    python scripts/compare_answers.py [--slug double_pendulum_rigid_bodies] [--seed 0] [--repeats 3]
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import time

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import rigid_catalog
from meceng.tasks.alternatives import ALTERNATIVES
from meceng.tasks.registry import default_registry

#: (task, the text a copy-paste fault replaces, its replacement)
FAULTS = {"double_pendulum_rigid_bodies": ("sideLengths=[length2, width, thickness]",
                                           "sideLengths=[length1, width, thickness]")}


async def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--slug", default="double_pendulum_rigid_bodies", choices=sorted(FAULTS))
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    instance = default_registry().get(args.slug).instance(args.seed)
    truth = instance.reference_program
    alternative = next(a for a in ALTERNATIVES if a.slug == args.slug)
    old, new = FAULTS[args.slug]
    pairs = {f"the same system built another way ({alternative.name})": alternative.program(instance),
             f"a fault: {old!r} -> {new!r}": truth.replace(old, new)}
    toolbox = Toolbox(instance, rigid_catalog())
    for title, other in pairs.items():
        times, text = [], ""
        for _ in range(args.repeats):
            t0 = time.perf_counter()
            text = (await toolbox.call("compare", {"code_a": truth, "code_b": other})).text
            times.append(time.perf_counter() - t0)
        print(f"### {args.slug} seed {args.seed}: the ground truth (A) against {title} (B)")
        print(f"wall time of the call: median {statistics.median(times):.2f} s over {args.repeats} "
              f"(min {min(times):.2f}, max {max(times):.2f}); answer {len(text)} characters\n")
        print(text + "\n")


if __name__ == "__main__":
    asyncio.run(main())
