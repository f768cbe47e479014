"""The station and the stage's power: switched on where it was left, killed mid-job.

FIDELITY S3-30 (the absolute encoder sets the position at power-on: the
station must read it, never assume 0) and S3-36 (a KillSwitch cut leaves the
stage silent: the link is lost, motion is locked, a job pauses).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.jobs.program import Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from protocol.clock import Clock
from protocol.emulator.stage_firmware import StageConfig, StageFirmware
from protocol.stage.codec import CommandId
from tests.helpers.harness import StationHarness

HERE = SourceRef("test.txt", 1)


@pytest.fixture
def placed(qapp: object) -> Iterator[StationHarness]:
    """A station whose emulated stage is switched on at X 12.345 mm, Y 30 mm."""
    harness = StationHarness()
    config = StageConfig(encoder_positions_um=(12_345.0, 30_000.0))

    def emulator(clock: Clock, _profile: object) -> StageFirmware:
        return StageFirmware(clock, config)

    station = harness.station
    station.dialect = dataclasses.replace(station.dialect, emulator=emulator)
    yield harness
    harness.close()


def test_s3_30_the_station_shows_the_position_the_stage_powers_on_at(
    placed: StationHarness,
) -> None:
    placed.connect()
    model = placed.station.model
    assert [axis.position for axis in model.axes] == pytest.approx([12.345, 30.0])
    # A relative move counts from there, not from 0.
    start = len(placed.emulator.command_log)
    assert placed.session.move_relative(0, 1.0)
    placed.run_until(lambda: not placed.emulator.axes[0].moving and model.axes[0].position > 13)
    placed.run(0.3)  # the echoes after the stop
    assert model.axes[0].position == pytest.approx(13.345)
    assert placed.emulator.axes[0].physical_um == pytest.approx(13_345)
    moves = [c for c in placed.emulator.command_log[start:] if c.command == CommandId.MOVE_REL]
    assert [c.data for c in moves] == [1000]


def test_s3_36_a_stage_killed_mid_job_is_lost_its_motion_locked_and_the_job_paused(
    placed: StationHarness, tmp_path: Path
) -> None:
    placed.connect()
    placed.run(1.0)  # the parameter reads at connect
    model = placed.station.model
    runner = JobRunner(placed.station, tmp_path / "checkpoints")
    try:
        prog = Program("killed", (move(HERE, X=40.0), move(HERE, X=5.0)))
        runner.load(prog)
        runner.start()
        placed.run_until(lambda: placed.emulator.axes[0].moving)
        placed.session.set_jog([0, 1])  # and the operator holds a jog
        placed.run(0.3)
        placed.emulator.kill_switch()
        stopped_at = placed.emulator.axes[0].physical_um
        placed.run_until(lambda: model.link_state is LinkState.LOST, timeout=3)
        assert runner.state is JobState.PAUSED and runner.current_index == 0
        assert model.motion_lock_reason() == "link lost"
        assert placed.session.jog_vector == (0, 0)
        assert not placed.session.move_absolute(0, 10.0)  # refused while lost
        assert placed.emulator.axes[0].physical_um == stopped_at  # nothing moved it
        # Switched on again: the station finds it where it stopped (S3-30), the job
        # waits for the operator's Resume.
        placed.emulator.press_button()
        placed.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=10)
        placed.run(0.5)
        assert model.axes[0].position == pytest.approx(stopped_at / 1000, abs=0.001)
        assert runner.state is JobState.PAUSED
        runner.resume()
        placed.run_until(lambda: runner.state is JobState.DONE, timeout=30)
        assert placed.emulator.axes[0].position_um == pytest.approx(5_000)
    finally:
        runner.deleteLater()
