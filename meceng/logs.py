"""Logging setup: structlog, JSON lines into a file, readable key=value lines on a terminal."""

from __future__ import annotations

import logging
import sys
from pathlib import Path
from typing import Any

import structlog


def get_logger(name: str) -> structlog.stdlib.BoundLogger:
    """A structlog logger that writes through stdlib logging (logger ``name``).

    Library code never prints: without :func:`configure_logging` (or a run's log file) events
    below WARNING go nowhere, and no global structlog configuration is needed.
    """
    return structlog.wrap_logger(
        logging.getLogger(name),
        wrapper_class=structlog.stdlib.BoundLogger,
        processors=[structlog.contextvars.merge_contextvars, structlog.processors.add_log_level,
                    structlog.processors.TimeStamper(fmt="iso", utc=True),
                    structlog.stdlib.ProcessorFormatter.wrap_for_formatter],
    )


def configure_logging(log_file: Path | None = None, level: str = "INFO", console: bool = True) -> None:
    """Route structlog through stdlib logging: JSON to ``log_file``, console renderer to stderr."""
    timestamper = structlog.processors.TimeStamper(fmt="iso", utc=True)
    shared: list[Any] = [structlog.contextvars.merge_contextvars, structlog.processors.add_log_level,
                         timestamper]
    root = logging.getLogger("meceng")
    root.handlers.clear()
    root.setLevel(level)
    root.propagate = False
    if console:
        handler = logging.StreamHandler(sys.stderr)
        renderer = structlog.dev.ConsoleRenderer(colors=sys.stderr.isatty())
        handler.setFormatter(structlog.stdlib.ProcessorFormatter(processor=renderer, foreign_pre_chain=shared))
        handler.setLevel("WARNING")  # the progress bar owns the terminal; info goes to the run's log.jsonl
        root.addHandler(handler)
    if log_file is not None:
        log_file.parent.mkdir(parents=True, exist_ok=True)
        file_handler = logging.FileHandler(log_file)
        file_handler.setFormatter(structlog.stdlib.ProcessorFormatter(
            processor=structlog.processors.JSONRenderer(), foreign_pre_chain=shared))
        root.addHandler(file_handler)
