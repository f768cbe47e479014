"""Numbers in the operator's language for the machines' messages (a decimal comma in cs/sk).

:mod:`app.jobs.texts` does this for the job texts made without Qt; the
sessions and the motion gate sit beside :mod:`app.jobs` (which imports them),
so they take the separator from the default ``QLocale`` that
:func:`app.i18n.install` sets.
"""

from __future__ import annotations

from PySide6.QtCore import QLocale


def local_number(value: float, spec: str = "g") -> str:
    """``value`` as ``format(value, spec)`` writes it, with the language's decimal separator."""
    return format(float(value), spec).replace(".", QLocale().decimalPoint())
