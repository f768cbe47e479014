"""File names as messages show them: a hostile name cannot forge a line or drive a terminal.

A file may be called ``"a\\nb.nc"`` or carry terminal escapes; printed raw, such
a name would split a ``file:line: reason`` message in two or recolour the
operator's terminal.  Every message that names a file goes through
:func:`shown`.
"""

from __future__ import annotations


def shown(name: str) -> str:
    """``name`` with every unprintable character written as its escape (``\\n``, ``\\x1b``)."""
    if name.isprintable():
        return name
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in name)


def quoted(text: str, limit: int = 60) -> str:
    """``text`` quoted for a message, cut to ``limit`` characters: a hostile line may be
    megabytes long, and a message is read by a person."""
    if len(text) <= limit:
        return repr(text)
    return f"{text[:limit]!r}… ({len(text):,} characters)"


def clipped(text: str, limit: int = 80) -> str:
    """``text`` as shown unquoted in a message (an operation's G-code line), cut to ``limit``."""
    return text if len(text) <= limit else f"{text[:limit]}… ({len(text):,} characters)"
