"""End to end: a photo → a generated sequence → the job files → the emulated winder winds it.

The command line makes the pair from a picture (as an operator's SD card
would get it), the dock's loader reads it back, the runner checks it
against the winder (travel, axes) and runs it on the emulator; the
emulator's log is the judge, read by the helpers of the sample end-to-end
test: every nail drilled once in index order, then the wraps of the needle
in exactly the generated order.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from pytestqt.qtbot import QtBot

from app.__main__ import main
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.loaders import load_job
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.e2e.test_e2e_string_art import (
    DRILL_TIMEOUT_S,
    WIND_TIMEOUT_S,
    Board,
    drilled,
    first_gap,
    moves,
    track,
    wound,
)
from tests.helpers.harness import StationHarness
from tests.helpers.string_art_images import logo


@pytest.fixture
def winder(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("string-art"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    yield harness
    harness.close()


def test_a_photo_becomes_a_job_the_winder_drills_and_winds_in_the_generated_order(
    winder: StationHarness, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    photo = tmp_path / "logo.png"
    Image.fromarray(np.round(logo(120) * 255).astype(np.uint8)).save(photo)
    out = tmp_path / "job"
    argv = ["string-art", str(photo), "--board", "0,16,8", "--lines", "12", "--out", str(out)]
    assert main([*argv, "--resolution", "64", "--png-size", "64"]) == 0
    capsys.readouterr()

    program = load_job(out / "poradi.txt", [axis.name for axis in winder.station.profile.axes])
    assert isinstance(program, StringArtProgram)
    job = program.job
    assert len(job.sequence) == 13
    runner = JobRunner(winder.station, tmp_path / "checkpoints")
    try:
        assert runner.load(program) == []  # the winder's checks: axes, travel
        runner.start()
        winder.run_until(lambda: runner.state is not JobState.RUNNING, timeout=DRILL_TIMEOUT_S)
        assert runner.state is JobState.WAITING
        board = Board.of(job)
        drill_log = moves(winder)
        assert drilled(drill_log, board) == list(range(16))
        confirmed_at = len(winder.gcode_emulator.event_log)
        runner.confirm()
        winder.run_until(
            lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED),
            timeout=WIND_TIMEOUT_S,
        )
        assert runner.state is JobState.DONE
        places = [drill_log[-1]["pos"], *track(winder, confirmed_at)]
        first = job.sequence[0]
        assert first_gap(places, board) == (first, (first + 1) % 16)
        assert wound(places, board) == list(job.sequence[1:])
    finally:
        runner.deleteLater()
