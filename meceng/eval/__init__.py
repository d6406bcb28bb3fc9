"""Pure functions from execution results to verdicts, and their aggregation."""

#: Bumped whenever a change of the evaluation can change a verdict; recorded in every task record.
EVALUATOR_VERSION = "2026.11.1"
