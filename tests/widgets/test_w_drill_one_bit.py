"""A profile's "one bit for all holes" run from the jobs dock (FIDELITY S2-40), by clicks.

The original drilled every hole with its one 0.8 mm bit ("nepocita s vymenou
vrtaku"); the station asks for each diameter unless the profile says
``[drill] one_bit = true``.  Against the emulated drill on a manual clock.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.program import OpKind
from app.jobs.run.runner import JobRunner
from app.jobs.run.states import JobState
from app.profiles import MACHINES_DIR, load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock


def test_s2_40_one_bit_for_all_holes_runs_to_the_holes_without_asking_for_a_bit(
    qtbot: QtBot, tmp_path: Path, data_dir: Path
) -> None:
    shipped = (MACHINES_DIR / "pcb-drill.toml").read_text(encoding="utf-8")
    profile_path = tmp_path / "one-bit-drill.toml"
    profile_path.write_text(shipped + "\n[drill]\none_bit = true\n", encoding="utf-8")
    drill = StationHarness(load_profile(profile_path))
    try:
        runner = JobRunner(drill.station, tmp_path / "checkpoints")
        dock = JobsDock(drill.station, runner, confirm=lambda _text: True, throttle_ms=0)
        qtbot.addWidget(dock)
        dock.show()
        drill.connect()
        drill.run(0.5)
        assert dock.open_path(data_dir / "samples/pcb-driver/driver")
        program = runner.program
        assert program is not None
        assert not any(op.kind is OpKind.WAIT for op in program)
        states: list[JobState] = []
        runner.stateChanged.connect(states.append)
        qtbot.mouseClick(dock.run_button, Qt.MouseButton.LeftButton)
        emulator = drill.drill_emulator
        drill.run_until(lambda: len(emulator.drill_log) >= 3, timeout=120)
        assert JobState.WAITING not in states  # no bit prompt on the way to the holes
        assert not dock.prompt.isVisible()
        runner.abort()
    finally:
        drill.close()
