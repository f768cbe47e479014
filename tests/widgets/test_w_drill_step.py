"""VRTACKA's step-through on the Drill page (FIDELITY S2-41), driven by clicks.

The original's "Načti řádek" walked the Excellon file line by line, showed the
line, its coordinates and their microsteps, and the operator called the
drill's procedures by their letter buttons in any order.  Against the
emulated drill on a manual clock: what the page shows for each line of a real
file, what reaches the wire when the buttons are clicked (and what the drill
then did), what the motion gate refuses, and the preview's ring.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton
from pytestqt.qtbot import QtBot

from app.jobs.formats.excellon.reader import read_drill_file
from app.jobs.program import OpKind
from app.jobs.step_through import walk_stops
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.drill_step import DrillStepBox

DRIVER = "samples/pcb-driver/driver"


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    yield harness
    harness.close()


@pytest.fixture
def window(qtbot: QtBot, drill: StationHarness) -> MainWindow:
    built = MainWindow(drill.station)
    qtbot.addWidget(built)
    built.show()
    qtbot.waitExposed(built)
    drill.connect()
    drill.run(0.5)
    return built


def click(qtbot: QtBot, button: QPushButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def opened(qtbot: QtBot, window: MainWindow, path: Path) -> DrillStepBox:
    window.jobs_dock.open_path(path)
    page = next(b for b in window.menu_panel.findChildren(QPushButton) if b.text() == "D&rill")
    click(qtbot, page)
    box = window.drill_panel.step_box
    if not box.isVisible():
        assert box.walk.stops == ()  # folded away: nothing laid out at load
        click(qtbot, window.drill_panel.step_toggle)
    assert box.isVisible()
    return box


def procedures(box: DrillStepBox) -> list[str]:
    return [button.text() for button in box.procedure_buttons]


def test_s2_41_next_line_walks_a_real_excellon_file_showing_line_mm_microsteps_and_letters(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, data_dir: Path
) -> None:
    path = data_dir / DRIVER
    box = opened(qtbot, window, path)
    lines = path.read_text(encoding="utf-8").splitlines()
    program = window.job_runner.program
    assert program is not None  # the board fits the drill: the job was accepted
    assert box.procedure_buttons == [] and not box.previous_button.isEnabled()
    # Hole positions by file line as the file says them (1/10000 inch: the .dri's step).
    job = read_drill_file(path)
    holes = {h.source.line: (h.x_mm, h.y_mm) for h in job.holes}
    seen_lines: list[int] = []
    holes_shown = 0
    while box.next_button.isEnabled():
        click(qtbot, box.next_button)
        stop = box.walk.current
        assert stop is not None
        seen_lines.append(stop.line)
        assert box.line_text.text() == f"{stop.line}: {lines[stop.line - 1]}"
        if stop.line not in holes:
            assert box.coordinates.text() == "no coordinates on this line"
            assert procedures(box) == []
            continue
        holes_shown += 1
        x_mm, y_mm = holes[stop.line]
        assert stop.position == pytest.approx((x_mm, y_mm))
        x_steps = round(x_mm * 19.8 + 1e-9)
        y_steps = round(y_mm * 19.7 + 1e-9)
        assert box.coordinates.text() == (
            f"X {x_mm:.3f} mm = {x_steps} µsteps   Y {y_mm:.3f} mm = {y_steps} µsteps"
        )
        assert procedures(box) == [f"X{x_steps}", f"Y{y_steps}", "V"]
        # The preview rings this hole.
        marker = window.jobs_dock.preview.step_marker.getData()
        assert (float(marker[0][0]), float(marker[1][0])) == pytest.approx((x_mm, y_mm))
    # Every line of the file once, in order; every hole of the file shown.
    assert seen_lines == list(range(1, len(lines) + 1))
    assert holes_shown == len(job.holes) == sum(op.kind is OpKind.DRILL for op in program)
    # Previous walks back.
    click(qtbot, box.previous_button)
    assert box.walk.current is not None and box.walk.current.line == len(lines) - 1


def test_s2_41_the_operator_sends_the_letters_in_any_order_and_the_drill_does_them(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, data_dir: Path
) -> None:
    box = opened(qtbot, window, data_dir / DRIVER)
    while box.walk.current is None or box.walk.current.position is None:
        click(qtbot, box.next_button)
    x_text, y_text, v_text = procedures(box)
    session = drill.drill_session
    mark = len(drill.written)
    # Y first, then the drill, then X (the original: "nemusime dodrzovat poradi").
    click(qtbot, box.procedure_buttons[1])
    drill.run_until(lambda: not session.busy, timeout=60)
    click(qtbot, box.procedure_buttons[2])
    drill.run_until(lambda: not session.busy, timeout=60)
    click(qtbot, box.procedure_buttons[0])
    drill.run_until(lambda: not session.busy, timeout=60)
    assert drill.written[mark:] == [f"{y_text}\r".encode(), b"V\r", f"{x_text}\r".encode()]
    emulator = drill.drill_emulator
    # The hole went where the head stood then: Y at its target, X where it was (0).
    assert emulator.drill_log[-1].position == (0, int(y_text[1:]))
    assert emulator.positions[:2] == (int(x_text[1:]), int(y_text[1:]))
    assert v_text == "V"


def test_s2_41_a_line_outside_the_travel_is_refused_with_its_reason_and_nothing_sent(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, data_dir: Path
) -> None:
    """KiCad's file lies at negative Y: the job is refused, its lines walk, Y never leaves."""
    box = opened(qtbot, window, data_dir / "realdata/excellon/tracespace_kicad_mchck.drl")
    assert window.job_runner.program is None  # refused as a job; drawn, and walked
    while box.walk.current is None or box.walk.current.position is None:
        click(qtbot, box.next_button)
    assert box.walk.current is not None and box.walk.current.text == "X41.7Y-51.7"
    x_text, y_text, _v = procedures(box)
    assert y_text == f"Y{round(-51.7 * 19.7)}"
    mark = len(drill.written)
    click(qtbot, box.procedure_buttons[1])
    assert drill.written[mark:] == []
    # Judged as sent: the microsteps' own position (-1018 / 19.7 mm), not the file's.
    sent_mm = int(y_text[1:]) / 19.7
    assert box.note.text().startswith(f"{y_text} not sent: Motion refused: Y {sent_mm:.3f} mm")
    assert "outside the travel 0…150 mm" in box.note.text()
    click(qtbot, box.procedure_buttons[0])  # X 41.7 mm is inside: it goes
    assert drill.written[mark:] == [f"{x_text}\r".encode()]


def test_s2_41_nothing_is_sent_while_a_job_holds_the_machine(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, data_dir: Path
) -> None:
    box = opened(qtbot, window, data_dir / DRIVER)
    while box.walk.current is None or box.walk.current.position is None:
        click(qtbot, box.next_button)
    drill.station.model.set_jog_lock("a job is under way")
    mark = len(drill.written)
    click(qtbot, box.procedure_buttons[0])
    assert drill.written[mark:] == []
    assert "a job is under way" in box.note.text()


def test_s2_41_a_drawn_hole_is_one_stop_its_pen_letters_after_the_move(data_dir: Path) -> None:
    from app.jobs.loaders import JobOptions, load_job

    path = data_dir / DRIVER
    lines = path.read_text(encoding="utf-8").splitlines()
    drawn = load_job(path, ["X", "Y"], JobOptions(draw=True))
    stops = [s for s in walk_stops(drawn, lines) if s.position is not None]
    # Each bit's first hole: pen down there; its last: pen up; one stop per hole.
    assert sum(s.procedures == ("K",) for s in stops) == sum(
        op.kind is OpKind.PEN_DOWN for op in drawn
    )
    assert all(set(s.procedures) <= {"K", "Z"} for s in stops)
    assert len(stops) == len(read_drill_file(path).holes)


def test_s2_41_a_long_line_is_shown_clipped_and_whole_in_its_tooltip(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, tmp_path: Path
) -> None:
    comment = "; " + "a very long remark " * 20
    path = tmp_path / "long.drl"
    path.write_text(f"M48\n{comment}\nMETRIC\nT01C0.8\n%\nT01\nX10.0Y10.0\nM30\n", encoding="utf-8")
    box = opened(qtbot, window, path)
    click(qtbot, box.next_button)
    click(qtbot, box.next_button)
    assert box.walk.current is not None and box.walk.current.line == 2
    assert len(box.line_text.text()) <= 64 and box.line_text.text().endswith("…")
    assert box.line_text.toolTip() == f"2: {comment}"
