"""The window's macros: a dock of buttons, its editor, and their keys.

Built only for machines that run macros (:func:`app.macros.machines.macros_available`);
the dock and its runner come on first use (its View entry, Ctrl+M, a macro
key, or a dock the last session showed), so the first window imports no job
runner.  The keys: Ctrl+M shows or hides the dock, Ctrl+1 … Ctrl+9 run the
first nine macros — each refused, and said why, as its button would be.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject, Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QMainWindow, QMenu

from app.macros.machines import macros_available
from app.macros.store import MacroStore
from app.settings import StationSettings
from app.station import Station
from widgets.retranslate import Texts
from widgets.window.docks import WindowDocks

if TYPE_CHECKING:
    from widgets.macros.dock import MacrosDock

#: The dock's object name: where the window's saved layout places it.
DOCK_NAME = "macros_dock"
#: Ctrl+1 … Ctrl+9.
KEYED_MACROS = 9


class WindowMacros(QObject):
    """The macros dock of one window (built when first wanted) and the keys that reach it."""

    def __init__(
        self,
        window: QMainWindow,
        station: Station,
        store: MacroStore,
        docks: WindowDocks,
        view_menu: QMenu,
        texts: Texts,
        checkpoint_dir: Path | None,
    ) -> None:
        super().__init__(window)
        self._window = window
        self._station = station
        self._store = store
        self._docks = docks
        self._checkpoint_dir = checkpoint_dir
        self._dock: MacrosDock | None = None
        self.action = QAction(window, checkable=True)
        texts.set(self.action.setText, lambda: QCoreApplication.translate("MacrosDock", "Macros"))
        self.action.setShortcut(QKeySequence("Ctrl+M"))
        self.action.triggered.connect(self._show)
        view_menu.addAction(self.action)
        self.run_actions: list[QAction] = []
        for number in range(1, KEYED_MACROS + 1):
            run = QAction(window)
            run.setShortcut(QKeySequence(f"Ctrl+{number}"))
            run.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
            run.triggered.connect(lambda _=False, index=number - 1: self.run_index(index))
            window.addAction(run)
            self.run_actions.append(run)
        docks.more[DOCK_NAME] = lambda: self.dock

    @property
    def dock(self) -> MacrosDock:
        if self._dock is None:
            from widgets.macros.dock import MacrosDock

            self._dock = MacrosDock(
                self._station, self._store, self._checkpoint_dir, parent=self._window
            )
            # With the plots, as a tab: under the jobs dock the window would pass 800 px.
            self._docks.place_dock(self._dock, Qt.DockWidgetArea.BottomDockWidgetArea, self.action)
        return self._dock

    @property
    def built(self) -> bool:
        return self._dock is not None

    def _show(self, checked: bool) -> None:
        dock = self.dock
        dock.setVisible(checked)
        if checked:
            dock.raise_()

    def run_index(self, index: int) -> bool:
        """The ``index``-th macro's key: shown in its dock, run or refused there."""
        dock = self.dock
        if dock.isHidden():
            dock.show()
            self.action.setChecked(True)
        return dock.run_index(index)

    def stop(self) -> None:
        """Stop (Esc, the Stop button) ends a macro under way."""
        if self._dock is not None:
            self._dock.runner.abort()


def install_macros(
    window: QMainWindow,
    station: Station,
    settings: StationSettings,
    docks: WindowDocks,
    view_menu: QMenu,
    texts: Texts,
    checkpoint_dir: Path | None,
) -> WindowMacros | None:
    """The window's macros where the machine runs them (None elsewhere: nothing is shown)."""
    if not macros_available(station.profile):
        return None
    store = MacroStore(settings, station.profile.name)
    macro_dir = checkpoint_dir / "macros" if checkpoint_dir is not None else None
    return WindowMacros(window, station, store, docks, view_menu, texts, macro_dir)
