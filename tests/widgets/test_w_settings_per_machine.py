"""Settings that concern the machine are kept per machine profile; those of the person are not.

The arrow keys' step, skipping lines a machine cannot run and the last link
were once global: "1 mm per tap" chosen on the drill came back as "1 deg per
tap" on the winder, and the Link page showed the drill's serial port while
the stage ran on the emulator.  A file from before gives its values to the
machine it was last used with, and no file, however corrupt, stops a start.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.profiles import load_profile
from app.settings import (
    JOG_STEP,
    MACHINE_SPECS,
    THEME,
    StationSettings,
    machine_scope,
    machine_spec,
)
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

LEFT = Qt.MouseButton.LeftButton


def ini(path: Path, content: bytes | None = None) -> QSettings:
    if content is not None:
        path.write_bytes(content)
    return QSettings(str(path), QSettings.Format.IniFormat)


class Windows:
    """Opens the operator's window on any profile, over one settings file, as launches do."""

    def __init__(self, qtbot: QtBot, path: Path) -> None:
        self.qtbot = qtbot
        self.path = path
        self.harnesses: list[StationHarness] = []
        self.settings = StationSettings(ini(path))

    def open(self, profile: str, *, connect: bool = False) -> tuple[MainWindow, StationHarness]:
        harness = StationHarness(load_profile(profile))
        self.harnesses.append(harness)
        window = MainWindow(harness.station, self.settings)
        self.qtbot.addWidget(window)
        window.show()
        if connect:
            harness.connect()
        return window, harness

    def close(self, window: MainWindow) -> None:
        window.save_settings()
        window.close()

    def finish(self) -> None:
        for harness in self.harnesses:
            harness.close()


@pytest.fixture
def windows(qtbot: QtBot, tmp_path: Path) -> Iterator[Windows]:
    opened = Windows(qtbot, tmp_path / "stepdeck.ini")
    yield opened
    opened.finish()


def test_the_arrow_keys_step_chosen_on_the_drill_stays_the_drills(windows: Windows) -> None:
    drill, _ = windows.open("pcb-drill")
    combo = drill.manual_panel.key_step
    combo.setCurrentIndex(combo.findData(1.0))
    assert combo.currentText() == "1 mm per tap"
    windows.close(drill)

    winder, _ = windows.open("string-art")
    assert winder.manual_panel.key_step.currentData() == 0.0  # not "1 deg per tap"
    assert winder.jog.key_step == 0.0
    winder.manual_panel.key_step.setCurrentIndex(winder.manual_panel.key_step.findData(10.0))
    assert winder.manual_panel.key_step.currentText() == "10 deg per tap"
    windows.close(winder)

    again, _ = windows.open("pcb-drill")
    assert again.manual_panel.key_step.currentText() == "1 mm per tap"
    assert again.jog.key_step == 1.0


def test_a_tap_on_the_drill_moves_the_step_kept_for_the_drill(windows: Windows) -> None:
    """Judged at the machine: the drill remembered 1 mm, the winder 10 degrees."""
    windows.settings.machine("string-art").jog_step = 10.0
    windows.settings.machine("pcb-drill").jog_step = 1.0
    window, harness = windows.open("pcb-drill", connect=True)
    window.activateWindow()
    windows.qtbot.waitUntil(window.isActiveWindow)
    emulator = harness.drill_emulator
    harness.run_until(lambda: emulator.homed and not emulator.busy, timeout=30)
    windows.qtbot.keyPress(window, Qt.Key.Key_Right)
    windows.qtbot.keyRelease(window, Qt.Key.Key_Right)
    harness.run_until(lambda: not harness.drill_session.busy and emulator.positions[0] > 0, 30)
    assert emulator.positions[0] == 20  # 1 mm at 19.8 microsteps a mm, in whole microsteps


def test_skipping_lines_is_the_machines_choice(windows: Windows, qtbot: QtBot) -> None:
    plotter, _ = windows.open("grbl-plotter")
    check = plotter.jobs_dock.skip_check
    plotter.jobs_dock.show()
    qtbot.waitUntil(check.isVisible)
    qtbot.mouseClick(check, LEFT)
    assert check.isChecked()
    windows.close(plotter)

    winder, _ = windows.open("string-art")
    assert not winder.jobs_dock.skip_check.isChecked()
    windows.close(winder)

    again, _ = windows.open("grbl-plotter")
    assert again.jobs_dock.skip_check.isChecked()


def test_the_link_page_shows_the_link_in_use_and_remembers_each_machines_own(
    windows: Windows,
) -> None:
    drill_link = windows.settings.machine("pcb-drill")
    drill_link.transport, drill_link.device, drill_link.baud = "serial", "/dev/ttyUSB9", 19200

    stage, harness = windows.open("xy-stage")
    panel = stage.connection_panel
    assert panel.transport == "emulator" and panel.selected_port() != "/dev/ttyUSB9"
    windows.close(stage)

    drill, harness = windows.open("pcb-drill")
    panel = drill.connection_panel
    # Not connected yet: the drill's own last link is offered.
    assert panel.transport == "serial" and panel.selected_port() == "/dev/ttyUSB9"
    assert panel.baud_combo.currentData() == 19200
    harness.connect()
    assert harness.station.model.link_state is LinkState.CONNECTED
    # Connected to the emulator: the page says so, and that is the drill's last link now.
    assert panel.transport == "emulator"
    assert drill_link.transport == "emulator"
    assert drill_link.device == "/dev/ttyUSB9"  # the port stays offered for Serial


def test_the_theme_stays_the_persons(windows: Windows) -> None:
    windows.settings.write(THEME, "dark")
    for profile in ("pcb-drill", "string-art"):
        window, _ = windows.open(profile)
        assert window.theme.choice == "dark"
        windows.close(window)


# --- a file from before, and corrupt ones ---------------------------------------------


def test_global_values_from_before_become_the_last_machines(tmp_path: Path) -> None:
    path = tmp_path / "stepdeck.ini"
    content = (
        b"[station]\nprofile=pcb-drill\n"
        b"[link]\ntransport=serial\ndevice=/dev/ttyUSB0\nbaud=19200\n"
        b"[jog]\nkey_step=1\n"
        b"[job_options]\nskip_unsupported=true\ndraw=true\n"
        b"[view]\ntheme=dark\n"
    )
    settings = StationSettings(ini(path, content))
    drill = settings.machine("pcb-drill")
    assert (drill.transport, drill.device, drill.baud) == ("serial", "/dev/ttyUSB0", 19200)
    assert drill.jog_step == 1.0
    assert settings.job_options("pcb-drill") == {"draw": True, "skip_unsupported": True}
    winder = settings.machine("string-art")
    assert (winder.transport, winder.device, winder.baud, winder.jog_step) == (
        "emulator",
        "",
        None,
        0.0,
    )
    assert settings.job_options("string-art") == {"draw": True}  # draw concerns the job
    assert settings.theme == "dark"
    assert settings.take_warnings() == []
    settings.sync()
    # Moved, not copied: the old keys are gone, and a second start moves nothing again.
    store = ini(path)
    assert not any(store.contains(spec.key) for spec in MACHINE_SPECS)
    assert store.contains(machine_spec(JOG_STEP, "pcb-drill").key)
    again = StationSettings(store)
    assert again.machine("pcb-drill").jog_step == 1.0


def test_a_machines_own_value_wins_over_an_old_global_one(tmp_path: Path) -> None:
    content = b"[station]\nprofile=usb3\n[jog]\nkey_step=10\n[machines]\nusb3\\jog\\key_step=0.1\n"
    settings = StationSettings(ini(tmp_path / "stepdeck.ini", content))
    assert settings.machine("usb3").jog_step == 0.1


@pytest.mark.qt_log_ignore("QVariant::load")  # Qt's own word on the malformed @Variant
@pytest.mark.parametrize(
    "content",
    [
        # Bad old global values: each warned about, none moved, the start goes on.
        b"[station]\nprofile=pcb-drill\n[link]\ntransport=carrier-pigeon\nbaud=-3\n"
        b"[jog]\nkey_step=banana\n[job_options]\nskip_unsupported=perhaps\n",
        # Bad per-machine values.
        b"[machines]\npcb-drill\\link\\transport=42\npcb-drill\\link\\baud=1e99\n"
        b"pcb-drill\\jog\\key_step=0.5\npcb-drill\\link\\device=@Variant(\\0\\0\\0\\x7f)\n"
        b"pcb-drill\\job_options\\skip_unsupported=1 2 3\n",
        # The group is a value; the profile is unknown; the file is garbage.
        b"[General]\nmachines=7\n[station]\nprofile=no-such-machine\n[jog]\nkey_step=1\n",
        b"\x00\x01\x02garbage[[[\n=\n[machines]\npcb-drill\\jog\\key_step=\xff\xfe\n",
    ],
)
def test_corrupt_settings_never_stop_a_start_and_give_defaults(
    content: bytes, tmp_path: Path, qtbot: QtBot
) -> None:
    settings = StationSettings(ini(tmp_path / "stepdeck.ini", content))
    drill = settings.machine("pcb-drill")
    assert drill.transport in ("emulator", "serial", "ble")
    assert drill.jog_step in (0.0, 0.1, 1.0, 10.0)
    assert drill.baud is None or 50 <= drill.baud <= 4_000_000
    assert isinstance(settings.job_options("pcb-drill"), dict)
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = MainWindow(harness.station, settings)
        qtbot.addWidget(window)
        window.show()
        harness.connect()
        assert window.manual_panel.key_step.currentData() in (0.0, 0.1, 1.0, 10.0)
        assert window.connection_panel.transport == "emulator"  # what is connected
        window.save_settings()
    finally:
        harness.close()


def test_a_profile_name_from_any_file_stays_inside_its_group() -> None:
    # stays inside: a settings key, never a path; it must not leave its group either
    for name in ("../../etc", "a/b\\c", "", "ž" * 200, "x y=z"):  # stays inside: a key
        scope = machine_scope(name)
        assert scope and len(scope) <= 64
        assert all(c.isascii() and (c.isalnum() or c in "_-") for c in scope)
    settings = StationSettings(None)
    settings.machine("a/b").jog_step = 1.0
    assert settings.machine("a/b").jog_step == 1.0
    assert settings.machine("a").jog_step == 0.0
