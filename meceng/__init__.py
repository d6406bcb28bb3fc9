"""MecEng: a benchmark of how well language models build mechanical multibody models in Exudyn."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("meceng")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"
