"""The operator window, laid out like the stage's original tool.

Info panel on top (always visible), a column of page buttons beside the
dynamic panel, the static panel (speed, Sleep, Stop) on the right and a
status bar.  The window puts together what :mod:`widgets.window` builds —
the pages from the dialect's entry (``pages``), the menus, the docks, the
status bar and the key routing that keeps the two safety rules no single
panel can (``keys``: arrows jog and Esc stops from anywhere in the window;
every jog is released whenever the window may stop seeing key releases) —
and owns the motion lock, the settings it keeps and its own closing.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QMargins, QSettings, Qt, QTimer, Signal
from PySide6.QtGui import QCloseEvent, QShowEvent
from PySide6.QtWidgets import (
    QDialog,
    QFrame,
    QHBoxLayout,
    QLabel,
    QMainWindow,
    QMessageBox,
    QVBoxLayout,
    QWidget,
)

from app.i18n import LANGUAGES
from app.jobs.names import shown
from app.settings import DOCKS_SHOWN, GEOMETRY, PAGE, WINDOW_STATE, StationSettings
from app.station import Station
from widgets.after_first_paint import AfterFirstPaint
from widgets.dialects import window_dialect
from widgets.gamepad_setup import GamepadSetup
from widgets.jog_input import JogInput
from widgets.macros import install_macros
from widgets.page_stack import PageArea, PageStack
from widgets.panels.connection import ConnectionPanel
from widgets.panels.info import InfoPanel
from widgets.panels.menu import MenuPanel
from widgets.panels.static import StaticPanel
from widgets.retranslate import Maker, Texts
from widgets.screen_fit import fitted
from widgets.window.docks import WindowDocks
from widgets.window.keys import KeyRouter
from widgets.window.menus import WindowMenus
from widgets.window.pages import DrillTimingMemory, Pages, build_pages
from widgets.window.status import StatusLine

if TYPE_CHECKING:
    from app.jobs.run.runner import JobRunner
    from widgets.developer.pane import DeveloperPane
    from widgets.jobs.dock import JobsDock
    from widgets.telemetry_dock import TelemetryDock


class MainWindow(QMainWindow):
    """The operator window over one :class:`Station`.

    ``settings`` (optional) keeps the window geometry and the page shown between runs;
    the launcher passes its :class:`StationSettings`, so the warnings about values it could
    not use (collected since the start) are shown here, once.
    """

    #: The operator chose another machine profile; the launcher rebuilds station and window.
    profileRequested = Signal(str)

    def __init__(
        self,
        station: Station,
        settings: QSettings | StationSettings | None = None,
        parent: QWidget | None = None,
        *,
        checkpoint_dir: Path | None = None,
        i18n_cache: Path | None = None,
    ) -> None:
        super().__init__(parent)
        #: Where a language switch compiles its translation (None: the station's cache).
        self._i18n_cache = i18n_cache
        self.station = station
        self.model = station.model
        self._remembers = settings is not None
        self._settings = (
            settings if isinstance(settings, StationSettings) else StationSettings(settings)
        )
        #: This machine's own settings (arrow keys, link, skipped lines), apart from others'.
        self._machine_settings = self._settings.machine(station.profile.name)
        #: The box listing settings the station could not use (None: there were none).
        self.settings_warning: QMessageBox | None = None
        self._close_after_stop = False
        self.texts = Texts(self)
        self.texts.set(
            self.setWindowTitle,
            lambda: self.tr("StepDeck — {0}").format(station.profile.shown_title),
        )
        self.jog = JogInput(station, self)
        self._build_pages()
        self.static_panel = StaticPanel(station, self.jog)
        self._build_layout()
        self.status = StatusLine(
            station,
            self.statusBar(),
            self.texts,
            lambda count: self.tr("rejected frames: %n", "", count),
        )
        self.link_status = self.status.link_status
        self.message_label = self.status.message_label
        self.message_timer = self.status.message_timer
        self.rejected_label = self.status.rejected_label
        self._build_menus_and_docks(checkpoint_dir)
        self.model.lockChanged.connect(self._update_lock)
        self.model.linkStateChanged.connect(self.menus.update_machine_menu)
        self._update_lock()
        self._restore_settings()
        self.keys = KeyRouter(self, self.jog, self.developer_action.trigger)
        self.keys.install()
        self.gamepad = GamepadSetup(
            self,
            station,
            self.jog,
            self._settings,
            self.menus.machine_menu,
            remembers=self._remembers,
        )
        self.texts.also(self._retranslate)

    # --- building ------------------------------------------------------------

    def _build_pages(self) -> None:
        """The info panel, the motion lock's note, and the pages (the dialect's from its entry)."""
        station = self.station
        self.info_panel = InfoPanel(self.model)
        self.lock_label = QLabel()
        self.lock_label.setObjectName("motion_lock")
        self.lock_label.setStyleSheet(
            "background: #fff3cd; color: #7a5200; border: 1px solid #e0c060;"
            " border-radius: 4px; padding: 4px 8px; font-weight: bold;"
        )
        self.stack = PageStack()
        self.stack.setFrameShape(QFrame.Shape.StyledPanel)
        # Scrolls up and down when the screen is short, so no page makes the window taller.
        self.page_area = PageArea(self.stack)
        self.menu_panel = MenuPanel(self.stack)
        self.dialect = window_dialect(station.profile)
        # Held here: a signal keeps only a weak hold on a plain object's method.
        self._drill_timing = DrillTimingMemory(station, self._settings, self._remembers)
        self.pages = build_pages(
            station, self.jog, self.dialect, self._add_page, self._drill_timing
        )
        self.manual_panel = self.pages.manual
        if self.pages.drill is not None:  # S2-42: the teaching constants kept per profile
            remembered = self._machine_settings if self._remembers else None
            self.pages.drill.conversion_box.remember_in(remembered)
        self.manual_panel.set_key_step(self._machine_settings.jog_step)
        self.manual_panel.keyStepChanged.connect(self._remember_key_step)
        self._name_pages(self.pages)
        self.connection_panel = ConnectionPanel(station, self._settings)
        self.connection_panel.profileRequested.connect(self.profileRequested)
        self._add_page(
            lambda: self.tr("&Link"),
            self.connection_panel,
            lambda: self.tr("Connect: emulator, serial port or BLE (Alt+L)"),
        )

    def _name_pages(self, pages: Pages) -> None:
        """The pages as the window's attributes, as scripts and tests have always found them."""
        for name, panel in (
            ("drill_panel", pages.drill),
            ("usb3_panel", pages.usb3),
            ("absolute_panel", pages.absolute),
            ("relative_panel", pages.relative),
            ("gcode_panel", pages.gcode),
            ("dynamics_panel", pages.dynamics),
            ("dynamics_page", pages.dynamics_page),
        ):
            if panel is not None:
                setattr(self, name, panel)

    def _add_page(self, title: Maker, page: QWidget, tooltip: Maker) -> None:
        button = self.menu_panel.add_page(title(), page, tooltip())
        self.texts.set(button.setText, title)
        self.texts.set(button.setToolTip, tooltip)

    def _build_layout(self) -> None:
        middle = QHBoxLayout()
        middle.setSpacing(10)
        middle.addWidget(self.menu_panel)
        middle.addWidget(self.page_area, 1)
        middle.addWidget(self.static_panel)
        central = QWidget()
        layout = QVBoxLayout(central)
        layout.setContentsMargins(10, 10, 10, 6)
        layout.setSpacing(8)
        layout.addWidget(self.info_panel)
        layout.addWidget(self.lock_label)
        layout.addLayout(middle, 1)
        self.setCentralWidget(central)
        # The jobs dock runs the window's full height, beside the plots rather than above
        # them: its preview, with a prompt or the registration row over it, then has room
        # on an 800 px screen, and the plots and the developer pane sit under the pages.
        self.setCorner(Qt.Corner.BottomRightCorner, Qt.DockWidgetArea.RightDockWidgetArea)
        self.setCorner(Qt.Corner.TopRightCorner, Qt.DockWidgetArea.RightDockWidgetArea)

    def _build_menus_and_docks(self, checkpoint_dir: Path | None) -> None:
        """File, Machine, View (the docks' entries, colours, language) and Help."""
        menus = self.menus = WindowMenus(
            self,
            self.station,
            self._settings,
            self.texts,
            remembers=self._remembers,
            open_job=self._ask_open_job,
            open_recent=self.open_recent,
            connect_selected=self.connection_panel.connect_selected,
            stop_all=self.stop_all,
        )
        menus.add_machine_entries(self.pages.home_buttons(self.dialect.home_page))
        menus.add_override_entries(self.pages.gcode.overrides if self.pages.gcode else None)
        docks = self.docks = WindowDocks(
            self,
            self.station,
            self.pages,
            menus.view_menu,
            self.texts,
            checkpoint_dir=checkpoint_dir,
            settings=self._settings if self._remembers else None,
            job_opened=self._remember_job,
        )
        # Stop ends the job (its checkpoint kept).
        self.jog.stopRequested.connect(docks.abort_job)
        self.macros = install_macros(
            self, self.station, self._settings, docks, menus.view_menu, self.texts, checkpoint_dir
        )
        if self.macros is not None:  # and a macro under way
            self.jog.stopRequested.connect(self.macros.stop)
        self.theme = menus.build_theme_menu(docks.apply_colours)
        menus.build_language_menu(self.set_language)
        menus.update_machine_menu()
        # The entries tests and scripts reach on the window itself.
        for name in ("open_action", "quit_action", "connect_action", "disconnect_action"):
            setattr(self, name, getattr(menus, name))
        for name in ("stop_action", "about_action", "view_menu", "recent_menu", "home_actions"):
            setattr(self, name, getattr(menus, name))
        self.language_actions = menus.language_actions
        self.theme_actions = menus.theme_actions
        self.telemetry = docks.telemetry
        self.frame_log = docks.frame_log
        self.jobs_action = docks.jobs_action
        self.telemetry_action = docks.telemetry_action
        self.developer_action = docks.developer_action

    def _retranslate(self) -> None:
        """What is made from state, said again in the language just installed."""
        self._update_lock()
        self.status.show_link_status()
        self.status.show_rejected()
        self.menus.retranslate()

    # --- the docks, built when first wanted ------------------------------------

    @property
    def job_runner(self) -> JobRunner:
        return self.docks.job_runner

    @property
    def jobs_dock(self) -> JobsDock:
        return self.docks.jobs_dock

    @property
    def telemetry_dock(self) -> TelemetryDock:
        return self.docks.telemetry_dock

    @property
    def developer_pane(self) -> DeveloperPane:
        return self.docks.developer_pane

    # --- public --------------------------------------------------------------

    def set_language(self, choice: str) -> str:
        """Speak ``choice`` from now on, and remember it; returns the language installed.

        Installing the translator makes Qt send ``LanguageChange`` through every
        window, and each widget makes its texts again (:class:`Texts`): nothing is
        rebuilt, so the link, a running job and the fields' contents are untouched,
        and nothing is sent to the machine.
        """
        language = self.menus.install_language(choice, self._i18n_cache)
        self.status.show_message(self.tr("Language: {0}").format(LANGUAGES[language]))
        return language

    def set_theme(self, choice: str) -> None:
        """Use and remember the colours chosen ("system", "light" or "dark")."""
        self.menus.set_theme(choice)

    def show_about(self) -> QMessageBox:
        """Name, version and what this is (non-modal; returns the box)."""
        return self.menus.show_about()

    def show_shortcuts(self) -> QDialog:
        """Show (non-modal) the list of keys; returns the dialog."""
        return self.menus.show_shortcuts()

    def open_recent(self, path: Path) -> bool:
        """Open a job from the recent list (the dock says why when it cannot)."""
        self.jobs_dock.show()
        if not path.is_file():
            self.jobs_dock.say(
                self.tr("{0}: not opened — the file is no longer there").format(shown(path.name))
            )
            return False
        return self.jobs_dock.open_path(path, background=True)

    def stop_all(self) -> None:
        """What Esc and the Stop buttons do: forget held input and stop every axis."""
        self.jog.stop_all()

    def _ask_open_job(self) -> None:
        self.jobs_dock.show()
        self.jobs_dock.raise_()
        self.jobs_dock.ask_open()

    def _remember_job(self, path: object) -> None:
        if isinstance(path, Path):
            self._settings.add_recent_job(str(path))
            if self._remembers:
                self._settings.sync()

    # --- model → window ------------------------------------------------------

    def _update_lock(self) -> None:
        """Disable every motion control while the model says motion is refused, and say why."""
        reason = self.model.motion_lock_reason()
        enabled = reason is None
        # A job under way leaves the machine free to move but not to be jogged: the
        # jog buttons go off with the reason beside them, and a jog key says it.
        jog_lock = self.model.jog_lock_reason if enabled else None
        self.jog.set_enabled(enabled and jog_lock is None, reason or jog_lock)
        for panel in self.pages.motion_panels:
            panel.set_motion_enabled(enabled)
        self.manual_panel.set_jog_lock(jog_lock)
        self.menus.update_machine_menu()
        self.lock_label.setText(self.tr("Motion locked: {0}").format(reason))
        self.lock_label.setVisible(not enabled)

    # --- window lifecycle ----------------------------------------------------

    def _restore_settings(self) -> None:
        self.docks_restored = AfterFirstPaint(self, self._restore_docks)
        if not self._remembers:
            self.resize(980, 640)
            return
        geometry = self._settings.read(GEOMETRY)
        if geometry is None or not self.restoreGeometry(geometry):
            self.resize(980, 640)
        else:
            self.fit_on_screen()
        self.menu_panel.set_page(self._settings.read(PAGE))
        self._warn_about_settings()

    def _restore_docks(self) -> None:
        """The docks the last session showed, built after the first paint and placed as left."""
        state = self._settings.read(WINDOW_STATE)
        if state is None:
            return
        active = self.isActiveWindow()
        # The docks the last session showed are built first, so the state places them.
        self.docks.build_shown(self._settings.read(DOCKS_SHOWN))
        self.restoreState(state)
        if self.isVisible():
            self.fit_on_screen()  # the docks came after the window was placed
        if active and not self.isActiveWindow():
            self.activateWindow()  # building a dock took the keyboard from the operator

    def fit_on_screen(self) -> None:
        """Move (and if need be shrink) the window so it is wholly on its screen, frame and all.

        Done when the saved geometry is restored and again once shown, when the window
        manager's frame is known; a maximised or full-screen window is the system's.
        """
        if self.windowState() & (Qt.WindowState.WindowMaximized | Qt.WindowState.WindowFullScreen):
            return
        screen = self.screen()
        if screen is None:
            return
        geometry = self.geometry()
        frame = self.frameGeometry()
        margins = QMargins(
            geometry.left() - frame.left(),
            geometry.top() - frame.top(),
            frame.right() - geometry.right(),
            frame.bottom() - geometry.bottom(),
        )
        target = fitted(geometry, margins, screen.availableGeometry())
        if target != geometry:
            self.setGeometry(target)

    def _warn_about_settings(self) -> None:
        """Settings that could not be used: in the status bar and a box, once per start."""
        warnings = self._settings.take_warnings()
        if not warnings:
            return
        self.status.show_message(
            warnings[0]
            if len(warnings) == 1
            else self.tr(
                "%n settings could not be used; defaults are used instead", "", len(warnings)
            )
        )
        box = QMessageBox(
            QMessageBox.Icon.Warning,
            self.tr("StepDeck — settings"),
            "\n\n".join(warnings),
            parent=self,
        )
        box.setObjectName("settings_warning")
        box.setWindowModality(Qt.WindowModality.NonModal)
        self.settings_warning = box

    def save_settings(self) -> None:
        """Store geometry, window state and the page shown (also done on close)."""
        if not self._remembers:
            return
        self.docks_restored.now()  # closed before its first paint: the layout it was given
        self._settings.write(GEOMETRY, self.saveGeometry())
        self._settings.write(WINDOW_STATE, self.saveState())
        self.docks.save(self._settings)
        self._settings.write(PAGE, self.menu_panel.current)
        self._settings.sync()

    def _close_when_stopped(self) -> None:
        self.station.linkClosed.disconnect(self._close_when_stopped)
        self._close_after_stop = False
        # After the station's signal has returned: closing re-enters the station.
        QTimer.singleShot(0, self.close)

    def showEvent(self, event: QShowEvent) -> None:
        self.keys.install()
        super().showEvent(event)
        if self._remembers and not event.spontaneous():
            # The frame the window manager draws is known only now.
            QTimer.singleShot(0, self, self.fit_on_screen)
        if self.settings_warning is not None and not self.settings_warning.isVisible():
            self.settings_warning.show()  # not exec(): the window stays usable behind it

    def _remember_key_step(self, step: float) -> None:
        self._machine_settings.jog_step = step

    def closeEvent(self, event: QCloseEvent) -> None:
        """Closing the operator window stops the machine and closes the link.

        While a move runs the window stays open until the device confirms the
        stop (at most ``STOP_CONFIRM_S``), without blocking the event loop;
        then it closes by itself.
        """
        self.jog.release_all()
        self.gamepad.shutdown()
        if not self.station.stop_and_close():
            if not self._close_after_stop:
                self._close_after_stop = True
                self.station.linkClosed.connect(self._close_when_stopped)
            self.status.show_message(self.tr("Stopping every axis before closing…"))
            event.ignore()
            return
        self.save_settings()
        self.keys.remove()
        self.theme.release()
        self.menus.close_boxes()
        self.station.shutdown()
        super().closeEvent(event)
