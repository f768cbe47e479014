"""GRBL's firmware version, as the board says it: its banner and its ``$I`` answer.

A settings snapshot records it, so a restore onto a board that runs another
version can say so: a ``$N`` may mean something else there (GRBL 1.1 moved
and added settings against 0.9).  The banner (``Grbl 1.1h ['$' for help]``,
report.c ``report_init_message``) names the version; ``$I``'s
``[VER:1.1h.20190825:…]`` (``report_build_info``) adds the build date, so
it is kept over the banner's when both name the same version.
"""

from __future__ import annotations

import re

#: ``[VER:<version>.<build>:<build info>]``: the version and build, up to the colon.
_VER = re.compile(r"\[VER:([^:\]\s]+)")
#: ``Grbl <version> ['$' for help]`` (and forks that start the same way).
_BANNER = re.compile(r"Grbl\s+(\S+)", re.IGNORECASE)


def version_in(text: str) -> str | None:
    """The version a reply line names (``"1.1h"``, ``"1.1h.20190825"``), or None."""
    text = text.strip()
    found = _VER.match(text)
    if found is None and "'$' for help]" in text:
        found = _BANNER.match(text)
    return found[1] if found is not None else None


def same_version(a: str, b: str) -> bool:
    """Whether two versions are one: equal, or one is the other with its build date."""
    return a == b or a.startswith(b + ".") or b.startswith(a + ".")


def kept(known: str | None, heard: str) -> str:
    """What to keep when ``heard`` comes after ``known``: the build date is not dropped
    by a banner that names the same version (a reset), any other version replaces it."""
    if known is not None and known.startswith(heard + "."):
        return known
    return heard
