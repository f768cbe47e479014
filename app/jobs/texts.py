"""Job texts in the operator's language, for modules that must not import Qt.

The job-file readers the string-art generator and the command line share
(``reading``, the string-art reader) stay free of Qt: a worker thread and
``stepdeck`` run them with no application.  They call :func:`translate`,
which ``lupdate`` finds like Qt's own; it gives the English source until
:func:`app.i18n.install` hands it Qt's ``QCoreApplication.translate``.
"""

from __future__ import annotations

from collections.abc import Callable


def _source(context: str, text: str) -> str:
    return text


_translator: Callable[[str, str], str] = _source


def translate(context: str, text: str) -> str:
    """``text`` in the language installed (the English source while there is none)."""
    return _translator(context, text)


def use(translator: Callable[[str, str], str]) -> None:
    """Translate through ``translator`` from now on (the window's language)."""
    global _translator
    _translator = translator
