"""Macros exported to a TOML file and imported from one (another station, a colleague, a backup).

Written as the parameter snapshots are (:mod:`app.scripting.parameters`): by
hand, each string quoted as JSON quotes it, which TOML reads the same, so no
TOML writer is needed; read with :mod:`tomllib`.  A file is hostile until
checked: its size is capped, and every macro in it passes the same checks as
one typed in the editor (:func:`~app.macros.store.checked_list`) before any
is taken, so a bad file changes nothing.

    format = 1
    profile = "grbl-plotter"

    [[macro]]
    name = "Park"
    code = "G90\\nG0 X0 Y0"
"""

from __future__ import annotations

import json
import tomllib
from collections.abc import Sequence
from pathlib import Path

from PySide6.QtCore import QCoreApplication

from app.jobs.names import shown
from app.macros.store import MAX_MACROS, Macro, MacroError, checked_list, checked_macro

FORMAT = 1
#: 32 macros of 8000 characters, escaped, is well under this; more is not a macro file.
MAX_FILE_BYTES = 512 * 1024


def toml_string(text: str) -> str:
    """``text`` as a TOML basic string (JSON's escapes are TOML's, non-ASCII kept as is)."""
    return json.dumps(text, ensure_ascii=False)


def macros_toml(macros: Sequence[Macro], profile: str) -> str:
    """The file's text for ``macros`` of ``profile``."""
    lines = [
        "# StepDeck macros: the window's Macros → Export…; Import… reads it back",
        f"format = {FORMAT}",
        f"profile = {toml_string(profile)}",
    ]
    for macro in checked_list(macros):
        lines += ["", "[[macro]]", f"name = {toml_string(macro.name)}"]
        lines.append(f"code = {toml_string(macro.code)}")
    return "\n".join(lines) + "\n"


def export_macros(path: Path, macros: Sequence[Macro], profile: str) -> Path:
    path.write_text(macros_toml(macros, profile), encoding="utf-8")
    return path


def parse_macros(text: str, file: str) -> tuple[list[Macro], str]:
    """The macros of a file's ``text`` and the profile it names; MacroError says why not."""
    where = shown(file)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise MacroError(
            QCoreApplication.translate("Macros", "{0}: not TOML ({1})").format(where, exc)
        ) from None
    if data.get("format") != FORMAT:
        raise MacroError(
            QCoreApplication.translate(
                "Macros", "{0}: not a StepDeck macro file (format {1})"
            ).format(where, FORMAT)
        )
    entries = data.get("macro", [])
    if not isinstance(entries, list) or len(entries) > MAX_MACROS:
        raise MacroError(
            QCoreApplication.translate(
                "Macros", "{0}: [[macro]] must be a list of at most {1} tables"
            ).format(where, MAX_MACROS)
        )
    macros: list[Macro] = []
    for number, entry in enumerate(entries, start=1):
        if not isinstance(entry, dict):
            raise MacroError(
                QCoreApplication.translate("Macros", "{0}: macro {1} is not a table").format(
                    where, number
                )
            )
        try:
            macros.append(checked_macro(entry.get("name"), entry.get("code", "")))
        except MacroError as exc:
            text = QCoreApplication.translate("Macros", "{0}: macro {1}: {2}")
            raise MacroError(text.format(where, number, exc)) from None
    try:
        checked_list(macros)
    except MacroError as exc:
        raise MacroError(f"{where}: {exc}") from None
    profile = data.get("profile", "")
    return macros, profile if isinstance(profile, str) else ""


def import_macros(path: Path) -> tuple[list[Macro], str]:
    """Read a macro file (regular, small, UTF-8); MacroError with the file and the reason."""
    where = shown(path.name)
    try:
        if not path.is_file():
            raise MacroError(QCoreApplication.translate("Macros", "{0}: not a file").format(where))
        if path.stat().st_size > MAX_FILE_BYTES:
            raise MacroError(
                QCoreApplication.translate("Macros", "{0}: too large for a macro file").format(
                    where
                )
            )
        text = path.read_bytes().decode("utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise MacroError(
            QCoreApplication.translate("Macros", "{0}: not readable ({1})").format(where, exc)
        ) from None
    return parse_macros(text, path.name)


def merged(kept: Sequence[Macro], imported: Sequence[Macro]) -> list[Macro]:
    """``kept`` with ``imported`` added: one of the same name is replaced where it stands."""
    result = list(kept)
    for macro in imported:
        same = next(
            (i for i, m in enumerate(result) if m.name.casefold() == macro.name.casefold()), None
        )
        if same is None:
            result.append(macro)
        else:
            result[same] = macro
    return checked_list(result)
