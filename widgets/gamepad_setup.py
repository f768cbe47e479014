"""The gamepad in the window: Machine → Gamepad… (on/off, which device), its state in the
status bar, and its mapping for Help → Keys.

The jogging itself is :class:`app.gamepad.poller.GamepadJog`'s, fed to the window's own
:class:`~widgets.jog_input.JogInput`, so the motion lock the window applies to the keys
applies to the pad too.  The pad jogs only while a StepDeck window is the active one: the
keys' rule, and a second StepDeck (or a game) reading the same pad moves nothing here.
"""

from __future__ import annotations

import html
from collections.abc import Callable

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Qt
from PySide6.QtGui import QAction, QGuiApplication
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QMainWindow,
    QMenu,
    QVBoxLayout,
    QWidget,
)

from app.gamepad.poller import GamepadJog, PadState
from app.gamepad.settings import GAMEPAD_DEVICE, GAMEPAD_ENABLED
from app.gamepad.source import PadSource
from app.settings import StationSettings
from app.station import Station
from widgets.after_first_paint import AfterFirstPaint
from widgets.jog_input import JogInput
from widgets.retranslate import Texts

# What the pad does (translated where shown: QT_TRANSLATE_NOOP only marks them).
MAPPING: tuple[tuple[object, object], ...] = (
    (
        QT_TRANSLATE_NOOP("Gamepad", "Gamepad: left stick + shoulder button (held)"),
        QT_TRANSLATE_NOOP(
            "Gamepad",
            "Jog X and Y while both are held; pushed further, faster (G-code boards)",
        ),
    ),
    (
        QT_TRANSLATE_NOOP("Gamepad", "Gamepad: right stick up/down + shoulder button"),
        QT_TRANSLATE_NOOP("Gamepad", "Jog Z while both are held, on machines with a Z axis"),
    ),
    (
        QT_TRANSLATE_NOOP("Gamepad", "Joystick: stick + trigger (held)"),
        QT_TRANSLATE_NOOP("Gamepad", "Jog X and Y while both are held"),
    ),
    (
        QT_TRANSLATE_NOOP("Gamepad", "Let go of the stick or the button, or unplug"),
        QT_TRANSLATE_NOOP("Gamepad", "The jog stops at once"),
    ),
)


def _tr(text: str) -> str:
    """For the texts marked in :data:`MAPPING` (lupdate finds the others where written)."""
    return QCoreApplication.translate("Gamepad", text)


def mapping_rows() -> str:
    """The mapping as rows of Help → Keys' table (HTML)."""
    return "".join(
        f"<tr><td style='padding-right:16px'><b>{html.escape(_tr(str(what)))}</b></td>"
        f"<td>{html.escape(_tr(str(does)))}</td></tr>"
        for what, does in MAPPING
    )


def _station_active() -> bool:
    return QGuiApplication.applicationState() == Qt.ApplicationState.ApplicationActive


class GamepadSetup(QObject):
    """The window's gamepad: its poller, its menu entry, its status and its dialog."""

    def __init__(
        self,
        window: QMainWindow,
        station: Station,
        jog: JogInput,
        settings: StationSettings,
        menu: QMenu,
        *,
        remembers: bool,
        source_factory: Callable[[], PadSource] | None = None,
    ) -> None:
        super().__init__(window)
        self._window = window
        self._settings = settings
        self._remembers = remembers
        self.poller = GamepadJog(
            station, jog, source_factory=source_factory, active=_station_active, parent=self
        )
        self.poller.set_device(settings.read(GAMEPAD_DEVICE))
        self.texts = Texts(window.statusBar())
        self.status_label = QLabel()
        self.status_label.setObjectName("gamepad_status")
        self.status_label.setVisible(False)
        window.statusBar().addPermanentWidget(self.status_label)
        self.action = QAction(window)
        self.texts.set(
            self.action.setText, lambda: QCoreApplication.translate("Gamepad", "&Gamepad…")
        )
        self.action.triggered.connect(lambda _=False: self.show_dialog())
        menu.addSeparator()
        menu.addAction(self.action)
        self.dialog: GamepadDialog | None = None
        self.poller.stateChanged.connect(self._show_state)
        self.texts.also(self._show_state)
        self._show_state()
        # SDL loads (a tenth of a second) after the window is on screen, not before.
        self.started = AfterFirstPaint(window, self._start)

    def _start(self) -> None:
        if self._settings.read(GAMEPAD_ENABLED):
            self.poller.set_enabled(True)

    # --- the operator's choices -------------------------------------------------------

    @property
    def enabled(self) -> bool:
        return self.poller.enabled

    def set_enabled(self, enabled: bool) -> None:
        """Turn the pad on or off, and remember it."""
        self.poller.set_enabled(enabled)
        self._settings.write(GAMEPAD_ENABLED, enabled)
        self._sync()

    def set_device(self, name: str) -> None:
        """Read this device from now on ("": the first found), and remember it."""
        self.poller.set_device(name)
        self._settings.write(GAMEPAD_DEVICE, name)
        self._sync()

    def _sync(self) -> None:
        if self._remembers:
            self._settings.sync()

    # --- what is shown ----------------------------------------------------------------

    def state_text(self) -> str:
        """The pad's state in words: off, unavailable (why), looking, or the device read."""
        poller = self.poller
        state = poller.state
        if poller.unavailable is not None:
            return QCoreApplication.translate("Gamepad", "Gamepad unavailable: {0}").format(
                poller.unavailable
            )
        if state is PadState.OFF:
            return QCoreApplication.translate("Gamepad", "Gamepad: off")
        if state is PadState.LOADING:
            return QCoreApplication.translate("Gamepad", "Gamepad: starting…")
        if state is PadState.CONNECTED and poller.device is not None:
            return QCoreApplication.translate("Gamepad", "Gamepad: {0}").format(poller.device.name)
        if poller.wanted:
            return QCoreApplication.translate("Gamepad", "Gamepad: waiting for {0}").format(
                poller.wanted
            )
        return QCoreApplication.translate("Gamepad", "Gamepad: none plugged in")

    def _show_state(self) -> None:
        self.status_label.setText(self.state_text())
        self.status_label.setVisible(self.enabled)
        if self.dialog is not None:
            self.dialog.refresh()

    def show_dialog(self) -> GamepadDialog:
        """Machine → Gamepad…: non-modal; returns the dialog."""
        if self.dialog is None:
            self.dialog = GamepadDialog(self, self._window)
        self.dialog.refresh()
        self.dialog.show()
        self.dialog.activateWindow()
        return self.dialog

    def shutdown(self) -> None:
        """The window closes: the pad lets go and its device is closed."""
        self.poller.shutdown()


class GamepadDialog(QDialog):
    """On/off, the device, the state, and the mapping."""

    def __init__(self, setup: GamepadSetup, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("gamepad_dialog")
        self._setup = setup
        texts = Texts(self)
        texts.set(
            self.setWindowTitle, lambda: QCoreApplication.translate("Gamepad", "StepDeck — gamepad")
        )
        self.enable_box = QCheckBox()
        texts.set(
            self.enable_box.setText,
            lambda: QCoreApplication.translate("Gamepad", "&Jog with a gamepad or joystick"),
        )
        self.enable_box.toggled.connect(setup.set_enabled)
        self.device_combo = QComboBox()
        self.device_combo.activated.connect(self._device_chosen)
        self.state_label = QLabel()
        self.state_label.setWordWrap(True)
        self.mapping_label = QLabel()
        self.mapping_label.setWordWrap(True)
        form = QFormLayout()
        device_label = texts.label(lambda: QCoreApplication.translate("Gamepad", "&Device:"))
        device_label.setBuddy(self.device_combo)
        form.addRow(device_label, self.device_combo)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addWidget(self.enable_box)
        layout.addLayout(form)
        layout.addWidget(self.state_label)
        layout.addWidget(self.mapping_label)
        layout.addWidget(buttons)
        texts.also(self.refresh)

    def refresh(self) -> None:
        """The state, the devices attached now, and the mapping, as they are now."""
        setup = self._setup
        poller = setup.poller
        self.enable_box.blockSignals(True)
        self.enable_box.setChecked(setup.enabled)
        self.enable_box.blockSignals(False)
        names = poller.device_names()
        if poller.wanted and poller.wanted not in names:
            names.append(poller.wanted)  # remembered, not plugged in now
        self.device_combo.clear()
        self.device_combo.addItem(QCoreApplication.translate("Gamepad", "The first one found"), "")
        for name in names:
            self.device_combo.addItem(name, name)
        self.device_combo.setCurrentIndex(max(0, self.device_combo.findData(poller.wanted)))
        self.state_label.setText(setup.state_text())
        note = QCoreApplication.translate(
            "Gamepad",
            "Nothing jogs unless the enable button is held with the stick: a dropped pad or "
            "a drifting stick moves nothing. The pad jogs only while a StepDeck window is "
            "active, and a job under way refuses it as it refuses the keys.",
        )
        self.mapping_label.setText(f"<table>{mapping_rows()}</table><p>{html.escape(note)}</p>")

    def _device_chosen(self, index: int) -> None:
        name = self.device_combo.itemData(index)
        self._setup.set_device(name if isinstance(name, str) else "")
