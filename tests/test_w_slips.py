"""Small slips a newcomer noticed (issue 32), each held where a test can see it."""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

#: Two bits, so two prompts, and a park at the end that the drill reports after the holes.
BOARD = "M48\nMETRIC\nT1C0.8\nT2C1.0\n%\nT1\nX10.0Y10.0\nX40.0Y10.0\nT2\nX40.0Y30.0\nM30\n"


def test_a_finished_drill_job_has_no_time_left(qtbot: QtBot, tmp_path: Path) -> None:
    """It said "left 00:04" after "done": the park came after the last hole's report."""
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        window.show()
        dock = window.jobs_dock
        harness.connect()
        job = tmp_path / "board.drl"
        job.write_text(BOARD, encoding="utf-8")
        assert dock.open_path(job)
        dock.run_button.click()
        prompts = 0
        while dock.runner.state is not JobState.DONE:
            harness.run_until(
                lambda: dock.runner.state in (JobState.DONE, JobState.WAITING), timeout=120
            )
            if dock.runner.state is JobState.WAITING:
                prompts += 1
                assert dock.eta_label.text() != "left 00:00"  # the holes are still to come
                dock.continue_button.click()
        assert prompts == 2
        harness.run(2.0)
        assert dock.runner.remaining_s == 0.0
        assert dock.eta_label.text() == "left 00:00"
    finally:
        harness.close()
