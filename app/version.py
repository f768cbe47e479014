"""The station's version, for Help → About and bug reports.

Read from the installed package's metadata, so it is the one ``pyproject.toml``
declares and never a second copy that drifts from it.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version


def station_version() -> str:
    """The installed version, or "unknown" when run from a tree that was never installed."""
    try:
        return version("stepdeck")
    except PackageNotFoundError:
        return "unknown"
