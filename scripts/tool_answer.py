"""Call one of the agent's tools on a program for a task instance and print the answer exactly as
the model gets it: to read the tools as a model does, or to let a person (or a helper answering
blind) work through the loop by hand.

    python scripts/tool_answer.py cradle_restitution_rise --seed 5 simulate answer.py
    python scripts/tool_answer.py cradle_restitution_rise --seed 5 simulate answer.py \\
        --args '{"sensor_window": [0.2, 0.3], "sensor_samples": 51}'
    python scripts/tool_answer.py single_pendulum --seed 0 --texts open compare a.py --code-b b.py
"""

from __future__ import annotations

import argparse
import asyncio
import json
from pathlib import Path

from meceng.agents.toolbox import Toolbox
from meceng.catalog.catalogs import assembly_catalog, part_catalog, rigid_catalog
from meceng.tasks.registry import UnknownTaskError, default_registry


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("slug")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--texts", default="paper", choices=("paper", "open"))
    parser.add_argument("tool", choices=("simulate", "snapshot", "self_check", "compare"))
    parser.add_argument("code", type=Path, help="the program file")
    parser.add_argument("--code-b", type=Path, help="compare: program B")
    parser.add_argument("--args", default="{}", help="the tool's other arguments, as a JSON object")
    args = parser.parse_args()
    registry = default_registry()
    try:
        instance = registry.instance_of(registry.get(args.slug), args.seed, args.texts)
    except (UnknownTaskError, ValueError) as exc:
        parser.error(str(exc))
    catalog = {"part": part_catalog, "assembly": assembly_catalog}.get(instance.kind, rigid_catalog)()
    arguments = json.loads(args.args)
    if args.tool == "compare":
        if args.code_b is None:
            parser.error("compare needs --code-b")
        arguments.update(code_a=args.code.read_text(), code_b=args.code_b.read_text())
    else:
        arguments["code"] = args.code.read_text()
    answer = asyncio.run(Toolbox(instance, catalog).call(args.tool, arguments))
    print(answer.text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
