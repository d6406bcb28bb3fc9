"""Run answers written elsewhere (a person, a model answering blind, another harness) through the
real pipeline as a model's: a folder of SLUG.py programs is served by a fake Ollama server on
127.0.0.1 (the selection answered with the required components, the code request with the file),
and ``meceng run`` grades them into an ordinary run folder for the report and the viewer.

    python scripts/replay_answers.py ANSWERS/ --seed 4242 --levels 4 --out runs/ --name blind-oneshot
"""

from __future__ import annotations

import argparse
import asyncio
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from fake_ollama import FakeOllama, chat_reply, prompted_instance

from meceng.agents.prompts import gold_selection
from meceng.cli.arguments import parse_levels
from meceng.llm.types import LLMSettings
from meceng.pipeline import RunSettings, run_benchmark
from meceng.tasks.registry import default_registry


async def replay(answers: Path, seed: int, levels: tuple[str, ...], out: Path, name: str) -> Path:
    programs = {path.stem: path.read_text() for path in sorted(answers.glob("*.py"))}
    if not programs:
        raise SystemExit(f"no SLUG.py answers in {answers}")
    registry = default_registry()
    registry.check(programs)
    instances = [registry.instance_of(registry.get(slug), seed, "open") for slug in programs]

    async def respond(body: dict) -> tuple[int, dict, dict]:
        prompt = body["messages"][-1]["content"]
        instance = prompted_instance(instances, prompt)
        if "<components>" in prompt:
            return 200, chat_reply(gold_selection(instance.required_components), model=name), {}
        return 200, chat_reply(f"```python\n{programs[instance.slug]}\n```", model=name), {}

    async with FakeOllama(respond) as server:
        llm = LLMSettings(model=name, backend="ollama", hosts=(server.url,), batch_size=2)
        settings = RunSettings(llm=llm, levels=levels, only=tuple(programs), variations=1, seed=seed, out=out,
                               run_name=name, progress=False, texts="open")
        return await run_benchmark(settings)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("answers", type=Path, help="a folder of SLUG.py programs")
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--levels", type=parse_levels, default=("4",))
    parser.add_argument("--out", type=Path, default=Path("runs"))
    parser.add_argument("--name", default="replayed")
    args = parser.parse_args()
    print(asyncio.run(replay(args.answers, args.seed, args.levels, args.out, args.name)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
