"""``stepdeck install-desktop``: StepDeck in the desktop's application menu, for this user.

A wheel cannot put a desktop entry where the desktop looks (pip installs into
site-packages and a venv's ``bin``), so this copies the entry, the icon and the
job files' MIME types under ``$XDG_DATA_HOME`` (``~/.local/share`` when unset),
the per-user place of the XDG specifications.  The entry runs the ``stepdeck``
beside this Python by its full path: a venv or pipx install need not be on the
desktop session's PATH.  Nothing needs root and nothing outside the user's data
folder is written; ``--remove`` takes it all away again.

Exit status: 0 done, 1 a file could not be written or removed, or a wrong command line.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TextIO

from PySide6.QtCore import Qt
from PySide6.QtGui import QImage, QPainter
from PySide6.QtSvg import QSvgRenderer

from app.cli.usage import UsageError, UsageParser
from app.resources import DESKTOP_ENTRY, ICON, MIME_TYPES

OK, FAILED = 0, 1
APP_ID = "stepdeck"
#: Bitmap sizes for menus and docks that do not scale SVG (48 is the one the icon
#: theme specification asks every application to provide).
PNG_SIZES = (32, 48, 64, 128, 256)
#: Refreshing the desktop's caches is a convenience: a hung tool must not hang the install.
REFRESH_TIMEOUT_S = 30.0
#: Characters the desktop entry specification wants quoted (and some escaped) in Exec.
_EXEC_RESERVED = frozenset(" \t\n\"'\\><~|&;$*?#()`")


def data_home(environ: dict[str, str] | os._Environ[str] = os.environ) -> Path:
    """``$XDG_DATA_HOME``, or ``~/.local/share`` when it is unset, empty or relative.

    The base directory specification says a relative path there is invalid and
    must be ignored.
    """
    value = environ.get("XDG_DATA_HOME", "")
    if value and Path(value).is_absolute():
        return Path(value)
    return Path.home() / ".local" / "share"


def stepdeck_command() -> str:
    """The ``stepdeck`` to run: the one installed beside this Python, else the one on PATH."""
    beside = Path(sys.executable).parent / "stepdeck"
    if beside.is_file():
        return str(beside.absolute())
    return shutil.which("stepdeck") or "stepdeck"


def exec_argument(command: str) -> str:
    """``command`` as one argument of a desktop entry's Exec key (quoted when it must be)."""
    command = command.replace("%", "%%")  # a lone % starts a field code (%f)
    if not _EXEC_RESERVED & set(command):
        return command
    escaped = "".join(f"\\{c}" if c in '"`$\\' else c for c in command)
    # The value is also a string of the key file format, whose own escape is the backslash.
    return '"' + escaped.replace("\\", "\\\\") + '"'


def desktop_entry(command: str) -> str:
    """The shipped entry, running ``command`` instead of a bare ``stepdeck``."""
    lines = []
    for line in DESKTOP_ENTRY.read_text(encoding="utf-8").splitlines():
        if line.startswith("Exec="):
            _, _, arguments = line.partition(" ")
            line = f"Exec={exec_argument(command)} {arguments}".rstrip()
        lines.append(line)
    return "\n".join(lines) + "\n"


def icon_png(size: int) -> QImage:
    """The icon drawn at ``size`` pixels (QtSvg needs no display for this)."""
    image = QImage(size, size, QImage.Format.Format_ARGB32_Premultiplied)
    image.fill(Qt.GlobalColor.transparent)
    painter = QPainter(image)
    QSvgRenderer(str(ICON)).render(painter)
    painter.end()
    return image


def installed_files(home: Path) -> dict[str, Path]:
    """Where each installed file goes under the data folder ``home``."""
    icons = home / "icons" / "hicolor"
    files = {
        "entry": home / "applications" / f"{APP_ID}.desktop",
        "mime": home / "mime" / "packages" / f"{APP_ID}.xml",
        "svg": icons / "scalable" / "apps" / f"{APP_ID}.svg",
    }
    for size in PNG_SIZES:
        files[f"png{size}"] = icons / f"{size}x{size}" / "apps" / f"{APP_ID}.png"
    return files


def install(home: Path, command: str) -> list[Path]:
    """Write the entry, the icons and the MIME types under ``home``; the files written."""
    files = installed_files(home)
    for path in files.values():
        path.parent.mkdir(parents=True, exist_ok=True)
    files["entry"].write_text(desktop_entry(command), encoding="utf-8")
    shutil.copyfile(MIME_TYPES, files["mime"])
    shutil.copyfile(ICON, files["svg"])
    for size in PNG_SIZES:
        path = files[f"png{size}"]
        if not icon_png(size).save(str(path)):  # PNG, from the suffix
            raise OSError(f"cannot write {path}")
    return list(files.values())


def remove(home: Path) -> list[Path]:
    """Remove what :func:`install` wrote under ``home``; the files that were there."""
    removed = []
    for path in installed_files(home).values():
        if path.is_file():
            path.unlink()
            removed.append(path)
    return removed


def refresh_caches(home: Path, out: TextIO) -> None:
    """Tell the desktop: its MIME and application caches, where the tools are installed."""
    for tool, folder in (
        ("update-mime-database", home / "mime"),
        ("update-desktop-database", home / "applications"),
    ):
        program = shutil.which(tool)
        if program is None or not folder.is_dir():
            continue
        try:
            subprocess.run(
                [program, str(folder)], check=True, capture_output=True, timeout=REFRESH_TIMEOUT_S
            )
        except (OSError, subprocess.SubprocessError) as exc:
            print(f"stepdeck install-desktop: {tool} failed ({exc}); log in again", file=out)


def build_parser() -> argparse.ArgumentParser:
    parser = UsageParser(
        prog="stepdeck install-desktop",
        description=(
            "Put StepDeck in the desktop's application menu for the current user: the "
            "desktop entry, the icon and the job files' MIME types under $XDG_DATA_HOME "
            "(~/.local/share)."
        ),
    )
    parser.add_argument(
        "--remove", action="store_true", help="remove what an earlier install-desktop wrote"
    )
    return parser


def main(argv: Sequence[str], out: TextIO | None = None, err: TextIO | None = None) -> int:
    out = out or sys.stdout
    err = err or sys.stderr
    try:
        args = build_parser().parse_args(argv)
    except UsageError as exc:
        print(f"stepdeck install-desktop: {exc}", file=err)
        return FAILED
    home = data_home()
    try:
        if args.remove:
            removed = remove(home)
            print(f"removed {len(removed)} files from {home}", file=out)
        else:
            written = install(home, stepdeck_command())
            print(f"installed {written[0]} with its icon and MIME types", file=out)
    except OSError as exc:
        print(f"stepdeck install-desktop: {exc}", file=err)
        return FAILED
    refresh_caches(home, err)
    return OK
