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
