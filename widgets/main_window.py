"""The operator window, laid out like the stage's original tool.

Info panel on top (always visible), a column of page buttons beside the
dynamic panel, the static panel (speed, Sleep, Stop) on the right and a
status bar.  Besides layout, the window owns the two safety rules that no
single panel can enforce:

* keys are routed application-wide, so arrows jog and Esc stops whatever
  widget of the window has focus — except that arrows keep editing inside
  text fields, Esc also closes an open menu or list, and a dialog (a file
  dialog, the list of keys…) keeps its keys: there Esc closes the dialog and
  never runs the stop;
* whenever the window may stop seeing key releases (deactivated, focus gone,
  application inactive) every jog is released, so a jog can never run away
  because its key-up went to another window.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import (
    QT_TRANSLATE_NOOP,
    QCoreApplication,
    QEvent,
    QMargins,
    QObject,
    QSettings,
    QStandardPaths,
    Qt,
    QTimer,
    Signal,
)
from PySide6.QtGui import (
    QAction,
    QActionGroup,
    QCloseEvent,
    QFocusEvent,
    QKeyEvent,
    QKeySequence,
    QShowEvent,
)
from PySide6.QtWidgets import (
    QAbstractSpinBox,
    QApplication,
    QDialog,
    QDialogButtonBox,
    QFrame,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QMainWindow,
    QMessageBox,
    QPlainTextEdit,
    QPushButton,
    QScrollArea,
    QTextEdit,
    QVBoxLayout,
    QWidget,
)

from app import i18n
from app.developer.frame_log import FrameLog
from app.i18n import LANGUAGES
from app.jobs.names import shown
from app.machine import LinkState
from app.settings import DOCKS_SHOWN, GEOMETRY, PAGE, WINDOW_STATE, StationSettings
from app.station import Station
from app.telemetry import TelemetryRecorder
from app.version import station_version
from protocol.drill.timing import DrillTiming
from widgets.after_first_paint import AfterFirstPaint
from widgets.jog_input import JogInput
from widgets.link_text import link_detail_text, link_state_text
from widgets.number_field import NumberField
from widgets.page_stack import PageArea, PageStack
from widgets.panels.absolute import AbsolutePanel
from widgets.panels.connection import ConnectionPanel
from widgets.panels.drill import DrillPanel
from widgets.panels.dynamics import DynamicsPanel
from widgets.panels.gcode import GcodePanel
from widgets.panels.info import InfoPanel
from widgets.panels.manual import ManualPanel
from widgets.panels.menu import MenuPanel
from widgets.panels.relative import RelativePanel
from widgets.panels.static import StaticPanel
from widgets.panels.usb3 import Usb3Panel
from widgets.retranslate import Maker, Texts
from widgets.screen_fit import fitted
from widgets.stop_caption import stop_caption, stop_key_text
from widgets.theme import PlotColours, ThemeController

if TYPE_CHECKING:
    from PySide6.QtWidgets import QDockWidget

    from app.jobs.run.runner import JobRunner
    from widgets.developer.pane import DeveloperPane
    from widgets.jobs.dock import JobsDock
    from widgets.telemetry_dock import TelemetryDock

#: How long a status-bar message stays (ms): long enough to read twice.
MESSAGE_SHOWN_MS = 15_000

#: Widgets in which arrow keys move a text cursor or step a value, so they must not jog.
TEXT_EDITING = (QLineEdit, QAbstractSpinBox, QTextEdit, QPlainTextEdit)

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
        "Alt+M / A / R / D / L / X / G",
        QT_TRANSLATE_NOOP(
            "MainWindow", "Manual / Absolute / Relative / Dynamics / Link / Axes / G-code page"
        ),
    ),
    ("Ctrl+O", QT_TRANSLATE_NOOP("MainWindow", "Open a job (File → Open job…)")),
    ("Ctrl+Q", QT_TRANSLATE_NOOP("MainWindow", "Quit (stops the machine first)")),
    ("Ctrl+J", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the jobs dock")),
    ("Ctrl+T", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the telemetry plots")),
    ("Shift+V", QT_TRANSLATE_NOOP("MainWindow", "Show or hide the developer pane")),
    ("F1", QT_TRANSLATE_NOOP("MainWindow", "This list")),
)


def _is_text_editing(widget: QWidget | None) -> bool:
    """Whether ``widget`` or one of its ancestors edits text (a spin box's line edit…)."""
    while widget is not None:
        if isinstance(widget, TEXT_EDITING):
            return True
        widget = widget.parentWidget()
    return False


def _is_free_text(widget: QWidget | None) -> bool:
    """A field where any character is input (not a number field, whose keys we may take)."""
    if isinstance(widget, (QTextEdit, QPlainTextEdit)):
        return True
    if not isinstance(widget, QLineEdit) or isinstance(widget, NumberField):
        return False
    parent = widget.parentWidget()
    return not isinstance(parent, QAbstractSpinBox)


def _in_dialog(widget: QObject) -> bool:
    """Whether ``widget`` is in a dialog, or in a popup (a combo's list…) opened from one.

    A dialog owns its keys: Esc cancels it and arrows move in it.  Neither may reach
    the machine — Esc in a file dialog's type list once ran the stop, and arrows in
    its file list would have jogged.
    """
    current = widget if isinstance(widget, QWidget) else None
    while current is not None:
        if isinstance(current, QDialog):
            return True
        current = current.parentWidget()
    return False


def _in_popup(widget: QWidget) -> bool:
    """Whether ``widget`` is in the popup (menu, combo list) that has the keyboard now."""
    popup = QApplication.activePopupWidget()
    return popup is not None and (widget is popup or popup.isAncestorOf(widget))


class MainWindow(QMainWindow):
    """The operator window over one :class:`Station`.

    ``settings`` (optional) keeps the window geometry and the page shown between runs;
    the launcher passes its :class:`StationSettings`, so the warnings about values it could
    not use (collected since the start) are shown here, once.
    """

    #: The operator chose another machine profile; the launcher rebuilds station and window.
    profileRequested = Signal(str)

    #: The key list and the About box, made when first shown (again after a language switch).
    _help: QDialog | None
    _about: QMessageBox | None

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
        self._filtering = False
        self._close_after_stop = False
        self.texts = Texts(self)
        self.texts.set(
            self.setWindowTitle,
            lambda: self.tr("StepDeck — {0}").format(station.profile.shown_title),
        )

        self.jog = JogInput(station, self)
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
        self.manual_panel = ManualPanel(station, self.jog)
        self.manual_panel.set_key_step(self._machine_settings.jog_step)
        self.manual_panel.keyStepChanged.connect(self._remember_key_step)
        self._add_page(
            lambda: self.tr("&Manual"),
            self.manual_panel,
            lambda: self.tr("Hold-to-jog buttons, Home (Alt+M)"),
        )
        #: Every page with motion controls, for the motion lock.
        self.motion_panels: list[
            ManualPanel | AbsolutePanel | RelativePanel | Usb3Panel | DrillPanel | GcodePanel
        ] = [self.manual_panel]
        if station.profile.dialect == "drill":
            # The plotter takes absolute microsteps only: its own page, no Absolute/Relative.
            self.drill_panel = DrillPanel(station)
            self._restore_drill_timing()
            self.drill_panel.timing_box.applied.connect(self._remember_drill_timing)
            self._add_page(
                lambda: self.tr("D&rill"),
                self.drill_panel,
                lambda: self.tr("Command buttons, X/Y, terminal (Alt+R)"),
            )
            self.motion_panels.append(self.drill_panel)
        elif station.profile.dialect == "usb3":
            self.usb3_panel = Usb3Panel(station)
            self._add_page(
                lambda: self.tr("A&xes"),
                self.usb3_panel,
                lambda: self.tr("Move by mm, step size, thread (Alt+X)"),
            )
            self.motion_panels.append(self.usb3_panel)
        else:
            self.absolute_panel = AbsolutePanel(station)
            self.relative_panel = RelativePanel(station)
            self._add_page(
                lambda: self.tr("&Absolute"),
                self.absolute_panel,
                lambda: self.tr("Move to a target (Alt+A)"),
            )
            self._add_page(
                lambda: self.tr("&Relative"),
                self.relative_panel,
                lambda: self.tr("Move by an increment (Alt+R)"),
            )
            self.motion_panels += [self.absolute_panel, self.relative_panel]
        if station.profile.dialect == "gcode":
            self.gcode_panel = GcodePanel(station)
            self._add_page(
                lambda: self.tr("&G-code"),
                self.gcode_panel,
                lambda: self.tr("Console, pen, hold/resume/reset (Alt+G)"),
            )
            self.motion_panels.append(self.gcode_panel)
        if station.profile.capabilities.parameters:
            self.dynamics_panel = DynamicsPanel(station)
            # The page reflows to its width (axes stacked when narrow) and scrolls only
            # up and down: never sideways, where the second axis's column was cut off.
            dynamics_page = QScrollArea()
            dynamics_page.setObjectName("dynamics_page")
            dynamics_page.setWidget(self.dynamics_panel)
            dynamics_page.setWidgetResizable(True)
            dynamics_page.setFrameShape(QFrame.Shape.NoFrame)
            dynamics_page.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
            bar = dynamics_page.verticalScrollBar().sizeHint().width()
            dynamics_page.setMinimumWidth(self.dynamics_panel.minimumSizeHint().width() + bar)
            self.dynamics_page = dynamics_page
            self._add_page(
                lambda: self.tr("&Dynamics"),
                dynamics_page,
                lambda: self.tr("Device parameters (Alt+D)"),
            )
        self.connection_panel = ConnectionPanel(station, self._settings)
        self.connection_panel.profileRequested.connect(self.profileRequested)
        self._add_page(
            lambda: self.tr("&Link"),
            self.connection_panel,
            lambda: self.tr("Connect: emulator, serial port or BLE (Alt+L)"),
        )
        self.static_panel = StaticPanel(station, self.jog)
        self._build_layout()
        self._build_status_bar()
        self._build_menus()

        self.model.lockChanged.connect(self._update_lock)
        self.model.linkStateChanged.connect(self._show_link_status)
        self.model.linkStateChanged.connect(self._update_machine_menu)
        self.model.message.connect(self._show_message)
        self.model.linkStateChanged.connect(self._clear_link_message)
        station.sessionChanged.connect(self._attach_session)
        self._attach_session()
        self._update_lock()
        self._show_link_status()
        self._build_dock_actions(checkpoint_dir)
        self._build_theme_menu()
        self._build_language_menu()
        self._restore_settings()
        self._install_filter()
        self.texts.also(self._retranslate)

    # --- building ------------------------------------------------------------

    def _add_page(self, title: Maker, page: QWidget, tooltip: Maker) -> None:
        button = self.menu_panel.add_page(title(), page, tooltip())
        self.texts.set(button.setText, title)
        self.texts.set(button.setToolTip, tooltip)

    def _retranslate(self) -> None:
        """What is made from state, said again in the language just installed."""
        self._update_lock()
        self._show_link_status()
        self._show_rejected()
        self._fill_recent_menu()
        for action, button in self.home_actions:
            action.setText(button.text().replace("  ", " "))
            action.setToolTip(button.toolTip())
        # The key list and the About box are made when first shown: made again next time.
        for dialog in (self._help, self._about):
            if dialog is not None:
                dialog.close()
                dialog.deleteLater()
        self._help = None
        self._about = None

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

    def _build_dock_actions(self, checkpoint_dir: Path | None) -> None:
        """The View menu's entries for the docks; each dock is built when first wanted.

        The jobs dock (job formats, their readers, the preview's pyqtgraph),
        the telemetry plots and the developer pane are most of what the window
        would import and build, and none of them is on the first screen:
        they come when shown (their menu entry or key, a job opened, a test
        asking for one), or at start when the last session closed with them
        shown.  What records from the start does so without its dock: the
        telemetry recorder and the developer pane's frame log are made here,
        so a dock opened later shows the history since the window opened.
        """
        self._checkpoint_dir = checkpoint_dir
        self._job_runner: JobRunner | None = None
        self._jobs_dock: JobsDock | None = None
        self._telemetry_dock: TelemetryDock | None = None
        self._developer_pane: DeveloperPane | None = None
        self._colours: PlotColours | None = None
        # Stop ends the job (its checkpoint kept): otherwise a G-code job took the stop's
        # reset for a device reset and carried on, moving the machine again by itself.
        self.jog.stopRequested.connect(self._abort_job)
        self.telemetry = TelemetryRecorder(self.station, parent=self)
        self.frame_log = FrameLog(self.station, parent=self)
        self.jobs_action = self._dock_action(
            lambda: QCoreApplication.translate("JobsDock", "Jobs"),
            "Ctrl+J",
            lambda: self.jobs_dock,
        )
        self.telemetry_action = self._dock_action(
            lambda: QCoreApplication.translate("TelemetryDock", "Telemetry"),
            "Ctrl+T",
            lambda: self.telemetry_dock,
        )
        # Shift+V shows and hides it, from any focus, like the original tool's extension.
        self.developer_action = self._dock_action(
            lambda: QCoreApplication.translate("DeveloperPane", "Developer"),
            "Shift+V",
            lambda: self.developer_pane,
        )
        self.developer_action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
        self.addAction(self.developer_action)

    def _dock_action(self, title: Maker, shortcut: str, dock: Callable[[], QDockWidget]) -> QAction:
        """A checkable View entry standing for a dock's own toggle until the dock is built."""
        action = QAction(self, checkable=True)
        self.texts.set(action.setText, title)
        action.setShortcut(QKeySequence(shortcut))
        action.triggered.connect(lambda checked: self._show_dock(action, dock(), checked))
        self.view_menu.addAction(action)
        return action

    def _show_dock(self, action: QAction, dock: QDockWidget, checked: bool) -> None:
        """Shown in front, or hidden, as the original's Shift+V showed its extension.

        A dock shown but behind another's tab (the developer pane behind the
        plots) is brought forward rather than hidden: a key that seemed to do
        nothing, or hid what could not be seen, is what the operator met.
        """
        behind = bool(self.tabifiedDockWidgets(dock)) and dock.visibleRegion().isEmpty()
        if not checked and dock.isVisible() and behind:
            checked = True
            action.setChecked(True)
        dock.setVisible(checked)
        if checked:
            dock.raise_()

    def _add_dock(self, dock: QDockWidget, area: Qt.DockWidgetArea, action: QAction) -> None:
        """Place a dock built just now where the last session left it, hidden until asked."""
        self.addDockWidget(area, dock)
        if not self.restoreDockWidget(dock):
            dock.hide()
        dock.toggleViewAction().toggled.connect(action.setChecked)
        action.setChecked(not dock.isHidden())

    @property
    def job_runner(self) -> JobRunner:
        if self._job_runner is None:
            from app.jobs.run.runner import JobRunner

            checkpoint_dir = self._checkpoint_dir
            if checkpoint_dir is None:
                data = QStandardPaths.writableLocation(
                    QStandardPaths.StandardLocation.AppDataLocation
                )
                checkpoint_dir = Path(data) / "checkpoints"
            self._job_runner = JobRunner(self.station, checkpoint_dir, parent=self)
            gcode_panel = getattr(self, "gcode_panel", None)
            if isinstance(gcode_panel, GcodePanel):
                # The winder's board radius, zeroing by hand, follows the job loaded.
                gcode_panel.follow_jobs(self._job_runner)
        return self._job_runner

    def _abort_job(self) -> None:
        if self._job_runner is not None:
            self._job_runner.abort()

    @property
    def jobs_dock(self) -> JobsDock:
        if self._jobs_dock is None:
            from widgets.jobs.dock import JobsDock

            dock = JobsDock(self.station, self.job_runner, self)
            self._jobs_dock = dock
            dock.jobOpened.connect(self._remember_job)
            if self._remembers:
                dock.restore_options(self._settings.job_options(self.station.profile.name))
            if self._colours is not None:
                dock.preview.apply_colours(self._colours)
            self._add_dock(dock, Qt.DockWidgetArea.RightDockWidgetArea, self.jobs_action)
        return self._jobs_dock

    @property
    def telemetry_dock(self) -> TelemetryDock:
        if self._telemetry_dock is None:
            from widgets.telemetry_dock import TelemetryDock

            dock = TelemetryDock(self.telemetry, self)
            self._telemetry_dock = dock
            if self._colours is not None:
                dock.apply_colours(self._colours)
            self._add_dock(dock, Qt.DockWidgetArea.BottomDockWidgetArea, self.telemetry_action)
            self._tabify_bottom()
        return self._telemetry_dock

    @property
    def developer_pane(self) -> DeveloperPane:
        if self._developer_pane is None:
            from widgets.developer.pane import DeveloperPane

            pane = DeveloperPane(self.station, self, frame_log=self.frame_log)
            self._developer_pane = pane
            self._add_dock(pane, Qt.DockWidgetArea.BottomDockWidgetArea, self.developer_action)
            self._tabify_bottom()
        return self._developer_pane

    def _tabify_bottom(self) -> None:
        """The plots and the developer pane share the bottom as tabs, unless placed otherwise.

        Side by side the two need more than a 1280 px screen.  Either can still
        be dragged out to float.
        """
        telemetry, developer = self._telemetry_dock, self._developer_pane
        if telemetry is None or developer is None:
            return
        bottom = Qt.DockWidgetArea.BottomDockWidgetArea
        if any(d.isFloating() or self.dockWidgetArea(d) != bottom for d in (telemetry, developer)):
            return
        if developer not in self.tabifiedDockWidgets(telemetry):
            self.tabifyDockWidget(telemetry, developer)

    def _built_docks(self) -> list[QDockWidget]:
        docks = (self._jobs_dock, self._telemetry_dock, self._developer_pane)
        return [dock for dock in docks if dock is not None]

    def _build_theme_menu(self) -> None:
        """View → Colours: as the desktop says (and when it changes), light or dark; kept."""
        self.theme = ThemeController(self._settings.theme, self)
        self.theme.coloursChanged.connect(self._apply_colours)
        self._apply_colours(self.theme.colours)
        self.view_menu.addSeparator()
        menu = self.view_menu.addMenu("")
        self.texts.set(menu.setTitle, lambda: self.tr("&Colours"))
        group = QActionGroup(self)
        self.theme_actions: dict[str, QAction] = {}
        captions: tuple[tuple[str, Maker], ...] = (
            ("system", lambda: self.tr("As the &system")),
            ("light", lambda: self.tr("&Light")),
            ("dark", lambda: self.tr("&Dark")),
        )
        for choice, caption in captions:
            action = QAction(self, checkable=True)
            self.texts.set(action.setText, caption)
            action.setChecked(choice == self.theme.choice)
            action.triggered.connect(lambda _=False, c=choice: self.set_theme(c))
            group.addAction(action)
            menu.addAction(action)
            self.theme_actions[choice] = action

    def _build_language_menu(self) -> None:
        """View → Language: the system's or a fixed one; kept, and switched at once."""
        menu = self.view_menu.addMenu("")
        self.texts.set(menu.setTitle, lambda: self.tr("L&anguage"))
        group = QActionGroup(self)
        self.language_actions: dict[str, QAction] = {}
        choices: list[tuple[str, Maker]] = [("system", lambda: self.tr("As the &system"))]
        choices += [(code, lambda n=name: n) for code, name in LANGUAGES.items()]
        for choice, caption in choices:
            action = QAction(self, checkable=True)
            self.texts.set(action.setText, caption)
            action.setChecked(choice == self._settings.language)
            action.triggered.connect(lambda _=False, c=choice: self.set_language(c))
            group.addAction(action)
            menu.addAction(action)
            self.language_actions[choice] = action

    def set_language(self, choice: str) -> str:
        """Speak ``choice`` from now on, and remember it; returns the language installed.

        Installing the translator makes Qt send ``LanguageChange`` through every
        window, and each widget makes its texts again (:class:`Texts`): nothing is
        rebuilt, so the link, a running job and the fields' contents are untouched,
        and nothing is sent to the machine.
        """
        self._settings.language = choice
        if self._remembers:
            self._settings.sync()
        self.language_actions[choice].setChecked(True)
        language = i18n.install(choice, self._i18n_cache)
        self._show_message(self.tr("Language: {0}").format(LANGUAGES[language]))
        return language

    def set_theme(self, choice: str) -> None:
        """Use and remember the colours chosen ("system", "light" or "dark")."""
        self._settings.theme = choice
        if self._remembers:
            self._settings.sync()
        self.theme_actions[choice].setChecked(True)
        self.theme.set_choice(choice)

    def _apply_colours(self, colours: PlotColours) -> None:
        self._colours = colours  # for the docks not built yet
        if self._jobs_dock is not None:
            self._jobs_dock.preview.apply_colours(colours)
        if self._telemetry_dock is not None:
            self._telemetry_dock.apply_colours(colours)

    def _build_status_bar(self) -> None:
        self.link_status = QLabel()
        self.message_label = QLabel()
        self.message_timer = QTimer(self)
        self.message_timer.setSingleShot(True)
        self.message_timer.setInterval(MESSAGE_SHOWN_MS)
        self.message_timer.timeout.connect(self._expire_message)
        #: The link state when the message shown was said (a link failure's message goes
        #: when the link is back).
        self._message_link_state = LinkState.DISCONNECTED
        self.rejected_label = QLabel()
        self.texts.set(
            self.rejected_label.setToolTip,
            lambda: self.tr("Frames from the device that failed to decode"),
        )
        bar = self.statusBar()
        bar.addWidget(self.link_status)
        bar.addWidget(self.message_label, 1)
        bar.addPermanentWidget(self.rejected_label)
        self._show_rejected()

    def _build_menus(self) -> None:
        """File, Machine, View and Help: where a user of other senders looks first.

        Machine's entries press the page buttons they stand for, so the menu can do
        nothing the page would not (a locked button ignores the click).
        """
        bar = self.menuBar()
        t = self.texts
        file_menu = bar.addMenu("")
        t.set(file_menu.setTitle, lambda: self.tr("&File"))
        self.open_action = QAction(self)
        t.set(self.open_action.setText, lambda: self.tr("&Open job…"))
        self.open_action.setShortcut(QKeySequence.StandardKey.Open)
        self.open_action.triggered.connect(self._ask_open_job)
        file_menu.addAction(self.open_action)
        self.recent_menu = file_menu.addMenu("")
        t.set(self.recent_menu.setTitle, lambda: self.tr("&Recent jobs"))
        self.recent_menu.aboutToShow.connect(self._fill_recent_menu)
        self._fill_recent_menu()
        file_menu.addSeparator()
        self.quit_action = QAction(self)
        t.set(self.quit_action.setText, lambda: self.tr("&Quit"))
        self.quit_action.setShortcut(QKeySequence("Ctrl+Q"))
        self.quit_action.triggered.connect(self.close)
        file_menu.addAction(self.quit_action)

        machine_menu = bar.addMenu("")
        t.set(machine_menu.setTitle, lambda: self.tr("&Machine"))
        self.connect_action = QAction(self)
        t.set(self.connect_action.setText, lambda: self.tr("&Connect"))
        self.connect_action.triggered.connect(self.connection_panel.connect_selected)
        self.disconnect_action = QAction(self)
        t.set(self.disconnect_action.setText, lambda: self.tr("&Disconnect"))
        self.disconnect_action.triggered.connect(self.station.stop_and_close)
        machine_menu.addAction(self.connect_action)
        machine_menu.addAction(self.disconnect_action)
        machine_menu.addSeparator()
        self.home_actions: list[tuple[QAction, QPushButton]] = []
        for button in self._home_buttons():
            action = QAction(button.text().replace("  ", " "), self)
            action.setToolTip(button.toolTip())
            action.triggered.connect(button.click)
            machine_menu.addAction(action)
            self.home_actions.append((action, button))
        machine_menu.addSeparator()
        stops = self.station.profile.capabilities.stop_command
        # Esc is routed by the window (see _route_key), not a shortcut: shown, not bound.
        self.stop_action = QAction(self)
        t.set(
            self.stop_action.setText,
            lambda: (self.tr("&Stop") if stops else self.tr("&Drop the queue")) + "\tEsc",
        )
        t.set(self.stop_action.setToolTip, lambda: stop_caption(self.station.profile)[1])
        self.stop_action.triggered.connect(self.stop_all)
        machine_menu.addAction(self.stop_action)
        machine_menu.setToolTipsVisible(True)

        self.view_menu = bar.addMenu("")
        t.set(self.view_menu.setTitle, lambda: self.tr("&View"))
        help_menu = bar.addMenu("")
        t.set(help_menu.setTitle, lambda: self.tr("&Help"))
        self.shortcuts_action = QAction(self)
        t.set(self.shortcuts_action.setText, lambda: self.tr("&Keys"))
        self.shortcuts_action.setShortcut(QKeySequence(Qt.Key.Key_F1))
        self.shortcuts_action.triggered.connect(self.show_shortcuts)
        help_menu.addAction(self.shortcuts_action)
        self.addAction(self.shortcuts_action)
        self.about_action = QAction(self)
        t.set(self.about_action.setText, lambda: self.tr("&About StepDeck"))
        self.about_action.triggered.connect(self.show_about)
        help_menu.addAction(self.about_action)
        self._help = None
        self._about = None

    def _home_buttons(self) -> list[QPushButton]:
        """The page buttons that home this machine, as the machine means "home"."""
        if self.station.profile.dialect == "gcode":
            return [self.gcode_panel.home_button]  # $H homes every axis at once
        if self.station.profile.dialect == "drill":
            return [self.drill_panel.command_buttons["N"]]
        return list(self.manual_panel.home_buttons)

    def _ask_open_job(self) -> None:
        self.jobs_dock.show()
        self.jobs_dock.raise_()
        self.jobs_dock.ask_open()

    def _remember_job(self, path: object) -> None:
        if isinstance(path, Path):
            self._settings.add_recent_job(str(path))
            if self._remembers:
                self._settings.sync()

    def _fill_recent_menu(self) -> None:
        """The list as stored now: another StepDeck window may have added to it."""
        self.recent_menu.clear()
        paths = self._settings.recent_jobs()
        for number, text in enumerate(paths, start=1):
            path = Path(text)
            action = self.recent_menu.addAction(f"&{number} {shown(path.name)}")
            action.setToolTip(shown(text))
            action.setData(text)
            action.triggered.connect(lambda _=False, p=path: self.open_recent(p))
        if not paths:
            self.recent_menu.addAction(self.tr("(none yet)")).setEnabled(False)
            return
        self.recent_menu.addSeparator()
        self.recent_menu.addAction(self.tr("&Clear the list"), self._clear_recent)
        self.recent_menu.setToolTipsVisible(True)

    def _clear_recent(self) -> None:
        self._settings.set_recent_jobs([])
        if self._remembers:
            self._settings.sync()

    def open_recent(self, path: Path) -> bool:
        """Open a job from the recent list (the dock says why when it cannot)."""
        self.jobs_dock.show()
        if not path.is_file():
            self.jobs_dock.say(
                self.tr("{0}: not opened — the file is no longer there").format(shown(path.name))
            )
            return False
        return self.jobs_dock.open_path(path, background=True)

    def _update_machine_menu(self, *_args: object) -> None:
        linked = self.model.link_state is not LinkState.DISCONNECTED
        self.connect_action.setEnabled(not linked)
        self.disconnect_action.setEnabled(linked)
        for action, button in self.home_actions:
            action.setEnabled(button.isEnabled())

    def show_about(self) -> QMessageBox:
        """Name, version and what this is (non-modal; returns the box)."""
        if self._about is None:
            what = self.tr(
                "A control station for small stepper machines: XY stages, a PCB drill, "
                "G-code plotters, the usb3 unit and the string-art winder."
            )
            machine = self.tr("Machine: {0}").format(html.escape(self.station.profile.shown_title))
            self._about = QMessageBox(
                QMessageBox.Icon.Information,
                self.tr("About StepDeck"),
                f"<b>StepDeck {station_version()}</b><p>{what}</p><p>{machine}</p>",
                parent=self,
            )
            self._about.setObjectName("about_box")
            self._about.setWindowModality(Qt.WindowModality.NonModal)
        self._about.show()
        return self._about

    # --- public --------------------------------------------------------------

    def show_shortcuts(self) -> QDialog:
        """Show (non-modal) the list of keys; returns the dialog."""
        if self._help is None:
            esc = stop_key_text(self.station.profile)
            rows = "".join(
                f"<tr><td style='padding-right:16px'><b>{self.tr(keys)}</b></td>"
                f"<td>{esc if keys == 'Esc' else self.tr(str(what))}</td></tr>"
                for keys, what in SHORTCUTS
            )
            note = self.tr(
                "Arrows do not jog while a text or number field has focus: there they keep "
                "editing. Esc works from anywhere in the window and also closes an open menu; "
                "in a dialog (like this one) Esc closes the dialog only."
            )
            text = QLabel(f"<table>{rows}</table><p>{note}</p>")
            text.setWordWrap(True)
            buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
            self._help = QDialog(self)
            self._help.setWindowTitle(self.tr("StepDeck — keyboard shortcuts"))
            buttons.rejected.connect(self._help.close)
            layout = QVBoxLayout(self._help)
            layout.addWidget(text)
            layout.addWidget(buttons)
        self._help.show()
        self._help.activateWindow()
        return self._help

    def stop_all(self) -> None:
        """What Esc and the Stop buttons do: forget held input and stop every axis."""
        self.jog.stop_all()

    # --- key routing and the runaway-jog guard -------------------------------

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        kind = event.type()
        if kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease):
            if isinstance(event, QKeyEvent) and self._owns(watched) and not _in_dialog(watched):
                assert isinstance(watched, QWidget)
                return self._route_key(watched, event)
        elif kind == QEvent.Type.WindowDeactivate:
            if watched is self:
                self.jog.release_all()
        elif kind == QEvent.Type.FocusOut:
            if isinstance(event, QFocusEvent) and self._owns(watched) and self._focus_left(event):
                self.jog.release_all()
        elif kind == QEvent.Type.ApplicationDeactivate:
            self.jog.release_all()
        return False

    def _owns(self, watched: QObject) -> bool:
        """Whether ``watched`` belongs to this window, floating docks included."""
        widget = watched if isinstance(watched, QWidget) else None
        while widget is not None:
            if widget is self:
                return True
            widget = widget.parentWidget()
        return False

    def _focus_left(self, event: QFocusEvent) -> bool:
        """Whether keyboard focus left this window (not just moved inside it)."""
        if event.reason() in (
            Qt.FocusReason.ActiveWindowFocusReason,
            Qt.FocusReason.PopupFocusReason,
        ):
            return True
        now = QApplication.focusWidget()
        return now is None or now.window() is not self

    def _route_key(self, receiver: QWidget, event: QKeyEvent) -> bool:
        """Handle jog keys and Esc; returns True when the event is consumed."""
        key = event.key()
        press = event.type() == QEvent.Type.KeyPress
        if key == Qt.Key.Key_Escape:
            if press and not event.isAutoRepeat():
                self.jog.stop_all()
            # A menu or combo list of this window that is open closes too: the stop is
            # never a reason to leave it hanging over the window.
            return not _in_popup(receiver)
        if key == Qt.Key.Key_Shift:
            if not event.isAutoRepeat():
                self.jog.set_shift(press)
            return False
        if key == Qt.Key.Key_V and event.modifiers() == Qt.KeyboardModifier.ShiftModifier:
            # The action's shortcut handles most of the window; number fields swallow the
            # keystroke first, so it is routed here. Free text keeps its capital V.
            if not press or event.isAutoRepeat() or _is_free_text(QApplication.focusWidget()):
                return False
            self.developer_action.trigger()
            return True
        if not self.jog.is_jog_key(key):
            return False
        if event.isAutoRepeat():
            # The key is already held: its repeats feed the dead-man and reach no widget.
            if press:
                return self.jog.key_repeat(key)
            return self.jog.is_held(key)
        if not press:
            return self.jog.key_release(key)
        if _is_text_editing(receiver) or _is_text_editing(QApplication.focusWidget()):
            return False
        self.jog.set_shift(bool(event.modifiers() & Qt.KeyboardModifier.ShiftModifier))
        self.jog.key_press(key)
        return True

    def _on_application_state(self, state: Qt.ApplicationState) -> None:
        if state != Qt.ApplicationState.ApplicationActive:
            self.jog.release_all()

    def _install_filter(self) -> None:
        app = QApplication.instance()
        if self._filtering or not isinstance(app, QApplication):
            return
        app.installEventFilter(self)
        app.applicationStateChanged.connect(self._on_application_state)
        self._filtering = True

    def _remove_filter(self) -> None:
        app = QApplication.instance()
        if not self._filtering or not isinstance(app, QApplication):
            return
        app.removeEventFilter(self)
        app.applicationStateChanged.disconnect(self._on_application_state)
        self._filtering = False

    # --- model → window ------------------------------------------------------

    def _update_lock(self) -> None:
        """Disable every motion control while the model says motion is refused, and say why."""
        reason = self.model.motion_lock_reason()
        enabled = reason is None
        # A job under way leaves the machine free to move but not to be jogged: the
        # jog buttons go off with the reason beside them, and a jog key says it.
        jog_lock = self.model.jog_lock_reason if enabled else None
        self.jog.set_enabled(enabled and jog_lock is None, reason or jog_lock)
        for panel in self.motion_panels:
            panel.set_motion_enabled(enabled)
        self.manual_panel.set_jog_lock(jog_lock)
        self._update_machine_menu()
        self.lock_label.setText(self.tr("Motion locked: {0}").format(reason))
        self.lock_label.setVisible(not enabled)

    def _show_link_status(self, _state: object = None) -> None:
        state = self.model.link_state
        detail = f" — {link_detail_text(self.model.link_detail)}" if self.model.link_detail else ""
        session = self.station.session
        period = (
            f" · {session.period_ms} ms"
            if session is not None and state in (LinkState.CONNECTED, LinkState.STALE)
            else ""
        )
        self.link_status.setText(
            self.tr("Link {0}").format(link_state_text(state)) + detail + period
        )

    def _show_message(self, text: str) -> None:
        """Show ``text`` until the next message or for MESSAGE_SHOWN_MS, whichever comes first.

        A message left standing reads as the current state long after it stopped being
        true ("stopping…" an hour later).  The same text again only restarts the clock.
        """
        if self._repeats_link_status(text):
            return
        self.message_label.setText(text)
        self.message_label.setToolTip(text)
        self._message_link_state = self.model.link_state
        self.message_timer.start()

    def _repeats_link_status(self, text: str) -> bool:
        """Whether ``text`` only says again what the link status beside it says now.

        "Link lost: no reply" next to "Link lost — no reply" read as two events.
        """
        state = self.model.link_state
        detail = self.model.link_detail
        if state in (LinkState.CONNECTED, LinkState.DISCONNECTED) or not detail:
            return False
        link = self.station.link
        if link is not None and detail == link.describe():
            return False  # only the port's name: the message says more
        return detail in text

    def _expire_message(self) -> None:
        self.message_label.clear()
        self.message_label.setToolTip("")

    def _clear_link_message(self, state: object) -> None:
        """A message from while the link was failing is wrong once it is back ("no answer…")."""
        if state is LinkState.CONNECTED and self._message_link_state in (
            LinkState.CONNECTING,
            LinkState.STALE,
            LinkState.LOST,
        ):
            self.message_timer.stop()
            self._expire_message()

    def _show_rejected(self, *_args: object) -> None:
        session = self.station.session
        count = session.rejected if session is not None else 0
        self.rejected_label.setText(self.tr("rejected frames: %n", "", count))

    def _attach_session(self) -> None:
        # The count changes with what arrives: refresh on every received frame.
        session = self.station.session
        if session is not None:
            session.frameReceived.connect(self._show_rejected)
        self._show_rejected()
        self._show_link_status()

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
        # The docks the last session showed are built first, so the state places them;
        # a state saved before docks were built on demand does not say: all are built.
        active = self.isActiveWindow()
        shown_docks = self._settings.read(DOCKS_SHOWN)
        docks: dict[str, Callable[[], object]] = {
            "jobs_dock": lambda: self.jobs_dock,
            "telemetry_dock": lambda: self.telemetry_dock,
            "developer_pane": lambda: self.developer_pane,
        }
        for name, build in docks.items():
            if shown_docks is None or name in shown_docks.split(","):
                build()
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

    def _restore_drill_timing(self) -> None:
        """The drill's timing constants the operator set last time (FIDELITY S2-06)."""
        base = self.station.profile.drill_timing
        timing = self._settings.drill_timing(base) if self._remembers else base
        if timing != base:
            self.station.set_drill_timing(timing)
            self.drill_panel.timing_box.show_timing(timing)

    def _remember_drill_timing(self, timing: DrillTiming | None) -> None:
        if not self._remembers:
            return
        self._settings.set_drill_timing(timing)
        self._settings.sync()

    def _warn_about_settings(self) -> None:
        """Settings that could not be used: in the status bar and a box, once per start."""
        warnings = self._settings.take_warnings()
        if not warnings:
            return
        self._show_message(
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
        shown_docks = [dock.objectName() for dock in self._built_docks() if not dock.isHidden()]
        self._settings.write(DOCKS_SHOWN, ",".join(shown_docks))
        self._settings.write(PAGE, self.menu_panel.current)
        if self._jobs_dock is not None:
            self._settings.set_job_options(
                self._jobs_dock.option_values(), self.station.profile.name
            )
        self._settings.sync()

    def _close_when_stopped(self) -> None:
        self.station.linkClosed.disconnect(self._close_when_stopped)
        self._close_after_stop = False
        # After the station's signal has returned: closing re-enters the station.
        QTimer.singleShot(0, self.close)

    def showEvent(self, event: QShowEvent) -> None:
        self._install_filter()
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
        if not self.station.stop_and_close():
            if not self._close_after_stop:
                self._close_after_stop = True
                self.station.linkClosed.connect(self._close_when_stopped)
            self._show_message(self.tr("Stopping every axis before closing…"))
            event.ignore()
            return
        self.save_settings()
        self._remove_filter()
        self.theme.release()
        if self._help is not None:
            self._help.close()
        if self._about is not None:
            self._about.close()
        self.station.shutdown()
        super().closeEvent(event)
