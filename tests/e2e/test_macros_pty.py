"""Macros from a script, against the emulated GRBL plotter in its own process on a pty.

The emulator's ``--log`` is the judge of what reached the machine: every line
it received, every move it finished.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings

import stepdeck
from app.macros.store import Macro, MacroStore
from app.settings import StationSettings
from tests.helpers.emulator_process import emulator_on_pty

#: Real seconds the emulator's log may take to show what the board did.
LOG_BOUND_S = 10.0


def events(log: Path) -> list[dict[str, object]]:
    if not log.exists():
        return []
    return [json.loads(line) for line in log.read_text().splitlines() if line.strip()]


def received(log: Path) -> list[str]:
    return [str(e["text"]) for e in events(log) if e["event"] == "line"]


def test_a_kept_macro_runs_and_an_out_of_travel_one_never_reaches_the_board(
    qapp: object, tmp_path: Path
) -> None:
    log = tmp_path / "grbl.log"
    settings = tmp_path / "stepdeck.ini"
    store = MacroStore(
        StationSettings(QSettings(str(settings), QSettings.Format.IniFormat)), "grbl-plotter"
    )
    store.save([Macro("Corner", "G90\nG0 X12 Y7"), Macro("Park", "G90\nG0 X900 Y10\nG0 X0 Y0")])
    options = ("--profile", "grbl-plotter", "--time-scale", "20", "--log", str(log))
    with emulator_on_pty(*options) as path:
        machine = stepdeck.connect("grbl-plotter", port=path)
        try:
            assert list(machine.macros(settings=settings)) == ["Corner", "Park"]
            with pytest.raises(stepdeck.JobRefused, match=r'macro "Park":2: X 900 is outside'):
                machine.run_macro("Park", settings=settings)
            result = machine.run_macro("Corner", settings=settings)
            assert result.operations == 2
            assert machine.position == pytest.approx({"X": 12.0, "Y": 7.0}, abs=0.01)
            with pytest.raises(stepdeck.JobRefused, match=r'macro "Back":2: X -3 is outside'):
                machine.run_macro("Back", code="G91\nG0 X-15")
        finally:
            machine.close()
    deadline = time.monotonic() + LOG_BOUND_S
    while not any(e["event"] == "move" for e in events(log)):
        assert time.monotonic() < deadline, "the emulator logged no move"
        time.sleep(0.05)
    lines = [line.replace(" ", "") for line in received(log)]
    assert "G0X12Y7" in lines
    assert not any("X900" in line or "X-15" in line for line in lines), lines
    moves = [e["pos"] for e in events(log) if e["event"] == "move"]
    assert all(0.0 <= float(p["X"]) <= 300.0 for p in moves)
