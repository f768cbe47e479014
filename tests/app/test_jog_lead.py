"""A held jog never leads the machine by more than its few steps, however late its reports.

Issue 31: under load a held jog on grbl-sim ended at X 13.248 instead of where the
test put it.  A board without ``Bf:`` in its reports (GRBL's default ``$10=1``)
had its jog steps timed on the station's clock; a board running below real time
(grbl-sim on a busy computer, or a board whose reports come late) then got step
after step into its planner, and a release whose cancel was not sent (the dead-man
firing while the last report, made before the board took the step, still said
Idle) left it to run them all out.  Here the emulated GRBL board runs at 30 % of
the station's clock, and what it did is read from the emulator itself.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.machines.gcode.session import JOG_BLOCKS_AHEAD, JOG_SPEED_SHARE, JOG_STEP_S
from app.machines.session import JOG_DEADMAN_S
from app.profiles import MachineProfile, load_profile
from protocol.clock import Clock
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.gcode_firmware import GcodeFirmware
from protocol.emulator.gcode_machine import grbl_plotter_config
from tests.helpers.harness import StationHarness

#: The board's time runs at this share of the station's.
SLOW = 0.3
PROFILE = load_profile("grbl-plotter")
#: One jog step of X: half its top speed for JOG_STEP_S.
STEP_MM = PROFILE.axes[0].max_speed * JOG_SPEED_SHARE * JOG_STEP_S


class SlowBoard(GcodeFirmware):
    """The emulated GRBL board with its whole control loop running at :data:`SLOW` speed."""

    def run_until(self, t: float) -> None:
        super().run_until(self._start + (t - self._start) * SLOW)


def _slow_board(clock: Clock, _profile: MachineProfile) -> EmulatedDevice:
    return SlowBoard(clock, grbl_plotter_config())


@pytest.fixture
def board(qtbot: QtBot) -> Iterator[StationHarness]:
    """A fresh GRBL board ($10=1: no Bf: in its reports), slower than the station's clock."""
    harness = StationHarness(PROFILE)
    station = harness.station
    station.dialect = dataclasses.replace(station.dialect, emulator=_slow_board)
    harness.connect()
    session = harness.gcode_session
    assert session.send_line("$10=1")
    harness.run_until(lambda: session.settled, timeout=10)
    harness.run(0.5)
    status = session.status
    assert status is not None and status.planner_free is None
    yield harness
    harness.close()


def _x(board: StationHarness) -> float:
    return board.gcode_emulator.position()["X"]


def _sent_to(board: StationHarness) -> float:
    """Where the jog steps sent so far take X (each ``$J=G91 … X<delta> …``)."""
    total = 0.0
    for line in board.written:
        if line.startswith(b"$J="):
            word = next(w for w in line.split() if w.startswith(b"X"))
            total += float(word[1:])
    return total


def test_a_held_jog_leads_a_slow_board_by_its_steps_not_by_the_station_clock(
    board: StationHarness,
) -> None:
    session = board.gcode_session
    session.set_jog((1, 0))
    worst = 0.0
    for _ in range(40):  # 2 s held, the key repeating every 0.1 s
        board.hold(0.05)
        # The steps are relative: where they lead is the sum of those sent.
        worst = max(worst, _sent_to(board) - _x(board))
    assert _x(board) > 2 * STEP_MM  # it did jog
    # Never more than the steps allowed ahead, whatever the station's clock says.
    assert worst <= (JOG_BLOCKS_AHEAD + 1) * STEP_MM + 1e-6
    released_at = _x(board)
    session.set_jog((0, 0))
    board.run_until(lambda: session.settled and session.machine_state == "Idle", timeout=30)
    assert _x(board) <= released_at + JOG_BLOCKS_AHEAD * STEP_MM + 1e-6


def test_a_jog_whose_key_release_never_comes_stops_within_its_lead(
    board: StationHarness,
) -> None:
    """The dead-man ends the jog; the board is told at once, whatever its last report said."""
    session = board.gcode_session
    ended: list[str] = []
    session.jogEnded.connect(ended.append)
    session.set_jog((1, 0))  # and no key repeat ever comes
    board.run_until(lambda: bool(ended), timeout=JOG_DEADMAN_S + 1)
    at_deadman = _x(board)
    board.run_until(lambda: session.settled and session.machine_state == "Idle", timeout=30)
    assert _x(board) <= at_deadman + JOG_BLOCKS_AHEAD * STEP_MM + 1e-6
    # And it stays there: nothing more is sent, nothing more runs.
    sent = len(board.written)
    standing = _x(board)
    board.run(3.0)
    assert _x(board) == standing
    assert all(w == b"?" for w in board.written[sent:])
