"""setuptools' build backend, asking for PySide6 only when a wheel is built.

A wheel carries the compiled translations, and compiling them needs the
``lrelease`` PySide6 ships (setup.py); an editable install and an sdist do not,
and a development install should not unpack several hundred megabytes of Qt
into a throwaway build environment for nothing.  This is setuptools' documented
way to add build requirements dynamically (an in-tree backend wrapping it).
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from setuptools import build_meta
from setuptools.build_meta import *  # noqa: F403  (every hook, unchanged but the one below)

PYPROJECT = Path(__file__).resolve().parent / "pyproject.toml"


def lrelease_requirement() -> str:
    """PySide6 as the station depends on it: its lrelease reads the .ts the app is tested with."""
    project = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["project"]
    for requirement in project["dependencies"]:
        if requirement.lower().startswith("pyside6-essentials"):
            return str(requirement)
    return "PySide6-Essentials"


def get_requires_for_build_wheel(config_settings: dict[str, Any] | None = None) -> list[str]:
    return [*build_meta.get_requires_for_build_wheel(config_settings), lrelease_requirement()]
