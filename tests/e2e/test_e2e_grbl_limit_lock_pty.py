"""End to end: a soft limit on the emulated GRBL plotter (its own process, a pty), a real-clock
station and the alarm band.

GRBL 1.1h answers nothing after ``ALARM:1``/``ALARM:2`` and ``[MSG:Reset to continue]`` until a 0x18
(protocol.c's critical-event loop; the emulator does the same, compared with grbl-sim in
``test_e2e_grbl_limit_alarm_vs_grbl_sim.py``).  The station must show that silence as the
alarm, not a lost link, for longer than it gives a silent board; the band's Unlock resets the
board first and ``$X`` goes after its banner; nothing moves.  Every wait is bounded, the
process is ended whatever happens.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.gcode import timing
from app.machines.gcode.limit_lock import waiting_text
from app.profiles import load_profile
from app.station import Station
from tests.e2e.test_e2e_gcode import connect, events
from tests.e2e.test_emulator_pty import Emulator, running_emulator
from widgets.panels.gcode import GcodePanel


@pytest.fixture
def board(tmp_path: Path) -> Iterator[tuple[Emulator, Path]]:
    log = tmp_path / "plotter.log"
    with running_emulator(
        "--pty", "--controls", "--log", str(log), profile="grbl-plotter"
    ) as emulator:
        yield emulator, log


@pytest.fixture
def station(qtbot: QtBot) -> Iterator[Station]:
    built = Station(load_profile("grbl-plotter"))
    try:
        yield built
    finally:
        built.shutdown()


def test_a_limit_is_waited_out_as_the_alarm_and_unlock_resets_first(
    qtbot: QtBot, board: tuple[Emulator, Path], station: Station
) -> None:
    (process, path), log = board
    connect(qtbot, station, path)
    panel = GcodePanel(station)
    qtbot.addWidget(panel)
    panel.show()
    band = panel.alarm_band
    session = station.gcode_session
    assert session is not None
    states: list[LinkState] = []
    station.model.linkStateChanged.connect(states.append)
    assert process.stdin is not None
    process.stdin.write(b"alarm 2\n")  # a soft limit: position kept, Unlock offered
    process.stdin.flush()
    qtbot.waitUntil(band.reset_button.isVisible, timeout=5000)
    assert band.title.text() == "ALARM:2" and "Ctrl-X" in band.action.text()
    assert band.unlock_button.isVisible()
    locked_at = session.clock.now()
    # Longer than a silent board is given before it is called lost: still the alarm.
    qtbot.waitUntil(
        lambda: session.clock.now() - locked_at > 1.5 * timing.SILENCE_S,
        timeout=int(4 * timing.SILENCE_S * 1000),
    )
    assert LinkState.LOST not in states, states
    assert station.model.link_state is LinkState.CONNECTED
    assert station.model.link_detail == waiting_text()
    moves = sum(e["event"] == "move" for e in events(log))
    qtbot.mouseClick(band.unlock_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not band.isVisible(), timeout=5000)  # out of alarm: Idle reported
    assert session.machine_state == "Idle" and not session.limit_lock.waiting
    read = [e.get("text", "reset") for e in events(log) if e["event"] in ("line", "reset")]
    assert read[-2:] == ["reset", "$X"]  # the reset first, $X after its banner
    assert sum(e["event"] == "move" for e in events(log)) == moves  # nothing moved
    assert LinkState.LOST not in states, states
    assert station.model.link_detail == station.link.describe()
