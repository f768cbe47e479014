"""The menus a sender's user looks for: File, Machine, View, Help.

Each entry is triggered as the operator would and the outcome read from the
window, the machine or the settings file — never from the action itself.
"""

from __future__ import annotations

import tomllib
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QFileDialog
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

ROOT = Path(__file__).resolve().parents[2]


def _window(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, settings: QSettings | None = None
) -> MainWindow:
    window = MainWindow(harness.station, settings, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    return window


def _ini(tmp_path: Path) -> QSettings:
    return QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)


def _job(tmp_path: Path, name: str) -> Path:
    path = tmp_path / name
    path.write_text("5, 5\n10, 5\n", encoding="utf-8")
    return path


@pytest.fixture
def gcode_harness(qapp: object) -> Iterator[StationHarness]:
    h = StationHarness(load_profile("grbl-plotter"))
    yield h
    h.close()


def test_the_menu_bar_reads_file_machine_view_help(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    titles = [a.text().replace("&", "") for a in window.menuBar().actions()]
    assert titles == ["File", "Machine", "View", "Help"]


def test_open_job_loads_it_and_recent_jobs_lists_it_across_launches(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    first, second = _job(tmp_path, "first.csv"), _job(tmp_path, "second.csv")
    window = _window(qtbot, harness, tmp_path, _ini(tmp_path))
    chosen = iter([str(first), str(second)])
    monkeypatch.setattr(
        QFileDialog, "getOpenFileName", staticmethod(lambda *_a, **_k: (next(chosen), ""))
    )
    runner = window.jobs_dock.runner
    for path in (first, second):
        window.open_action.trigger()
        qtbot.waitUntil(lambda p=path: runner.program is not None and runner.program.source == p)
    assert window.jobs_dock.isVisible()
    window.close()
    qtbot.waitUntil(lambda: not window.isVisible())

    again = _window(qtbot, harness, tmp_path, _ini(tmp_path))
    again.recent_menu.aboutToShow.emit()
    entries = [a for a in again.recent_menu.actions() if a.data()]
    assert [a.data() for a in entries] == [str(second), str(first)]  # newest first
    entries[1].trigger()
    runner = again.jobs_dock.runner
    qtbot.waitUntil(lambda: runner.program is not None and runner.program.source == first)


def test_a_recent_job_that_is_gone_is_reported_not_opened(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    assert not window.open_recent(tmp_path / "gone.csv")
    assert "gone.csv: not opened" in window.jobs_dock.messages.toPlainText()
    assert window.jobs_dock.runner.program is None


def test_machine_menu_connects_homes_stops_and_disconnects(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    model = harness.station.model
    assert window.connect_action.isEnabled() and not window.disconnect_action.isEnabled()
    home_x = window.home_actions[0][0]
    assert home_x.text() == "Home X" and not home_x.isEnabled()  # motion is locked
    window.connect_action.trigger()
    session = harness.station.session
    assert session is not None
    harness.run_until(lambda: session.device_answered, timeout=5)
    harness.run(1.5)
    assert model.link_state is LinkState.CONNECTED
    assert window.disconnect_action.isEnabled() and not window.connect_action.isEnabled()
    assert home_x.isEnabled()
    harness.session.move_absolute(0, 3.0)  # away from the switch, so homing takes a while
    harness.run_until(lambda: window.info_panel.statuses[0].text() == "target reached", 3)
    home_x.trigger()
    harness.run_until(lambda: window.info_panel.statuses[0].text() == "homing", timeout=1)
    window.stop_action.trigger()
    harness.run_until(lambda: not model.any_moving, timeout=2)
    window.disconnect_action.trigger()
    harness.run_until(lambda: model.link_state is LinkState.DISCONNECTED, timeout=5)
    assert window.connect_action.isEnabled()


def test_a_gcode_machine_has_one_home_for_every_axis(
    qtbot: QtBot, gcode_harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, gcode_harness, tmp_path)
    assert [a.text() for a, _ in window.home_actions] == ["Home"]


def test_about_names_the_installed_version(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
    window = _window(qtbot, harness, tmp_path)
    window.about_action.trigger()
    box = window.show_about()
    assert box.isVisible()
    assert f"StepDeck {declared}" in box.text()


def test_quit_closes_the_window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> None:
    window = _window(qtbot, harness, tmp_path)
    window.quit_action.trigger()
    qtbot.waitUntil(lambda: not window.isVisible())


def test_a_machine_that_homes_every_axis_at_once_has_one_home_all_button(
    qtbot: QtBot, gcode_harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, gcode_harness, tmp_path)
    buttons = window.manual_panel.home_buttons
    assert [b.text() for b in buttons] == ["Home all"]
    gcode_harness.connect()
    gcode_harness.run(1.0)
    assert buttons[0].isEnabled()
    sent_before = len(gcode_harness.written)
    qtbot.mouseClick(buttons[0], Qt.MouseButton.LeftButton)
    gcode_harness.run(0.2)
    sent = b"".join(gcode_harness.written[sent_before:])
    assert b"$H" in sent or b"G28" in sent
