"""The macros dock and editor, driven by clicks and keys as the operator drives them."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QApplication, QFileDialog
from pytestqt.qtbot import QtBot

from app.jobs.run.states import ACTIVE, JobState
from app.machine import LinkState
from app.macros.store import Macro, MacroStore
from app.macros.toml_file import export_macros
from app.profiles import load_profile
from app.settings import StationSettings
from tests.helpers.harness import StationHarness
from widgets.macros.dock import MacrosDock
from widgets.macros.editor import MacroEditor
from widgets.main_window import MainWindow


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    yield harness
    harness.close()


def ini(tmp_path: Path) -> QSettings:
    return QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)


def open_window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    window = MainWindow(harness.station, ini(tmp_path), checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    return window


def keep(tmp_path: Path, *macros: Macro) -> None:
    MacroStore(StationSettings(ini(tmp_path)), "grbl-plotter").save(list(macros))


def dock_of(window: MainWindow) -> MacrosDock:
    assert window.macros is not None
    return window.macros.dock


def connect(harness: StationHarness) -> None:
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)


def position(harness: StationHarness) -> tuple[float, float]:
    where = harness.gcode_emulator.position()
    return round(where["X"], 3), round(where["Y"], 3)


def test_a_click_runs_the_macro_and_ctrl_2_the_second(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Corner", "G90\nG0 X30 Y20"), Macro("Home", "G90\nG0 X0 Y0"))
    window = open_window(qtbot, grbl, tmp_path)
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_M, Qt.KeyboardModifier.ControlModifier)
    dock = dock_of(window)
    assert dock.isVisible()
    assert [b.text() for b in dock.buttons] == ["1  Corner", "2  Home"]
    assert not dock.buttons[0].isEnabled()  # not connected yet
    assert "not connected" in dock.lock_label.text()
    assert not dock.progress.isVisible()  # no empty bar before a macro has run
    connect(grbl)
    assert dock.buttons[0].isEnabled()
    qtbot.mouseClick(dock.buttons[0], Qt.MouseButton.LeftButton)
    assert dock.runner.state in ACTIVE and dock.progress.isVisible()
    assert not dock.buttons[1].isEnabled()  # one macro at a time
    assert dock.stop_button.isEnabled()
    grbl.run_until(lambda: dock.runner.state is JobState.DONE, timeout=60)
    assert position(grbl) == (30.0, 20.0)
    assert dock.progress.value() == dock.progress.maximum()
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_2, Qt.KeyboardModifier.ControlModifier)
    assert dock.runner.name == "Home"
    grbl.run_until(lambda: dock.runner.state is JobState.DONE, timeout=60)
    assert position(grbl) == (0.0, 0.0)
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_5, Qt.KeyboardModifier.ControlModifier)
    assert dock.message_label.text() == "No macro 5"


def test_an_out_of_travel_macro_is_refused_on_its_line_and_nothing_is_sent(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Park", "G90\nG0 X900 Y10"))
    window = open_window(qtbot, grbl, tmp_path)
    connect(grbl)
    dock = dock_of(window)
    dock.show()
    grbl.run(0.3)
    before = len(grbl.written)
    qtbot.mouseClick(dock.buttons[0], Qt.MouseButton.LeftButton)
    grbl.run(1.0)
    assert [w for w in grbl.written[before:] if w.strip() != b"?"] == []
    assert 'macro "Park":2: X 900 is outside the travel 0…300' in dock.message_label.text()


def test_esc_stops_a_running_macro(qtbot: QtBot, grbl: StationHarness, tmp_path: Path) -> None:
    keep(tmp_path, Macro("Far", "G0 X290 Y190"))
    window = open_window(qtbot, grbl, tmp_path)
    connect(grbl)
    dock = dock_of(window)
    dock.show()
    qtbot.mouseClick(dock.buttons[0], Qt.MouseButton.LeftButton)
    grbl.run_until(lambda: position(grbl)[0] > 10.0, timeout=30)
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    assert dock.runner.state is JobState.ABORTED
    grbl.run(3.0)
    stopped = position(grbl)
    grbl.run(2.0)
    assert position(grbl) == stopped and stopped[0] < 290.0
    assert "stopped" in dock.progress.format()


def test_the_editor_adds_orders_deletes_and_keeps_the_macros(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Park", "G0 X0 Y0"))
    window = open_window(qtbot, grbl, tmp_path)
    dock = dock_of(window)
    dock.show()
    qtbot.mouseClick(dock.edit_button, Qt.MouseButton.LeftButton)
    editor = dock.editor
    assert isinstance(editor, MacroEditor)
    qtbot.mouseClick(editor.add_button, Qt.MouseButton.LeftButton)
    editor.name_field.clear()
    qtbot.keyClicks(editor.name_field, "Pen test")
    editor.code_field.clear()
    qtbot.keyClicks(editor.code_field, "M3 S1000")
    qtbot.mouseClick(editor.up_button, Qt.MouseButton.LeftButton)
    assert [m.name for m in editor.macros] == ["Pen test", "Park"]
    qtbot.mouseClick(
        editor.buttons.button(editor.buttons.StandardButton.Ok), Qt.MouseButton.LeftButton
    )
    assert [b.text() for b in dock.buttons] == ["1  Pen test", "2  Park"]
    kept = MacroStore(StationSettings(ini(tmp_path)), "grbl-plotter").load()
    assert kept == [Macro("Pen test", "M3 S1000"), Macro("Park", "G0 X0 Y0")]
    qtbot.mouseClick(dock.edit_button, Qt.MouseButton.LeftButton)
    editor = dock.editor
    assert isinstance(editor, MacroEditor)
    editor.list.setCurrentRow(1)
    qtbot.mouseClick(editor.delete_button, Qt.MouseButton.LeftButton)
    qtbot.mouseClick(
        editor.buttons.button(editor.buttons.StandardButton.Ok), Qt.MouseButton.LeftButton
    )
    assert MacroStore(StationSettings(ini(tmp_path)), "grbl-plotter").load() == [
        Macro("Pen test", "M3 S1000")
    ]


def test_the_editor_keeps_nothing_invalid_and_says_why(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Park", "G0 X0 Y0"), Macro("Home", "G0 X0"))
    window = open_window(qtbot, grbl, tmp_path)
    dock = dock_of(window)
    qtbot.mouseClick(dock.edit_button, Qt.MouseButton.LeftButton)
    editor = dock.editor
    assert isinstance(editor, MacroEditor)
    editor.list.setCurrentRow(1)
    editor.name_field.clear()
    qtbot.keyClicks(editor.name_field, "park")  # the same name as the first
    qtbot.mouseClick(
        editor.buttons.button(editor.buttons.StandardButton.Ok), Qt.MouseButton.LeftButton
    )
    assert editor.isVisible()
    assert "two macros" in editor.error_label.text()
    qtbot.mouseClick(
        editor.buttons.button(editor.buttons.StandardButton.Cancel), Qt.MouseButton.LeftButton
    )
    assert [m.name for m in dock.macros] == ["Park", "Home"]


def test_import_and_export_through_their_buttons(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    keep(tmp_path, Macro("Park", "G0 X0 Y0"))
    window = open_window(qtbot, grbl, tmp_path)
    dock = dock_of(window)
    qtbot.mouseClick(dock.edit_button, Qt.MouseButton.LeftButton)
    editor = dock.editor
    assert isinstance(editor, MacroEditor)
    source = export_macros(tmp_path / "in.toml", [Macro("PARK", "G0 X5"), Macro("Z", "G0 Y1")], "x")
    hostile = tmp_path / "hostile.toml"
    hostile.write_text('format = 1\n[[macro]]\nname = "a\\u001b"\n')
    out = tmp_path / "out.toml"
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(hostile), ""))
    qtbot.mouseClick(editor.import_button, Qt.MouseButton.LeftButton)
    assert "hostile.toml: macro 1:" in editor.error_label.text()
    assert editor.macros == [Macro("Park", "G0 X0 Y0")]  # a bad file changes nothing
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(source), ""))
    qtbot.mouseClick(editor.import_button, Qt.MouseButton.LeftButton)
    assert editor.macros == [Macro("PARK", "G0 X5"), Macro("Z", "G0 Y1")]
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(out), ""))
    qtbot.mouseClick(editor.export_button, Qt.MouseButton.LeftButton)
    assert out.read_text() == (tmp_path / "in.toml").read_text().replace('"x"', '"grbl-plotter"')


def test_machines_without_gcode_text_show_no_macros(qtbot: QtBot, tmp_path: Path) -> None:
    harness = StationHarness(load_profile("usb3"))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path)
        qtbot.addWidget(window)
        assert window.macros is None
        assert "Macros" not in [a.text() for a in window.view_menu.actions()]
    finally:
        harness.close()


def test_a_macro_the_settings_file_spoilt_is_left_out_and_said(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Park", "G0 X0 Y0"), Macro("Home", "G0 X0"))
    store = ini(tmp_path)
    store.setValue("machines/grbl-plotter/macros/1/code", "G0 X0\x07")  # a bell in the G-code
    store.sync()
    window = open_window(qtbot, grbl, tmp_path)
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_M, Qt.KeyboardModifier.ControlModifier)
    dock = dock_of(window)
    assert [b.text() for b in dock.buttons] == ["1  Park"]
    assert "machines/grbl-plotter/macros/1/code" in dock.message_label.text()


def test_the_macros_dock_shown_at_close_is_back_at_the_next_start(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Park", "G0 X0 Y0"))
    first = open_window(qtbot, grbl, tmp_path)
    assert first.macros is not None and not first.macros.built
    first.macros.action.trigger()
    assert first.macros.dock.isVisible()
    first.close()
    second = MainWindow(grbl.station, ini(tmp_path), checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(second)
    assert second.macros is not None and not second.macros.built  # not before the first paint
    second.show()
    qtbot.waitUntil(lambda: not second.docks_restored.pending)
    assert second.macros.built and second.macros.dock.isVisible()
    assert second.macros.action.isChecked()
    assert [b.text() for b in second.macros.dock.buttons] == ["1  Park"]


def test_a_lost_link_pauses_the_macro_and_resume_finishes_it(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    keep(tmp_path, Macro("Walk", "G1 X20 F300\nG1 X40\nG1 X60"))
    window = open_window(qtbot, grbl, tmp_path)
    connect(grbl)
    dock = dock_of(window)
    dock.show()
    qtbot.mouseClick(dock.buttons[0], Qt.MouseButton.LeftButton)
    grbl.run_until(lambda: position(grbl)[0] > 5.0, timeout=30)
    assert not dock.resume_button.isEnabled()
    grbl.loopback.sever("cable pulled")
    grbl.run_until(lambda: dock.runner.state is JobState.PAUSED, timeout=5)
    assert dock.resume_button.isEnabled() and dock.stop_button.isEnabled()
    assert "paused" in dock.message_label.text()
    grbl.loopback.set_manipulator(None)
    grbl.run_until(lambda: grbl.station.model.link_state is LinkState.CONNECTED, timeout=30)
    qtbot.mouseClick(dock.resume_button, Qt.MouseButton.LeftButton)
    grbl.run_until(lambda: dock.runner.state not in ACTIVE, timeout=120)
    assert dock.runner.state is JobState.DONE, dock.message_label.text()
    assert position(grbl) == (60.0, 0.0)


def test_the_macros_dock_beside_a_running_job_keeps_the_window_in_1280_by_800(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    """Jobs, plots and macros shown at once, a job running: the window still fits the
    screen (under the jobs dock the macros made it 856 px tall), the macros a tab beside
    the plots, brought to the front by Ctrl+M."""
    window = open_window(qtbot, grbl, tmp_path)
    window.resize(1280, 800)
    window.jobs_dock.show()
    window.telemetry_dock.show()
    job = tmp_path / "square.gcode"
    job.write_text("G21 G90\nG1 X40 F3000\nG1 Y40\nG1 X0\nG1 Y0\n", encoding="utf-8")
    assert window.jobs_dock.open_path(job)
    connect(grbl)
    qtbot.mouseClick(window.jobs_dock.run_button, Qt.MouseButton.LeftButton)
    assert window.jobs_dock.runner.state in ACTIVE
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_M, Qt.KeyboardModifier.ControlModifier)
    dock = dock_of(window)
    QApplication.processEvents()
    assert dock.isVisible() and not dock.visibleRegion().isEmpty()  # in front of its tab
    assert dock in window.tabifiedDockWidgets(window.telemetry_dock)
    hint = window.minimumSizeHint()
    assert hint.width() <= 1280 and hint.height() <= 800, hint
    assert window.size().height() <= 800


def test_a_language_switch_mid_job_says_the_lock_again_in_the_language(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path, i18n_cache: Path
) -> None:
    """The job's lock reason was the text of its start: a switch to Czech left "a job is
    under way" in English on the Manual page and in the macros dock until the job ended."""
    from app import i18n

    keep(tmp_path, Macro("Park", "G90\nG0 X0 Y0"))
    window = open_window(qtbot, grbl, tmp_path)
    job = tmp_path / "square.gcode"
    job.write_text("G21 G90\nG1 X40 F600\nG1 Y40\nG1 X0\nG1 Y0\n", encoding="utf-8")
    assert window.jobs_dock.open_path(job)
    connect(grbl)
    qtbot.mouseClick(window.jobs_dock.run_button, Qt.MouseButton.LeftButton)
    dock = dock_of(window)
    dock.show()
    assert "a job is under way" in dock.lock_label.text()
    try:
        window.set_language("cs")
        QApplication.processEvents()
        assert dock_of(window).runner.runner.state is JobState.IDLE
        assert window.jobs_dock.runner.state in ACTIVE
        busy = QApplication.translate("JobRunner", "a job is under way — abort it or let it finish")
        assert busy != "a job is under way — abort it or let it finish"
        assert grbl.station.model.jog_lock_reason == busy
        assert busy in dock.lock_label.text()
        assert busy in window.manual_panel.jog_note.text()
    finally:
        i18n.install("en", i18n_cache)
