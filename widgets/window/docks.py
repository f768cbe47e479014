"""The window's docks — jobs, telemetry plots, developer pane — each built when first wanted.

The jobs dock (job formats, their readers, the preview's pyqtgraph), the
telemetry plots and the developer pane are most of what the window would
import and build, and none of them is on the first screen: they come when
shown (their menu entry or key, a job opened, a test asking for one), or at
start when the last session closed with them shown.  What records from the
start does so without its dock: the telemetry recorder and the developer
pane's frame log are made here, so a dock opened later shows the history
since the window opened.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, QStandardPaths, Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QDockWidget, QMainWindow, QMenu

from app.developer.frame_log import FrameLog
from app.settings import DOCKS_SHOWN, StationSettings
from app.station import Station
from app.telemetry import TelemetryRecorder
from widgets.retranslate import Maker, Texts
from widgets.theme import PlotColours
from widgets.window.pages import Pages

if TYPE_CHECKING:
    from app.jobs.run.runner import JobRunner
    from widgets.developer.pane import DeveloperPane
    from widgets.jobs.dock import JobsDock
    from widgets.telemetry_dock import TelemetryDock


class WindowDocks(QObject):
    """The docks of one window, their View entries, and the job runner behind the jobs dock.

    ``job_options``: the jobs dock's options as last kept for this machine (None: the
    window keeps no settings); ``job_opened`` hears of each job opened (the recent list).
    """

    def __init__(
        self,
        window: QMainWindow,
        station: Station,
        pages: Pages,
        view_menu: QMenu,
        texts: Texts,
        *,
        checkpoint_dir: Path | None,
        settings: StationSettings | None,
        job_opened: Callable[[object], None],
    ) -> None:
        super().__init__(window)
        self._window = window
        self._station = station
        self._pages = pages
        self._view_menu = view_menu
        self._texts = texts
        self._checkpoint_dir = checkpoint_dir
        self._settings = settings
        self._job_opened = job_opened
        self._job_runner: JobRunner | None = None
        self._jobs_dock: JobsDock | None = None
        self._telemetry_dock: TelemetryDock | None = None
        self._developer_pane: DeveloperPane | None = None
        self._colours: PlotColours | None = None
        #: Docks of features built elsewhere (the macros'), by object name → their builder:
        #: shown again at start and saved with these (:meth:`place_dock` places them).
        self.more: dict[str, Callable[[], QDockWidget]] = {}
        self._more_built: list[QDockWidget] = []
        self.telemetry = TelemetryRecorder(station, parent=window)
        self.frame_log = FrameLog(station, parent=window)
        self.jobs_action = self._dock_action(
            lambda: QCoreApplication.translate("JobsDock", "Jobs"), "Ctrl+J", lambda: self.jobs_dock
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
        window.addAction(self.developer_action)

    def _dock_action(self, title: Maker, shortcut: str, dock: Callable[[], QDockWidget]) -> QAction:
        """A checkable View entry standing for a dock's own toggle until the dock is built."""
        action = QAction(self._window, checkable=True)
        self._texts.set(action.setText, title)
        action.setShortcut(QKeySequence(shortcut))
        action.triggered.connect(lambda checked: self._show_dock(action, dock(), checked))
        self._view_menu.addAction(action)
        return action

    def _show_dock(self, action: QAction, dock: QDockWidget, checked: bool) -> None:
        """Shown in front, or hidden, as the original's Shift+V showed its extension.

        A dock shown but behind another's tab (the developer pane behind the
        plots) is brought forward rather than hidden: a key that seemed to do
        nothing, or hid what could not be seen, is what the operator met.
        """
        behind = bool(self._window.tabifiedDockWidgets(dock)) and dock.visibleRegion().isEmpty()
        if not checked and dock.isVisible() and behind:
            checked = True
            action.setChecked(True)
        dock.setVisible(checked)
        if checked:
            dock.raise_()

    def place_dock(self, dock: QDockWidget, area: Qt.DockWidgetArea, action: QAction) -> None:
        """A dock of :attr:`more`, built just now: placed, saved and restored as these are."""
        self._more_built.append(dock)
        self._add_dock(dock, area, action)
        self._tabify_bottom()

    def _add_dock(self, dock: QDockWidget, area: Qt.DockWidgetArea, action: QAction) -> None:
        """Place a dock built just now where the last session left it, hidden until asked."""
        self._window.addDockWidget(area, dock)
        if not self._window.restoreDockWidget(dock):
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
            self._job_runner = JobRunner(self._station, checkpoint_dir, parent=self._window)
            if self._pages.gcode is not None:
                # The winder's board radius, zeroing by hand, follows the job loaded.
                self._pages.gcode.follow_jobs(self._job_runner)
        return self._job_runner

    @property
    def runner_built(self) -> bool:
        return self._job_runner is not None

    def abort_job(self) -> None:
        """Stop ends the job (its checkpoint kept): otherwise a G-code job took the stop's
        reset for a device reset and carried on, moving the machine again by itself."""
        if self._job_runner is not None:
            self._job_runner.abort()

    @property
    def jobs_dock(self) -> JobsDock:
        if self._jobs_dock is None:
            from widgets.jobs.dock import JobsDock

            dock = JobsDock(self._station, self.job_runner, self._window)
            self._jobs_dock = dock
            dock.jobOpened.connect(self._job_opened)
            if self._settings is not None:
                dock.restore_options(self._settings.job_options(self._station.profile.name))
            if self._colours is not None:
                dock.preview.apply_colours(self._colours)
            if self._pages.drill is not None:  # the step-through walks what is drawn
                self._pages.drill.step_box.follow(dock.preview)
            self._add_dock(dock, Qt.DockWidgetArea.RightDockWidgetArea, self.jobs_action)
        return self._jobs_dock

    @property
    def telemetry_dock(self) -> TelemetryDock:
        if self._telemetry_dock is None:
            from widgets.telemetry_dock import TelemetryDock

            dock = TelemetryDock(self.telemetry, self._window)
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

            pane = DeveloperPane(self._station, self._window, frame_log=self.frame_log)
            self._developer_pane = pane
            self._add_dock(pane, Qt.DockWidgetArea.BottomDockWidgetArea, self.developer_action)
            self._tabify_bottom()
        return self._developer_pane

    def _tabify_bottom(self) -> None:
        """The docks of the bottom (the plots, the developer pane, the macros) share it as
        tabs, unless placed otherwise.

        Side by side they need more than a 1280 px screen, and the macros under the
        jobs dock more than 800 px.  Any can still be dragged out to float.
        """
        window = self._window
        bottom = Qt.DockWidgetArea.BottomDockWidgetArea
        docks = [
            d
            for d in (self._telemetry_dock, self._developer_pane, *self._more_built)
            if d is not None and not d.isFloating() and window.dockWidgetArea(d) == bottom
        ]
        for dock in docks[1:]:
            if dock not in window.tabifiedDockWidgets(docks[0]):
                window.tabifyDockWidget(docks[0], dock)

    def built(self) -> list[QDockWidget]:
        """The docks built so far (none until first wanted)."""
        docks = (self._jobs_dock, self._telemetry_dock, self._developer_pane)
        return [dock for dock in docks if dock is not None] + self._more_built

    def build_shown(self, shown: str | None) -> None:
        """Build the docks the last session showed (``shown``: their names, comma-separated),
        so the window state places them; a state saved before docks were built on demand
        does not say (None): all are built."""
        docks: dict[str, Callable[[], object]] = {
            "jobs_dock": lambda: self.jobs_dock,
            "telemetry_dock": lambda: self.telemetry_dock,
            "developer_pane": lambda: self.developer_pane,
            **self.more,
        }
        for name, build in docks.items():
            if shown is None or name in shown.split(","):
                build()

    def apply_colours(self, colours: PlotColours) -> None:
        self._colours = colours  # for the docks not built yet
        if self._jobs_dock is not None:
            self._jobs_dock.preview.apply_colours(colours)
        if self._telemetry_dock is not None:
            self._telemetry_dock.apply_colours(colours)

    def save(self, settings: StationSettings) -> None:
        """What of the docks is kept: which are shown, and the jobs dock's options."""
        shown = [dock.objectName() for dock in self.built() if not dock.isHidden()]
        settings.write(DOCKS_SHOWN, ",".join(shown))
        if self._jobs_dock is not None:
            settings.set_job_options(self._jobs_dock.option_values(), self._station.profile.name)
