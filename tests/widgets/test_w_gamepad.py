"""The gamepad in the window: Machine → Gamepad… turns it on and picks the device (kept across
a restart), the status bar names the device, the window's motion lock refuses the pad as it
refuses the keys, Help → Keys lists the mapping, and a station without SDL says so and
runs on."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QLabel, QMainWindow
from pytestqt.qtbot import QtBot

from app import i18n
from app.gamepad.poller import PadState
from app.gamepad.sdl import load_sdl
from app.gamepad.settings import GAMEPAD_DEVICE, GAMEPAD_ENABLED
from app.gamepad.source import PadSource, PadUnavailable
from app.profiles import load_profile
from app.settings import StationSettings
from tests.app.test_gamepad_sdl import FULL, LEFT_SHOULDER, LEFT_X, VirtualPad
from tests.helpers.harness import StationHarness
from widgets.gamepad_setup import GamepadSetup
from widgets.jog_input import JogInput
from widgets.main_window import MainWindow


@pytest.fixture
def pad() -> Iterator[VirtualPad]:
    virtual = VirtualPad(load_sdl())
    yield virtual
    virtual.detach()


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    yield harness
    harness.close()


def shown_window(qtbot: QtBot, harness: StationHarness, ini: Path) -> MainWindow:
    window = MainWindow(harness.station, QSettings(str(ini), QSettings.Format.IniFormat))
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    return window


def test_the_pad_jogs_in_the_window_named_in_the_status_bar_and_the_lock_refuses_it(
    qtbot: QtBot, grbl: StationHarness, pad: VirtualPad, tmp_path: Path
) -> None:
    window = shown_window(qtbot, grbl, tmp_path / "stepdeck.ini")
    grbl.connect()
    grbl.run(1.0)
    said: list[str] = []
    grbl.station.model.message.connect(said.append)
    setup = window.gamepad
    setup.set_device(pad.name)
    setup.set_enabled(True)
    label = window.findChild(QLabel, "gamepad_status")
    assert label is not None and label.isVisible()
    # SDL's import runs off the GUI thread first: the station says it is starting.
    assert label.text() in ("Gamepad: starting…", f"Gamepad: {pad.name}")
    qtbot.waitUntil(lambda: setup.poller.state is PadState.CONNECTED)
    assert label.text() == f"Gamepad: {pad.name}"
    pad.button(LEFT_SHOULDER, True)
    pad.axis(LEFT_X, FULL)
    setup.poller.poll()
    session = grbl.gcode_session
    assert session.jog_vector == (1, 0)
    pad.axis(LEFT_X, 0)
    setup.poller.poll()
    assert session.jog_vector == (0, 0)
    # A job owns the machine: the window locks the jog, and the pad is refused once.
    grbl.station.model.set_jog_lock("a job is running")
    pad.axis(LEFT_X, FULL)
    for _ in range(5):
        grbl.run(0.04)
        setup.poller.poll()
    assert session.jog_vector == (0, 0)
    assert said.count("Jog refused: a job is running") == 1
    # Unplugged: the status bar says none is there.
    pad.detach()
    setup.poller.poll()
    assert label.text() == f"Gamepad: waiting for {pad.name}"


def test_on_and_the_device_are_kept_and_the_pad_is_read_after_a_restart(
    qtbot: QtBot, grbl: StationHarness, pad: VirtualPad, tmp_path: Path
) -> None:
    ini = tmp_path / "stepdeck.ini"
    window = shown_window(qtbot, grbl, ini)
    dialog = window.gamepad.show_dialog()
    combo = dialog.device_combo
    qtbot.waitUntil(lambda: combo.count() > 1)  # listed once SDL is imported
    names = [combo.itemText(i) for i in range(combo.count())]
    assert names[0] == "The first one found" and pad.name in names
    combo.setCurrentIndex(names.index(pad.name))
    combo.activated.emit(names.index(pad.name))
    dialog.enable_box.setChecked(True)
    qtbot.waitUntil(lambda: window.gamepad.poller.state is PadState.CONNECTED)
    assert dialog.state_label.text() == f"Gamepad: {pad.name}"
    window.close()
    stored = StationSettings(QSettings(str(ini), QSettings.Format.IniFormat))
    assert stored.read(GAMEPAD_ENABLED) is True and stored.read(GAMEPAD_DEVICE) == pad.name
    again = shown_window(qtbot, grbl, ini)
    again.gamepad.started.now()  # after the first paint
    qtbot.waitUntil(lambda: again.gamepad.poller.state is PadState.CONNECTED)
    assert again.gamepad.poller.wanted == pad.name
    again.gamepad.set_enabled(False)
    assert not again.findChild(QLabel, "gamepad_status").isVisible()  # type: ignore[union-attr]


def test_help_keys_lists_the_pad(qtbot: QtBot, grbl: StationHarness, tmp_path: Path) -> None:
    window = shown_window(qtbot, grbl, tmp_path / "stepdeck.ini")
    text = window.show_shortcuts().findChild(QLabel).text()  # type: ignore[union-attr]
    assert "left stick + shoulder button" in text and "unplug" in text


def test_without_sdl_the_pad_is_unavailable_and_the_keys_jog_on(
    qtbot: QtBot, grbl: StationHarness
) -> None:
    grbl.connect()
    grbl.run(1.0)

    def missing() -> PadSource:
        raise PadUnavailable("pysdl2 is not installed (pip install 'stepdeck[gamepad]')")

    window = QMainWindow()
    qtbot.addWidget(window)
    jog = JogInput(grbl.station, window)
    menu = window.menuBar().addMenu("Machine")
    settings = StationSettings(None)
    setup = GamepadSetup(
        window, grbl.station, jog, settings, menu, remembers=False, source_factory=missing
    )
    dialog = setup.show_dialog()
    dialog.enable_box.setChecked(True)
    assert setup.poller.state is PadState.UNAVAILABLE
    assert dialog.state_label.text() == (
        "Gamepad unavailable: pysdl2 is not installed (pip install 'stepdeck[gamepad]')"
    )
    assert settings.read(GAMEPAD_ENABLED) is True  # kept: the extra may be installed later
    jog.key_press(0x01000014)  # Qt.Key_Right: the keys are untouched
    assert grbl.gcode_session.jog_vector == (1, 0)
    jog.release_all()


@pytest.mark.parametrize(
    ("language", "off", "enable"),
    [
        ("cs", "Gamepad: vypnut", "&Ruční posuv gamepadem nebo joystickem"),
        ("sk", "Gamepad: vypnutý", "&Ručný posuv gamepadom alebo joystickom"),
    ],
)
def test_the_gamepad_speaks_czech_and_slovak(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path, language: str, off: str, enable: str
) -> None:
    window = MainWindow(
        grbl.station,
        QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat),
        i18n_cache=tmp_path / "qm",
    )
    qtbot.addWidget(window)
    try:
        dialog = window.gamepad.show_dialog()
        window.set_language(language)  # Qt delivers the change through the event loop
        qtbot.waitUntil(lambda: dialog.enable_box.text() == enable)
        assert dialog.state_label.text() == off
        assert window.gamepad.status_label.text() == off
        assert window.gamepad.action.text() == "&Gamepad…"
        rows = window.show_shortcuts().findChild(QLabel).text()  # type: ignore[union-attr]
        assert "Gamepad:" in rows and "shoulder button" not in rows
    finally:
        i18n.remove()
