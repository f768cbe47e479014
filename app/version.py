"""The station's version, for Help → About and bug reports.

Read from the installed package's metadata, so it is the one ``pyproject.toml``
declares and never a second copy that drifts from it.
"""

from __future__ import annotations


def station_version() -> str:
    """The installed version, or "unknown" when run from a tree that was never installed.

    ``importlib.metadata`` is imported here, when asked: it costs the window's
    start about 50 ms, and only the About box and bug reports need it.
    """
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("stepdeck")
    except PackageNotFoundError:
        return "unknown"
