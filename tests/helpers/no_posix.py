"""Imports as on Windows: ``termios``, ``fcntl``, ``tty`` and ``pty`` cannot be imported.

For a subprocess that checks what StepDeck imports where those do not exist
(``python -c "from tests.helpers import no_posix; no_posix.block(...)"``).  A
meta path finder is not enough: once a third-party package has imported
``termios`` for its own POSIX backend (pyserial does on Linux, and imports its
Windows one on Windows), a later ``import termios`` is served from
``sys.modules`` without asking any finder.  So ``__import__`` itself is wrapped,
and it looks at who imports.
"""

from __future__ import annotations

import builtins
import sys
from collections.abc import Mapping, Sequence
from types import ModuleType
from typing import Any

POSIX_ONLY = frozenset({"termios", "fcntl", "tty", "pty"})
FIRST_PARTY = ("app", "widgets", "protocol", "stepdeck", "tests")


def block(importers: Sequence[str] | None = FIRST_PARTY) -> None:
    """Refuse the POSIX-only modules to ``importers`` (top-level package names; None: all)."""
    original = builtins.__import__
    if importers is None:
        for name in POSIX_ONLY:
            sys.modules.pop(name, None)

    def guarded(
        name: str,
        globals: Mapping[str, Any] | None = None,
        locals: Mapping[str, Any] | None = None,
        fromlist: Sequence[str] = (),
        level: int = 0,
    ) -> ModuleType:
        if level == 0 and name.partition(".")[0] in POSIX_ONLY:
            importer = str((globals or {}).get("__name__", ""))
            if importers is None or importer.partition(".")[0] in importers:
                raise ImportError(f"No module named {name!r} (blocked as on Windows)", name=name)
        return original(name, globals, locals, fromlist, level)

    builtins.__import__ = guarded
