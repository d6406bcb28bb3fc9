"""Sweeps: a study's grid of models, temperatures and prompt variants, checked from its TOML spec
(`spec`, `keys`), probed for reachable servers (`hosts`), split into shards for a cluster (`shard`)
and run with one shared grading pool per machine (`farm`)."""
