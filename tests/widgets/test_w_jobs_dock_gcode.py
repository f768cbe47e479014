"""Jobs dock on the G-code machines: options, the board question, exports, background reading."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams, read_string_art
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock

LEFT = Qt.MouseButton.LeftButton


def make_dock(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, asked: list[NeedsNailCount] | None = None
) -> JobsDock:
    runner = JobRunner(harness.station, tmp_path / "checkpoints")

    def board(needs: NeedsNailCount) -> StringArtParams | None:
        if asked is not None:
            asked.append(needs)
        return StringArtParams(0, 160, 20.0)

    dock = JobsDock(
        harness.station, runner, confirm=lambda _t: False, throttle_ms=0, ask_board=board
    )
    qtbot.addWidget(dock)
    dock.resize(820, 640)
    dock.show()
    return dock


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    harness.run(0.3)
    yield harness
    harness.close()


@pytest.fixture
def winder(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("string-art"))
    harness.connect()
    harness.run(0.3)
    yield harness
    harness.close()


def messages(dock: JobsDock) -> str:
    return dock.messages.toPlainText()


def test_gcode_options_show_on_a_gcode_machine_only(
    qtbot: QtBot, plotter: StationHarness, harness: StationHarness, tmp_path: Path
) -> None:
    dock = make_dock(qtbot, plotter, tmp_path)
    assert dock.translate_pen_check.isVisible() and dock.skip_check.isVisible()
    penless = StationHarness(load_profile("string-art"))
    try:
        winder = make_dock(qtbot, penless, tmp_path / "winder")
        assert not winder.translate_pen_check.isVisible() and winder.skip_check.isVisible()
    finally:
        penless.close()
    stage = make_dock(qtbot, harness, tmp_path / "stage")
    assert not stage.translate_pen_check.isVisible()


def test_a_file_the_plotter_cannot_run_is_refused_line_by_line_until_skipping_is_chosen(
    qtbot: QtBot, plotter: StationHarness, data_dir: Path, tmp_path: Path
) -> None:
    bunny = data_dir / "realdata/gcode/CNC-Drawinger_unicorn_BUNNY.gcode"
    dock = make_dock(qtbot, plotter, tmp_path)
    assert not dock.open_path(bunny)
    text = messages(dock)
    assert "refused" in text and "M18" in text
    first_m18 = next(
        n
        for n, line in enumerate(bunny.read_text().splitlines(), start=1)
        if line.startswith("M18")
    )
    assert f"{bunny.name}:{first_m18}" in text  # the line, as the operator finds it
    # Refused, but still shown: the drawing is previewed while Run stays off.
    assert dock.runner.program is None and not dock.run_button.isEnabled()
    assert dock.preview.program is not None and "preview only" in dock.file_label.text()
    assert dock.preview.path_geometry is not None and len(dock.preview.path_geometry.work.x)
    qtbot.mouseClick(dock.skip_check, LEFT)  # re-reads the file with the new choice
    qtbot.waitUntil(lambda: dock.runner.program is not None)  # on the worker thread
    assert dock.runner.state is JobState.READY
    assert "M18" in messages(dock).split("operations loaded")[-1]  # listed as left out


def test_a_bare_nail_list_asks_for_the_board_once_and_loads(
    qtbot: QtBot, winder: StationHarness, data_dir: Path, tmp_path: Path
) -> None:
    asked: list[NeedsNailCount] = []
    dock = make_dock(qtbot, winder, tmp_path, asked)
    path = data_dir / "realdata/stringart/threadArt_cat-sequence_160pins.txt"
    assert dock.open_path(path)
    assert len(asked) == 1 and asked[0].min_nails <= 160
    program = dock.runner.program
    assert program is not None
    # The totals once, with the time this machine needs for them.
    totals = [line for line in messages(dock).splitlines() if "160 nails" in line]
    assert len(totals) == 1 and "connections" in totals[0] and "about" in totals[0], totals
    dock.open_path(path)  # re-reading the same file keeps the board given
    assert len(asked) == 1


def test_exports_write_the_sd_files_and_the_gcode(
    qtbot: QtBot, winder: StationHarness, data_dir: Path, tmp_path: Path
) -> None:
    dock = make_dock(qtbot, winder, tmp_path)
    sample = data_dir / "samples/string-art-hexagon/poradi.txt"
    assert dock.open_path(sample)
    assert dock.export_button.isEnabled()
    out = tmp_path / "sd"
    assert dock.exports.export_sd(out)
    assert read_string_art(out / "poradi.txt") == read_string_art(sample)
    gcode = tmp_path / "hexagon.gcode"
    assert dock.exports.export_gcode(gcode)
    lines = gcode.read_text().splitlines()
    assert sum(1 for line in lines if line.startswith("M0")) == 1
    assert all(len(line) < 80 for line in lines)


def test_a_large_file_is_read_in_the_background_and_the_window_keeps_working(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    path = tmp_path / "big.gcode"
    with path.open("w") as out:
        out.write("M4\n")
        for i in range(150_000):
            out.write(f"G1 X{(i % 200) * 0.5:.3f} Y{(i // 200) % 150:.3f} F3000\n")
        out.write("M3\n")
    dock = make_dock(qtbot, plotter, tmp_path)
    assert dock.open_path(path, background=True)
    assert "reading" in dock.file_label.text()
    assert not dock.open_button.isEnabled()
    ticks = [0]

    def tick() -> None:
        ticks[0] += 1

    from PySide6.QtCore import QTimer

    timer = QTimer()
    timer.timeout.connect(tick)
    timer.start(10)
    qtbot.waitUntil(lambda: dock.runner.program is not None, timeout=60_000)
    timer.stop()
    assert ticks[0] > 3  # the event loop ran while the file was read
    assert len(dock.runner.program) == 150_002
    assert dock.open_button.isEnabled()


def test_an_option_changed_while_the_file_is_read_is_taken_when_the_reading_ends(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    path = tmp_path / "bunny-like.gcode"
    path.write_text("M4\nG1 X10 Y10 F3000\nM18\nM3\n")  # M18: not the CoreXY plotter's
    dock = make_dock(qtbot, plotter, tmp_path)
    assert dock.open_path(path, background=True)
    qtbot.mouseClick(dock.skip_check, LEFT)  # while the first reading is under way
    qtbot.waitUntil(lambda: dock.runner.program is not None)  # read again, M18 skipped
    assert dock.options.skip_unsupported and "still reading" not in messages(dock)


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(0.3)
    yield harness
    harness.close()


def test_progress_counts_what_the_machine_ran_and_says_what_was_sent_ahead(
    qtbot: QtBot, grbl: StationHarness, tmp_path: Path
) -> None:
    # Nine long edges: GRBL answers lines far ahead of drawing them (the CoreXY plotter's
    # own firmware answers a move only once it is done).
    plotter = grbl
    lines = ["G21", "G90"] + [f"G1 X{40 * (k % 2) + 5} Y{5 * k + 5} F600" for k in range(9)]
    job = tmp_path / "edges.gcode"
    job.write_text("\n".join(lines) + "\n", encoding="utf-8")
    dock = make_dock(qtbot, plotter, tmp_path)
    assert dock.open_path(job)
    runner = dock.runner
    total = len(runner.program or [])
    qtbot.mouseClick(dock.run_button, LEFT)
    plotter.run_until(lambda: runner.done > runner.progress.executed, timeout=10)
    # Everything sent, the machine still on its way: not shown as done.
    plotter.run_until(lambda: runner.done == total, timeout=10)
    assert runner.progress.executed < total and runner.state is not JobState.DONE
    assert dock.progress.value() == runner.progress.executed < dock.progress.maximum()
    assert dock.count_label.text() == f"{runner.progress.executed} / {total} ops · {total} sent"
    assert dock.preview.done == runner.progress.executed  # green only what was drawn
    plotter.run_until(lambda: runner.state is JobState.DONE, timeout=120)
    assert plotter.gcode_session.settled
    assert dock.count_label.text() == f"{total} / {total} ops"
    assert dock.progress.value() == dock.progress.maximum()


def test_an_abort_reports_one_count_the_one_the_resume_offer_holds(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    lines = [f"G1 X{40 * (k % 2) + 5} Y{5 * k + 5} F600" for k in range(9)]
    job = tmp_path / "edges.gcode"
    job.write_text("G21\nG90\n" + "\n".join(lines) + "\n", encoding="utf-8")
    dock = make_dock(qtbot, plotter, tmp_path)
    assert dock.open_path(job)
    runner = dock.runner
    qtbot.mouseClick(dock.run_button, LEFT)
    plotter.run_until(lambda: runner.done > runner.progress.executed >= 3, timeout=60)
    qtbot.mouseClick(dock.abort_button, LEFT)
    plotter.run(1.0)
    executed = runner.progress.executed
    assert f"Job aborted after {executed} of" in messages(dock)
    assert runner.resume_available == executed
    assert f"completed {executed} of" in dock.resume_offer_label.text()
    assert dock.count_label.text().startswith(f"{executed} / ")
