"""Nothing left in English: every text of the window, in Czech and in Slovak, at every moment.

The window of every profile is walked as an operator sees it: each page, the
jobs, telemetry and developer docks, a job loaded and run into its prompt and
to its end.  At each moment every text the window shows is read (captions,
labels, tooltips, window, group, dock and tab titles, table headers, combo
items, menus, the status bar, the plots' titles and axes, and the job's
messages) and a word of English in it fails the test, listed with where it
was seen.  A word is English when the language's own translations never use
it and it is no unit, name or G-code word from the short allow-list below.
"""

from __future__ import annotations

import html
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from functools import cache
from pathlib import Path

import pyqtgraph as pg
import pytest
from PySide6.QtCore import QLocale, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QAbstractButton,
    QApplication,
    QComboBox,
    QDockWidget,
    QGroupBox,
    QLabel,
    QLineEdit,
    QMenu,
    QTabBar,
    QTableView,
    QTreeView,
    QWidget,
)
from pytestqt.qtbot import QtBot

from app import i18n
from app.jobs.run.runner import JobState
from app.profiles import available_profiles, load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

ROOT = Path(__file__).resolve().parents[2]

#: Words that are the same in every language: units, names, wire and G-code words, keys.
ALLOWED = {
    # units
    "mm", "µm", "min", "kHz", "Hz", "ms", "mA", "mV",
    # names
    "StepDeck", "GRBL", "Grbl", "CoreXY", "USB", "BLE", "Bluetooth", "Excellon", "CSV",
    "PNG", "SVG", "XON", "XOFF", "FRAM", "EEPROM", "IMU", "PCB", "VRTACKA", "grbl", "sim",
    "Qt", "PySide", "pyqtgraph", "Python", "TX", "RX", "INJ", "BAD", "TTL", "UART",
    # keys on the keyboard, as printed on it
    "Ctrl", "Shift", "Alt", "Esc", "Tab", "PgUp", "PgDown", "PageUp", "PageDown", "Del",
    # GRBL's own state words, shown as the firmware sends them
    "Idle", "Run", "Hold", "Jog", "Alarm", "Door", "Check", "Home", "Sleep",
    # the languages, each named in itself
    "English",
}  # fmt: skip
#: Text in straight double quotes is quoted as the wire or a file has it ("Grbl 1.1h […]").
QUOTED = re.compile(r'"[^"]*"|\'[^\']*\'')
#: A word: letters only, at least three (shorter ones are axis names, units and G words);
#: a unit's prefix µ does not make "µsteps" any less English.
WORD = re.compile(r"(?<=µ)[^\W\d_]{3,}|[^\W\d_µ][^\W\d_]{2,}")


@cache
def _vocabulary(language: str) -> frozenset[str]:
    """Every word the language's translations use (names they keep, like STOP, count)."""
    path = ROOT / "resources" / "i18n" / f"stepdeck_{language}.ts"
    words: set[str] = set()
    for translation in ET.parse(path).getroot().iter("translation"):
        for text in (translation.text or "", *(f.text or "" for f in translation)):
            words.update(WORD.findall(_plain(text)))
    return frozenset(words)


def _plain(text: str) -> str:
    """The text as read: without markup, mnemonics and entities."""
    text = QUOTED.sub(" ", re.sub(r"<[^>]*>", " ", text))
    return html.unescape(text).replace("&&", "\0").replace("&", "").replace("\0", "&")


def english_words(text: str, language: str, names: set[str]) -> list[str]:
    """The words of ``text`` that are neither the language's nor allowed."""
    known = _vocabulary(language) | ALLOWED | names
    return [
        word
        for word in WORD.findall(_plain(text))
        if word.isascii() and word not in known and word.lower() not in known
    ]


#: A number written with a decimal point ("0.80 mm"), not a version ("1.1h") or a file's name.
POINT_NUMBER = re.compile(r"(?<![\w.])\d+\.\d+(?![\w.])")


def decimal_points(text: str) -> list[str]:
    """Numbers in ``text`` that Czech and Slovak would write with a decimal comma."""
    return POINT_NUMBER.findall(QUOTED.sub(" ", text))


def _action_texts(actions: list[QAction], where: str) -> Iterator[tuple[str, str]]:
    for action in actions:
        if action.isSeparator():
            continue
        yield f"{where} > action", action.text()
        yield f"{where} > action tooltip", action.toolTip()
        menu = action.menu()
        if isinstance(menu, QMenu):
            yield from _action_texts(menu.actions(), f"{where} > {action.text()}")


def _widget_texts(widget: QWidget) -> Iterator[tuple[str, str]]:
    """What ``widget`` itself says to the operator."""
    if isinstance(widget, (QLabel, QAbstractButton)):
        yield "text", widget.text()
    if isinstance(widget, QGroupBox):
        yield "group title", widget.title()
    if isinstance(widget, QDockWidget) or widget.isWindow():
        yield "window title", widget.windowTitle()
    if isinstance(widget, QTabBar):
        for index in range(widget.count()):
            yield "tab", widget.tabText(index)
            yield "tab tooltip", widget.tabToolTip(index)
    if isinstance(widget, QComboBox):
        for index in range(widget.count()):
            yield "combo item", widget.itemText(index)
    if isinstance(widget, QLineEdit):
        yield "placeholder", widget.placeholderText()
    header = widget.horizontalHeader() if isinstance(widget, QTableView) else None
    header = widget.header() if isinstance(widget, QTreeView) else header
    if header is not None and header.model() is not None:
        for section in range(header.count()):
            text = header.model().headerData(section, Qt.Orientation.Horizontal)
            yield "header", str(text or "")
    if isinstance(widget, pg.PlotWidget):
        item = widget.getPlotItem()
        yield "plot title", item.titleLabel.text
        for name in ("left", "bottom", "right"):
            yield f"plot {name} axis", item.getAxis(name).labelText
    if isinstance(widget, pg.GraphicsLayoutWidget):
        for plot in widget.ci.items:
            if isinstance(plot, pg.PlotItem):
                yield "plot title", plot.titleLabel.text
                for name in ("left", "bottom", "right"):
                    yield f"plot {name} axis", plot.getAxis(name).labelText
    yield "tooltip", widget.toolTip()
    yield "status tip", widget.statusTip()
    yield "placeholder", getattr(widget, "placeholderText", lambda: "")() or ""
    yield from _action_texts(widget.actions(), "own")


def _where(widget: QWidget) -> str:
    names = []
    while widget is not None and len(names) < 4:
        names.append(widget.objectName() or type(widget).__name__)
        widget = widget.parentWidget()
    return "/".join(reversed(names))


def window_texts(window: MainWindow) -> Iterator[tuple[str, str]]:
    """Every text ``window`` shows now: its widgets, menus, status bar and job messages."""
    yield from _action_texts(window.menuBar().actions(), "menu")
    yield "status bar", window.statusBar().currentMessage()
    for widget in [window, *window.findChildren(QWidget)]:
        if not widget.isVisibleTo(window) and not isinstance(widget, QDockWidget):
            continue
        where = _where(widget)
        for kind, text in _widget_texts(widget):
            yield f"{where} ({kind})", text
    if any(dock.objectName() == "jobs_dock" for dock in window.docks.built()):
        for line in window.jobs_dock.messages.toPlainText().splitlines():
            yield "job messages", line


#: A drill file with two bits (a bit-change prompt) and three holes.
BOARD = "M48\nMETRIC\nT1C0.8\nT2C1.0\n%\nT1\nX10.0Y10.0\nX40.0Y10.0\nT2\nX40.0Y30.0\nM30\n"
#: A point list that waits for the operator first.
WAIT = "wait: swap the probe\n5, 5\n7.5, 5\n"


def _job(profile: str, folder: Path) -> Path:
    if profile in ("xy-stage", "usb3", "string-art"):
        path = folder / "probe.csv"
        path.write_text(WAIT, encoding="utf-8")
        return path
    path = folder / "board.drl"
    path.write_text(BOARD, encoding="utf-8")
    return path


@pytest.mark.parametrize("language", ["cs", "sk"])
@pytest.mark.parametrize("profile", available_profiles())
def test_no_text_in_the_window_is_left_in_english(
    qtbot: QtBot, i18n_cache: Path, tmp_path: Path, profile: str, language: str
) -> None:
    i18n.install(language, i18n_cache)
    harness = StationHarness(load_profile(profile))
    # What the operator typed or named stays as it is: the job's file and its own words.
    names = set(WORD.findall(f"{WAIT} {tmp_path} probe.csv board.drl {available_profiles()}"))
    found: dict[str, set[str]] = {}

    def read(moment: str) -> None:
        QApplication.processEvents()
        for where, text in window_texts(window):
            words = english_words(text, language, names)
            if words:
                found.setdefault(f"{text!r} {words}", set()).add(f"{moment}: {where}")
            for line in WAIT.splitlines():  # the file's own lines, quoted as they are
                text = text.replace(line, " ")
            points = decimal_points(text)
            if points:
                found.setdefault(f"{text!r} {points}", set()).add(f"{moment}: {where}")

    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        for dock in (window.jobs_dock, window.telemetry_dock, window.developer_pane):
            dock.show()
        if window.macros is not None:  # G-code machines: the macro bar, none kept yet
            window.macros.dock.show()
        read("opened")
        harness.connect()
        harness.run(1.5)
        for index in range(window.stack.count()):
            window.menu_panel.button(index).click()
            read(f"page {index}")
        window.developer_pane.raise_()
        read("developer pane")
        dock = window.jobs_dock
        dock.draw_check.setChecked(profile.endswith("plotter"))  # its holes drawn with the pen
        assert dock.open_path(_job(profile, tmp_path)), dock.messages.toPlainText()
        read("job loaded")
        dock.run_button.click()
        harness.run_until(lambda: dock.runner.state is JobState.WAITING, timeout=60)
        read("prompt")
        dock.continue_button.click()
        harness.run(1.0)
        read("running")
        if dock.runner.state is not JobState.DONE:
            dock.abort_button.click()
        harness.run_until(
            lambda: dock.runner.state in (JobState.ABORTED, JobState.DONE), timeout=60
        )
        read("ended")
        for dialog in (window.show_shortcuts(), window.show_about()):
            for where, text in [("title", dialog.windowTitle())] + [
                (_where(w), t) for w in dialog.findChildren(QWidget) for _, t in _widget_texts(w)
            ]:
                words = english_words(text, language, names)
                if words:
                    found.setdefault(f"{text!r} {words}", set()).add(f"dialog: {where}")
            dialog.close()
    finally:
        harness.close()
    listed = "\n".join(f"{text}  ({sorted(places)[0]})" for text, places in sorted(found.items()))
    assert not found, f"{len(found)} texts still in English ({language}, {profile}):\n{listed}"


@pytest.mark.parametrize(
    ("text", "english"),
    [
        ("Připojit", []),
        ("[mm/rev]", ["rev"]),
        ("Shift (held)", ["held"]),
        ("0,5 µsteps", ["steps"]),
        ("12,000 deg", ["deg"]),
        ("0 position", ["position"]),
        ("<b>X</b> 12,5 mm", []),
        ("Vložit \"Grbl 1.1h ['$' for help]\"", []),
    ],
)
def test_the_check_tells_english_from_czech(text: str, english: list[str]) -> None:
    """The check itself: it finds English words, and passes Czech, units and markup."""
    assert QLocale("cs").decimalPoint() == ","
    assert english_words(text, "cs", set()) == english


@pytest.mark.parametrize(
    ("text", "points"),
    [
        ("pojezd mezi otvory: 64.1 mm", ["64.1"]),
        ("vložte T01, 0,80 mm", []),
        ("Grbl 1.1h", []),
        ("board.drl:7", []),
        ("Vložit '<Hold:0|MPos:0.000,0.000>'", []),
    ],
)
def test_the_check_finds_decimal_points(text: str, points: list[str]) -> None:
    assert decimal_points(text) == points
