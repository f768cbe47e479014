"""The drill's conversion constants edited for teaching (FIDELITY S2-42), driven by clicks.

The original let a teacher change "Krok excelon" and "Mikrokroky X 19,8 / Y
19,7 na mm" to show what these constants do.  Against the emulated drill on a
manual clock, over a settings file: a loaded job follows the edited
constants (its preview, its microstep targets, the step-through), the
machine keeps them per profile, "Profile values" goes back, and a job under
way cannot have them changed under it.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QPushButton
from pytestqt.qtbot import QtBot

from app.jobs.program import OpKind, Program
from app.profiles import load_profile
from app.settings import StationSettings
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.number_field import NumberField

DRIVER = "samples/pcb-driver/driver"


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    yield harness
    harness.close()


@pytest.fixture
def settings(tmp_path: Path) -> StationSettings:
    return StationSettings(QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat))


def opened(qtbot: QtBot, drill: StationHarness, settings: StationSettings) -> MainWindow:
    window = MainWindow(drill.station, settings)
    qtbot.addWidget(window)
    window.show()
    qtbot.waitExposed(window)
    page = next(b for b in window.menu_panel.findChildren(QPushButton) if b.text() == "D&rill")
    click(qtbot, page)
    click(qtbot, window.drill_panel.conversion_toggle)
    assert window.drill_panel.conversion_box.isVisible()
    return window


def click(qtbot: QtBot, button: QPushButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def type_value(qtbot: QtBot, field: NumberField, text: str) -> None:
    qtbot.mouseClick(field, Qt.MouseButton.LeftButton)
    field.selectAll()
    qtbot.keyClicks(field, text)


def holes(program: Program | None) -> list[float]:
    """Where each hole is drilled, x then y, in the program's (the machine's) millimetres."""
    assert program is not None
    found: list[float] = []
    x = y = 0.0
    for op in program:
        if op.kind is OpKind.MOVE:
            x, y = op.target.get("X", x), op.target.get("Y", y)
        elif op.kind is OpKind.DRILL:
            found += [x, y]
    return found


def reloaded(qtbot: QtBot, window: MainWindow, before: Program | None) -> Program:
    qtbot.waitUntil(lambda: window.job_runner.program not in (None, before), timeout=20_000)
    program = window.job_runner.program
    assert program is not None
    return program


def test_s2_42_edited_microsteps_a_mm_move_the_loaded_job_and_its_microstep_targets(
    qtbot: QtBot, drill: StationHarness, settings: StationSettings, data_dir: Path
) -> None:
    window = opened(qtbot, drill, settings)
    box = window.drill_panel.conversion_box
    assert box.warning.isVisible() and "Teaching only" in box.warning.text()
    assert window.jobs_dock.open_path(data_dir / DRIVER)
    before = window.job_runner.program
    original = holes(before)
    # The step-through stands at the first hole: X's microsteps as the profile has them.
    step = window.drill_panel.step_box
    click(qtbot, window.drill_panel.step_toggle)
    while step.walk.current is None or step.walk.current.position is None:
        click(qtbot, step.next_button)
    first_x_mm = step.walk.current.position[0]
    assert step.procedure_buttons[0].text() == f"X{round(first_x_mm * 19.8)}"

    type_value(qtbot, box.per_mm_fields[0], "39.6")  # twice the profile's 19.8
    click(qtbot, box.apply_button)
    program = reloaded(qtbot, window, before)
    assert window.station.drill_conversion.microsteps_per_mm[0] == pytest.approx(39.6)
    # Every hole lands twice as far along X (the preview draws it so), Y unchanged.
    stretched = [v * (2 if i % 2 == 0 else 1) for i, v in enumerate(original)]
    assert holes(program) == pytest.approx(stretched)
    assert window.jobs_dock.preview.program is program
    assert any("microsteps a mm changed" in note for note in program.notes)
    # The same line is still shown: the job's millimetres, now twice the microsteps.
    assert step.walk.current is not None and step.walk.current.position is not None
    assert step.walk.current.position[0] == pytest.approx(2 * first_x_mm)
    assert step.procedure_buttons[0].text() == f"X{round(first_x_mm * 39.6)}"
    assert f"X {first_x_mm:.3f} mm = {round(first_x_mm * 39.6)} µsteps" in (step.coordinates.text())
    # Kept for this machine.
    key = "machines/pcb-drill/drill_conversion/microsteps_per_mm_X"
    assert float(settings.store.value(key)) == pytest.approx(39.6)

    # Profile values: back to 19.8, the job read again, the setting forgotten.
    click(qtbot, box.profile_button)
    program = reloaded(qtbot, window, program)
    assert holes(program) == pytest.approx(original)
    assert box.per_mm_fields[0].value() == pytest.approx(19.8)
    assert not settings.store.contains(key)


def test_s2_42_the_excellon_step_scales_the_files_coordinates(
    qtbot: QtBot, drill: StationHarness, settings: StationSettings, data_dir: Path
) -> None:
    window = opened(qtbot, drill, settings)
    box = window.drill_panel.conversion_box
    assert box.step_field.value() == 10000  # "Krok excelon": 1/10000 inch
    assert window.jobs_dock.open_path(data_dir / DRIVER)
    before = window.job_runner.program
    original = holes(before)
    type_value(qtbot, box.step_field, "20000")  # half a count: the board half as large
    click(qtbot, box.apply_button)
    program = reloaded(qtbot, window, before)
    assert holes(program) == pytest.approx([v / 2 for v in original])
    assert window.station.drill_conversion.excellon_step_inch == pytest.approx(5e-5)


def test_s2_42_the_constants_kept_for_the_drill_come_back_at_the_next_launch(
    qtbot: QtBot, settings: StationSettings
) -> None:
    first = StationHarness(load_profile("pcb-drill"))
    try:
        window = opened(qtbot, first, settings)
        type_value(qtbot, window.drill_panel.conversion_box.per_mm_fields[1], "20.5")
        click(qtbot, window.drill_panel.conversion_box.apply_button)
        window.close()
    finally:
        first.close()
    second = StationHarness(load_profile("pcb-drill"))
    try:
        window = opened(qtbot, second, settings)
        conversion = second.station.drill_conversion
        assert conversion.microsteps_per_mm == pytest.approx((19.8, 20.5))
        assert window.drill_panel.conversion_box.per_mm_fields[1].value() == pytest.approx(20.5)
    finally:
        second.close()


def test_s2_42_a_job_under_way_cannot_have_its_constants_changed(
    qtbot: QtBot, drill: StationHarness, settings: StationSettings, data_dir: Path
) -> None:
    window = opened(qtbot, drill, settings)
    drill.connect()
    drill.run(0.5)
    assert window.jobs_dock.open_path(data_dir / DRIVER)
    program = window.job_runner.program
    click(qtbot, window.jobs_dock.run_button)
    drill.run_until(lambda: drill.station.model.jog_lock_reason is not None)
    box = window.drill_panel.conversion_box
    type_value(qtbot, box.per_mm_fields[0], "30")
    click(qtbot, box.apply_button)
    assert drill.station.drill_conversion.microsteps_per_mm[0] == pytest.approx(19.8)
    assert "Not changed: a job is under way" in box.note.text()
    assert window.job_runner.program is program
    assert not settings.store.contains("machines/pcb-drill/drill_conversion/microsteps_per_mm_X")
    window.job_runner.abort()
