"""Job texts in the operator's language, for modules that must not import Qt.

The job-file readers the string-art generator and the command line share
(``reading``, the string-art reader) stay free of Qt: a worker thread and
``stepdeck`` run them with no application.  They call :func:`translate`,
which ``lupdate`` finds like Qt's own; it gives the English source until
:func:`app.i18n.install` hands it Qt's ``QCoreApplication.translate``.
"""

from __future__ import annotations

import string
from collections.abc import Callable


def _source(context: str, text: str) -> str:
    return text


_translator: Callable[[str, str], str] = _source


def translate(context: str, text: str) -> str:
    """``text`` in the language installed (the English source while there is none)."""
    return _translator(context, text)


#: The decimal separator of the language installed ("," in Czech and Slovak).
_point = "."


def use(translator: Callable[[str, str], str], decimal_point: str = ".") -> None:
    """Translate through ``translator`` and write numbers with ``decimal_point`` from now on."""
    global _translator, _point
    _translator = translator
    _point = decimal_point


class _Localized(string.Formatter):
    """``str.format`` whose fractional numbers take the language's decimal separator."""

    def format_field(self, value: object, format_spec: str) -> str:
        text = str(super().format_field(value, format_spec))
        return text.replace(".", _point) if isinstance(value, float) else text


_FORMATTER = _Localized()


def number(value: float, spec: str = "g") -> str:
    """``value`` as ``format(value, spec)`` writes it, with the language's decimal separator."""
    return format(float(value), spec).replace(".", _point)


def localized_format(template: str, /, *args: object, **kwargs: object) -> str:
    """``template.format(...)``, fractional numbers written as the language writes them."""
    return _FORMATTER.format(template, *args, **kwargs)
