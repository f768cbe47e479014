"""The macros of one machine profile, kept in the station's settings file.

Each macro is two values under ``machines/<profile>/macros/<n>/`` (its name and
its G-code) plus a count, read through :class:`~app.settings.StationSettings`
like every other setting: a value edited by hand, from an older version or
half overwritten yields no macro and a warning naming the key, never a crash
and never a snippet that was not what the operator saved.  A macro that reads
back but is not valid (a name twice, a line that is not printable text) is
dropped for the same reason.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.settings import BadValue, Spec, StationSettings, machine_spec

#: A bar of buttons, not a program library: more than this is a job file.
MAX_MACROS = 32
MAX_NAME_CHARS = 40
#: A snippet, not a job: a few lines a person reads before pressing its button.
MAX_LINES = 200
MAX_CODE_CHARS = 8000

_log = logging.getLogger(__name__)


class MacroError(ValueError):
    """A macro (or a file of them) the station will not keep, with the reason."""


@dataclass(frozen=True)
class Macro:
    """A named G-code snippet; made only through :func:`checked_macro` once it is valid."""

    name: str
    code: str


def name_problem(name: object) -> str | None:
    """Why ``name`` cannot name a macro (None: it can)."""
    if not isinstance(name, str) or not name.strip():
        return QCoreApplication.translate("Macros", "a macro needs a name")
    if name != name.strip():
        return QCoreApplication.translate("Macros", "the name starts or ends with a space")
    if len(name) > MAX_NAME_CHARS:
        return QCoreApplication.translate(
            "Macros", "the name is longer than {0} characters"
        ).format(MAX_NAME_CHARS)
    if not name.isprintable() or '"' in name:
        return QCoreApplication.translate(
            "Macros", "the name may hold printable characters only, and no quote"
        )
    return None


def code_problem(code: object) -> str | None:
    """Why ``code`` cannot be a macro's text (None: it can; the parser judges the G-code)."""
    if not isinstance(code, str):
        return QCoreApplication.translate("Macros", "the G-code is not text")
    if len(code) > MAX_CODE_CHARS:
        return QCoreApplication.translate(
            "Macros", "the G-code is longer than {0} characters"
        ).format(MAX_CODE_CHARS)
    lines = code.split("\n")
    if len(lines) > MAX_LINES:
        return QCoreApplication.translate("Macros", "the G-code has more than {0} lines").format(
            MAX_LINES
        )
    for number, line in enumerate(lines, start=1):
        if not line.replace("\t", " ").isprintable():
            return QCoreApplication.translate(
                "Macros", "line {0} holds a character that is not printable text"
            ).format(number)
    return None


def checked_macro(name: object, code: object) -> Macro:
    """A macro from any values (a settings file, a TOML file, a dialog); raises MacroError."""
    problem = name_problem(name) or code_problem(code)
    if problem is not None:
        raise MacroError(problem)
    assert isinstance(name, str) and isinstance(code, str)
    return Macro(name, code.replace("\r\n", "\n").replace("\r", "\n"))


def checked_list(macros: Sequence[Macro]) -> list[Macro]:
    """``macros`` as a profile may keep them: each valid, names unique, not too many."""
    if len(macros) > MAX_MACROS:
        raise MacroError(
            QCoreApplication.translate("Macros", "more than {0} macros").format(MAX_MACROS)
        )
    seen: set[str] = set()
    for macro in macros:
        checked_macro(macro.name, macro.code)
        if macro.name.casefold() in seen:
            raise MacroError(
                QCoreApplication.translate("Macros", "two macros are named {0}").format(
                    repr(macro.name)
                )
            )
        seen.add(macro.name.casefold())
    return list(macros)


def _converter(problem: Callable[[object], str | None]) -> Callable[[object], str]:
    def convert(value: object) -> str:
        why = problem(value)
        if why is not None:
            raise BadValue(why)
        assert isinstance(value, str)
        return value

    return convert


def _count(value: object) -> int:
    if isinstance(value, bool):
        raise BadValue("a truth value")
    if isinstance(value, str) and value.strip().isascii() and value.strip().isdigit():
        value = int(value.strip()) if len(value.strip()) <= 3 else -1
    if not isinstance(value, int) or not 0 <= value <= MAX_MACROS:
        raise BadValue("not a count of macros")
    return value


COUNT = Spec("macros/count", 0, f"an integer within 0…{MAX_MACROS}", _count)


def name_spec(index: int) -> Spec[str]:
    return Spec(f"macros/{index}/name", "", "a macro name", _converter(name_problem))


def code_spec(index: int) -> Spec[str | None]:
    """None where the code is missing or spoilt: the macro is left out, not run emptied."""
    return Spec(f"macros/{index}/code", None, "a macro's G-code", _converter(code_problem))


class MacroStore:
    """One profile's macros in a :class:`StationSettings` (its file, or memory in tests)."""

    def __init__(self, settings: StationSettings, profile: str) -> None:
        self.settings = settings
        self.profile = profile

    def load(self) -> list[Macro]:
        """The macros kept, in their order; those that do not read back whole are left out."""
        read = self.settings.read
        count = read(machine_spec(COUNT, self.profile))
        macros: list[Macro] = []
        seen: set[str] = set()
        for index in range(count):
            name = read(machine_spec(name_spec(index), self.profile))
            code = read(machine_spec(code_spec(index), self.profile))
            if not name or code is None or name.casefold() in seen:
                _log.warning("macros: entry %d of %s left out", index, self.profile)
                continue
            seen.add(name.casefold())
            macros.append(Macro(name, code))
        return macros

    def save(self, macros: Sequence[Macro]) -> None:
        """Keep ``macros`` (checked: an invalid list is the caller's bug, MacroError)."""
        kept = checked_list(macros)
        store = self.settings.store
        for index in range(MAX_MACROS):
            for spec in (name_spec(index), code_spec(index)):
                store.remove(machine_spec(spec, self.profile).key)
        for index, macro in enumerate(kept):
            self.settings.write(machine_spec(name_spec(index), self.profile), macro.name)
            self.settings.write(machine_spec(code_spec(index), self.profile), macro.code)
        self.settings.write(machine_spec(COUNT, self.profile), len(kept))
        self.settings.sync()


def find(macros: Sequence[Macro], name: str) -> Macro | None:
    """The macro called ``name`` (names are unique whatever their case)."""
    return next((m for m in macros if m.name.casefold() == name.casefold()), None)
