"""The report over finished runs: HTML and Markdown pages (`build`) with their plots (`plots`).
Its numbers are pure functions of the records and live in `meceng.eval.tables`."""

from meceng.report.build import build_report

__all__ = ["build_report"]
