"""GRBL's ``$$`` round-tripped through a TOML snapshot with a diff, over a pty, against real
GRBL 1.1h (grbl-sim) and the emulated grbl-plotter, through the scripting API.

The script reads every setting, saves a snapshot, changes three settings,
asks what the snapshot would change (the diff names exactly those three),
restores it (only those three lines go on the wire) and reads the board
again: it holds the snapshot's values.  A value out of range is refused
before the wire: the board's log never shows it.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

import stepdeck
from tests.helpers import grbl_sim
from tests.helpers.emulator_process import device_path, start_emulator, stop

CHANGES = {"$1": 100.0, "$24": 30.5, "$110": 4000.0}


@dataclass
class Board:
    name: str
    path: str
    log: Path

    def lines_received(self) -> list[str]:
        """Every line the host sent, as the board's wire log has it."""
        found = []
        for raw in self.log.read_text(encoding="utf-8").splitlines():
            try:
                event = json.loads(raw)
            except ValueError:
                continue
            if event.get("event") == "line":
                found.append(str(event.get("text", "")).replace(" ", ""))
        return found


@pytest.fixture(scope="module")
def grbl_sim_exe() -> Path:
    if grbl_sim.compiler() is None:
        pytest.skip("no C compiler and make: grbl-sim cannot be built (.ci/run installs them)")
    source = Path(__file__).resolve().parents[1] / "third_party" / "grbl"
    return grbl_sim.build(source)


@pytest.fixture(params=["grbl-sim", "emulator"])
def board(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[Board]:
    if request.param == "grbl-sim":
        exe = request.getfixturevalue("grbl_sim_exe")
        workdir = tmp_path / "grbl"
        workdir.mkdir()
        process = grbl_sim.start(exe, workdir)
        log = workdir / "wire.log"
    else:
        log = tmp_path / "emulator.log"
        process = start_emulator("--profile", "grbl-plotter", "--log", str(log))
    try:
        yield Board(request.param, device_path(process), log)
    finally:
        stop(process)


def test_dollar_dollar_round_trips_through_a_toml_snapshot_with_a_diff(
    qapp: object, board: Board, tmp_path: Path
) -> None:
    machine = stepdeck.connect("grbl-plotter", port=board.path, timeout=30)
    try:
        settings = machine.settings(timeout=30)
        before = settings.values
        assert len(before) == 34 and before["$0"] == 10.0
        snapshot = settings.save(tmp_path / "board.toml")

        assert settings.write(CHANGES, timeout=30) == CHANGES
        differences = settings.diff(snapshot)
        assert {d.key: (d.device, d.wanted) for d in differences} == {
            key: (value, before[key]) for key, value in CHANGES.items()
        }

        with pytest.raises(stepdeck.SettingRefused, match="must be within 3…255"):
            settings.write({"$0": 2})
        sent_before_restore = len(board.lines_received())
        restored = settings.load(snapshot, timeout=30)
        assert sorted(d.key for d in restored) == sorted(CHANGES)
        assert settings.read(timeout=30) == before
        assert settings.diff(snapshot) == []
        restore_lines = board.lines_received()[sent_before_restore:]
        assert sorted(line for line in restore_lines if "=" in line) == sorted(
            f"{key}={before[key]:g}" for key in CHANGES
        )
        assert not any(line.startswith("$0=") for line in board.lines_received())
    finally:
        machine.close()


def test_the_usb3_units_eeprom_round_trips_through_a_snapshot(qapp: object, tmp_path: Path) -> None:
    """The same for the usb3 unit's step sizes and threads, on the emulator over a pty."""
    process = start_emulator("--profile", "usb3")
    try:
        machine = stepdeck.connect("usb3", port=device_path(process), timeout=30)
        try:
            settings = machine.settings(timeout=30)
            before = settings.values
            snapshot = settings.save(tmp_path / "unit.toml")
            settings.write({"Y.thread": 6, "Z.step_size": 5}, timeout=30)
            assert [(d.key, d.wanted) for d in settings.diff(snapshot)] == [
                ("Z.step_size", before["Z.step_size"]),
                ("Y.thread", before["Y.thread"]),
            ]
            settings.load(snapshot, timeout=30)
            assert settings.read(timeout=30) == before
        finally:
            machine.close()
    finally:
        stop(process)
