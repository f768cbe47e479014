"""File, Machine, View and Help: where a user of other senders looks first.

Machine's entries press the page buttons they stand for, so the menu can do
nothing the page would not (a locked button ignores the click).  Texts keep
the ``MainWindow`` translation context they had when the window made them.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Qt
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QLabel,
    QMainWindow,
    QMenu,
    QMessageBox,
    QPushButton,
    QVBoxLayout,
)

from app import i18n
from app.i18n import LANGUAGES
from app.jobs.names import shown
from app.machine import LinkState
from app.settings import StationSettings
from app.station import Station
from app.version import station_version
from widgets.gamepad_setup import mapping_rows
from widgets.retranslate import Maker, Texts
from widgets.stop_caption import stop_caption, stop_key_text
from widgets.theme import PlotColours, ThemeController

if TYPE_CHECKING:
    from widgets.panels.gcode_overrides import OverrideBox

#: Keys and what they do (translated where shown: QT_TRANSLATE_NOOP only marks them).
SHORTCUTS: tuple[tuple[str, object], ...] = (
    ("← →", QT_TRANSLATE_NOOP("MainWindow", "Jog X while held")),
    ("↑ ↓", QT_TRANSLATE_NOOP("MainWindow", "Jog Y while held (two arrows at once = diagonal)")),
    (
        "PageUp / PageDown",
        QT_TRANSLATE_NOOP("MainWindow", "Jog Z while held, on machines with a Z axis"),
    ),
    (
        str(QT_TRANSLATE_NOOP("MainWindow", "Shift (held)")),
        QT_TRANSLATE_NOOP("MainWindow", "Jog and move at the other speed"),
    ),
    ("Esc", QT_TRANSLATE_NOOP("MainWindow", "Stop everything, from anywhere in the window")),
    (
        "Alt+M / A / R / D / L / X / G / T",
        QT_TRANSLATE_NOOP(
            "MainWindow",
            "Manual / Absolute / Relative / Dynamics / Link / Axes / G-code / Settings page",
        ),
    ),
    (
        "F5 / F6",
        QT_TRANSLATE_NOOP("MainWindow", "Feed override -10 % / +10 %, on GRBL machines"),
    ),
    (
        "Shift+F5 / Shift+F6",
        QT_TRANSLATE_NOOP("MainWindow", "Feed override -1 % / +1 %, on GRBL machines"),
    ),
    ("F7", QT_TRANSLATE_NOOP("MainWindow", "Feed override back to 100 %, on GRBL machines")),
    ("F8", QT_TRANSLATE_NOOP("MainWindow", "Rapid override 100 → 50 → 25 %, on GRBL machines")),
    ("Ctrl+O", QT_TRANSLATE_NOOP("MainWindow", "Open a job (File → Open job…)")),
    (
        "Ctrl+Shift+R",
        QT_TRANSLATE_NOOP("MainWindow", "Run the job from a line you pick (Jobs → Run from…)"),
    ),
    ("Ctrl+Q", QT_TRANSLATE_NOOP("MainWindow", "Quit (stops the machine first)")),
    ("Ctrl+J", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the jobs dock")),
    ("Ctrl+T", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the telemetry plots")),
    ("Shift+V", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the developer pane")),
    ("Ctrl+M", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the macros (G-code machines)")),
    ("Ctrl+1 … Ctrl+9", QT_TRANSLATE_NOOP("MainWindow", "Run macro 1 … 9 (G-code machines)")),
    ("F1", QT_TRANSLATE_NOOP("MainWindow", "This list")),
)


def _tr(source: str, disambiguation: str | None = None, n: int = -1) -> str:
    """For texts made from state (lupdate finds them where they are written, in full)."""
    return QCoreApplication.translate("MainWindow", source, disambiguation, n)


class WindowMenus(QObject):
    """The menu bar's menus, the recent jobs, the colours and languages, the key list and
    the About box (made when first shown, again after a language switch)."""

    def __init__(
        self,
        window: QMainWindow,
        station: Station,
        settings: StationSettings,
        texts: Texts,
        *,
        remembers: bool,
        open_job: Callable[[], None],
        open_recent: Callable[[Path], object],
        connect_selected: Callable[[], object],
        stop_all: Callable[[], None],
    ) -> None:
        super().__init__(window)
        self._window = window
        self._station = station
        self._settings = settings
        self._texts = texts
        self._remembers = remembers
        self._open_recent = open_recent
        self._help: QDialog | None = None
        self._about: QMessageBox | None = None
        self.home_actions: list[tuple[QAction, QPushButton]] = []
        self.language_actions: dict[str, QAction] = {}
        self.theme_actions: dict[str, QAction] = {}
        bar = window.menuBar()
        self._build_file(bar.addMenu(""), open_job)
        self.machine_menu = bar.addMenu("")
        texts.set(
            self.machine_menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&Machine")
        )
        self.connect_action = self._action(
            lambda: QCoreApplication.translate("MainWindow", "&Connect"), connect_selected
        )
        self.disconnect_action = self._action(
            lambda: QCoreApplication.translate("MainWindow", "&Disconnect"), station.stop_and_close
        )
        self.machine_menu.addAction(self.connect_action)
        self.machine_menu.addAction(self.disconnect_action)
        self.machine_menu.addSeparator()
        self._stop_all = stop_all
        self.view_menu = bar.addMenu("")
        texts.set(
            self.view_menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&View")
        )
        self._build_help(bar.addMenu(""))

    def _action(self, text: Maker, slot: Callable[[], object]) -> QAction:
        action = QAction(self._window)
        self._texts.set(action.setText, text)
        action.triggered.connect(lambda _=False: slot())
        return action

    def _build_file(self, menu: QMenu, open_job: Callable[[], None]) -> None:
        t = self._texts
        t.set(menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&File"))
        self.open_action = QAction(self._window)
        t.set(
            self.open_action.setText,
            lambda: QCoreApplication.translate("MainWindow", "&Open job…"),
        )
        self.open_action.setShortcut(QKeySequence.StandardKey.Open)
        self.open_action.triggered.connect(open_job)
        menu.addAction(self.open_action)
        self.recent_menu = menu.addMenu("")
        t.set(
            self.recent_menu.setTitle,
            lambda: QCoreApplication.translate("MainWindow", "&Recent jobs"),
        )
        self.recent_menu.aboutToShow.connect(self.fill_recent_menu)
        self.fill_recent_menu()
        menu.addSeparator()
        self.quit_action = QAction(self._window)
        t.set(self.quit_action.setText, lambda: QCoreApplication.translate("MainWindow", "&Quit"))
        self.quit_action.setShortcut(QKeySequence("Ctrl+Q"))
        self.quit_action.triggered.connect(self._window.close)
        menu.addAction(self.quit_action)

    def add_machine_entries(self, home_buttons: list[QPushButton]) -> None:
        """Home (the buttons of the page that homes this machine) and Stop, after the pages."""
        menu = self.machine_menu
        for button in home_buttons:
            action = QAction(button.text().replace("  ", " "), self._window)
            action.setToolTip(button.toolTip())
            action.triggered.connect(button.click)
            menu.addAction(action)
            self.home_actions.append((action, button))
        menu.addSeparator()
        stops = self._station.profile.capabilities.stop_command
        # Esc is routed by the window (widgets.window.keys), not a shortcut: shown, not bound.
        self.stop_action = QAction(self._window)
        self._texts.set(
            self.stop_action.setText,
            lambda: (
                (
                    QCoreApplication.translate("MainWindow", "&Stop")
                    if stops
                    else QCoreApplication.translate("MainWindow", "&Drop the queue")
                )
                + "\tEsc"
            ),
        )
        self._texts.set(self.stop_action.setToolTip, lambda: stop_caption(self._station.profile)[1])
        self.stop_action.triggered.connect(self._stop_all)
        menu.addAction(self.stop_action)
        menu.setToolTipsVisible(True)

    def add_override_entries(self, box: OverrideBox | None) -> None:
        """Machine → Overrides, with their keys (F5…F8), where the machine has overrides."""
        if box is None or box.isHidden():  # hidden: the firmware has no overrides
            return
        menu = self.machine_menu.addMenu("")
        self._texts.set(
            menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&Overrides")
        )
        for action in box.actions_for(self._window, self._texts):
            menu.addAction(action)
            self._window.addAction(action)

    def _build_help(self, menu: QMenu) -> None:
        t = self._texts
        t.set(menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&Help"))
        self.shortcuts_action = QAction(self._window)
        t.set(
            self.shortcuts_action.setText,
            lambda: QCoreApplication.translate("MainWindow", "&Keys"),
        )
        self.shortcuts_action.setShortcut(QKeySequence(Qt.Key.Key_F1))
        self.shortcuts_action.triggered.connect(self.show_shortcuts)
        menu.addAction(self.shortcuts_action)
        self._window.addAction(self.shortcuts_action)
        self.about_action = QAction(self._window)
        t.set(
            self.about_action.setText,
            lambda: QCoreApplication.translate("MainWindow", "&About StepDeck"),
        )
        self.about_action.triggered.connect(self.show_about)
        menu.addAction(self.about_action)

    def build_theme_menu(self, apply_colours: Callable[[PlotColours], None]) -> ThemeController:
        """View → Colours: as the desktop says (and when it changes), light or dark; kept."""
        self.theme = ThemeController(self._settings.theme, self._window)
        self.theme.coloursChanged.connect(apply_colours)
        apply_colours(self.theme.colours)
        self.view_menu.addSeparator()
        menu = self.view_menu.addMenu("")
        self._texts.set(menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "&Colours"))
        captions: tuple[tuple[str, Maker], ...] = (
            ("system", lambda: QCoreApplication.translate("MainWindow", "As the &system")),
            ("light", lambda: QCoreApplication.translate("MainWindow", "&Light")),
            ("dark", lambda: QCoreApplication.translate("MainWindow", "&Dark")),
        )
        self._choices(menu, captions, self.theme.choice, self.set_theme, self.theme_actions)
        return self.theme

    def build_language_menu(self, set_language: Callable[[str], object]) -> None:
        """View → Language: the system's or a fixed one; kept, and switched at once."""
        menu = self.view_menu.addMenu("")
        self._texts.set(
            menu.setTitle, lambda: QCoreApplication.translate("MainWindow", "L&anguage")
        )
        choices: list[tuple[str, Maker]] = [
            ("system", lambda: QCoreApplication.translate("MainWindow", "As the &system"))
        ]
        choices += [(code, lambda n=name: n) for code, name in LANGUAGES.items()]
        self._choices(menu, choices, self._settings.language, set_language, self.language_actions)

    def _choices(
        self,
        menu: QMenu,
        captions: tuple[tuple[str, Maker], ...] | list[tuple[str, Maker]],
        current: str,
        choose: Callable[[str], object],
        actions: dict[str, QAction],
    ) -> None:
        """One checkable entry per choice, exclusive, ``current`` checked."""
        group = QActionGroup(self._window)
        for choice, caption in captions:
            action = QAction(self._window, checkable=True)
            self._texts.set(action.setText, caption)
            action.setChecked(choice == current)
            action.triggered.connect(lambda _=False, c=choice: choose(c))
            group.addAction(action)
            menu.addAction(action)
            actions[choice] = action

    def install_language(self, choice: str, cache: Path | None) -> str:
        """Speak ``choice`` from now on, and remember it; returns the language installed."""
        self._settings.language = choice
        if self._remembers:
            self._settings.sync()
        self.language_actions[choice].setChecked(True)
        return i18n.install(choice, cache)

    def set_theme(self, choice: str) -> None:
        """Use and remember the colours chosen ("system", "light" or "dark")."""
        self._settings.theme = choice
        if self._remembers:
            self._settings.sync()
        self.theme_actions[choice].setChecked(True)
        self.theme.set_choice(choice)

    def fill_recent_menu(self) -> None:
        """The list as stored now: another StepDeck window may have added to it."""
        self.recent_menu.clear()
        paths = self._settings.recent_jobs()
        for number, text in enumerate(paths, start=1):
            path = Path(text)
            action = self.recent_menu.addAction(f"&{number} {shown(path.name)}")
            action.setToolTip(shown(text))
            action.setData(text)
            action.triggered.connect(lambda _=False, p=path: self._open_recent(p))
        if not paths:
            none = QCoreApplication.translate("MainWindow", "(none yet)")
            self.recent_menu.addAction(none).setEnabled(False)
            return
        self.recent_menu.addSeparator()
        self.recent_menu.addAction(
            QCoreApplication.translate("MainWindow", "&Clear the list"), self._clear_recent
        )
        self.recent_menu.setToolTipsVisible(True)

    def _clear_recent(self) -> None:
        self._settings.set_recent_jobs([])
        if self._remembers:
            self._settings.sync()

    def update_machine_menu(self, *_args: object) -> None:
        linked = self._station.model.link_state is not LinkState.DISCONNECTED
        self.connect_action.setEnabled(not linked)
        self.disconnect_action.setEnabled(linked)
        for action, button in self.home_actions:
            action.setEnabled(button.isEnabled())

    def retranslate(self) -> None:
        """What is made from state, said again in the language just installed."""
        self.fill_recent_menu()
        for action, button in self.home_actions:
            action.setText(button.text().replace("  ", " "))
            action.setToolTip(button.toolTip())
        # The key list and the About box are made when first shown: made again next time.
        self.close_boxes()
        for dialog in (self._help, self._about):
            if dialog is not None:
                dialog.deleteLater()
        self._help = None
        self._about = None

    def close_boxes(self) -> None:
        for dialog in (self._help, self._about):
            if dialog is not None:
                dialog.close()

    def show_about(self) -> QMessageBox:
        """Name, version and what this is (non-modal; returns the box)."""
        if self._about is None:
            what = QCoreApplication.translate(
                "MainWindow",
                "A control station for small stepper machines: XY stages, a PCB drill, "
                "G-code plotters, the usb3 unit and the string-art winder.",
            )
            machine = QCoreApplication.translate("MainWindow", "Machine: {0}").format(
                html.escape(self._station.profile.shown_title)
            )
            self._about = QMessageBox(
                QMessageBox.Icon.Information,
                QCoreApplication.translate("MainWindow", "About StepDeck"),
                f"<b>StepDeck {station_version()}</b><p>{what}</p><p>{machine}</p>",
                parent=self._window,
            )
            self._about.setObjectName("about_box")
            self._about.setWindowModality(Qt.WindowModality.NonModal)
        self._about.show()
        return self._about

    def show_shortcuts(self) -> QDialog:
        """Show (non-modal) the list of keys; returns the dialog."""
        if self._help is None:
            esc = stop_key_text(self._station.profile)
            rows = "".join(
                f"<tr><td style='padding-right:16px'><b>{_tr(keys)}</b></td>"
                f"<td>{esc if keys == 'Esc' else _tr(str(what))}</td></tr>"
                for keys, what in SHORTCUTS
            )
            rows += mapping_rows()  # the gamepad's (Machine → Gamepad…)
            note = QCoreApplication.translate(
                "MainWindow",
                "Arrows do not jog while a text or number field has focus: there they keep "
                "editing. Esc works from anywhere in the window and also closes an open menu; "
                "in a dialog (like this one) Esc closes the dialog only.",
            )
            text = QLabel(f"<table>{rows}</table><p>{note}</p>")
            text.setWordWrap(True)
            buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
            self._help = QDialog(self._window)
            self._help.setWindowTitle(
                QCoreApplication.translate("MainWindow", "StepDeck — keyboard shortcuts")
            )
            buttons.rejected.connect(self._help.close)
            layout = QVBoxLayout(self._help)
            layout.addWidget(text)
            layout.addWidget(buttons)
        self._help.show()
        self._help.activateWindow()
        return self._help
