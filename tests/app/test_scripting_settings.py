"""``machine.settings()``: GRBL's $$ and the usb3 unit's EEPROM from a script (simulated
emulator, as fast as the computer goes)."""

from __future__ import annotations

import asyncio
from collections.abc import Iterator
from pathlib import Path

import pytest

import stepdeck


@pytest.fixture
def plotter(qapp: object) -> Iterator[stepdeck.Machine]:
    machine = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        yield machine
    finally:
        machine.close()


def test_settings_are_read_described_and_written(plotter: stepdeck.Machine) -> None:
    settings = plotter.settings()
    assert settings.kind == "grbl" and len(settings.values) == 34
    assert settings["$110"] == 6000.0
    assert settings.describe("$0").startswith("$0 Step pulse time [µs], 3…255: How long")
    assert settings.write({"$110": 5000, "$1": 100}) == {"$110": 5000.0, "$1": 100.0}
    assert plotter.settings()["$110"] == 5000.0  # a fresh read: the board keeps it


def test_a_refused_write_raises_every_reason_and_changes_nothing(
    plotter: stepdeck.Machine,
) -> None:
    settings = plotter.settings()
    with pytest.raises(stepdeck.SettingRefused) as refused:
        settings.write({"$110": -5, "$0": 2, "$1": 50})
    assert "$110 (X maximum rate): must be within 0.001…100000 mm/min" in str(refused.value)
    assert "$0 (Step pulse time): must be within 3…255 µs" in str(refused.value)
    assert refused.value.written == {}
    assert settings.read()["$1"] == 25.0  # $1 was valid, but the write is refused whole


def test_a_snapshot_diffs_and_restores_what_differs(
    plotter: stepdeck.Machine, tmp_path: Path
) -> None:
    settings = plotter.settings()
    path = settings.save(tmp_path / "plotter.toml")
    settings.write({"$24": 30.5})
    assert [str(d) for d in settings.diff(path)] == [
        "$24 Homing locate feed rate: 30.5 → 25 mm/min"
    ]
    assert [d.key for d in settings.load(path)] == ["$24"]
    assert settings.diff(path) == []


def test_another_machines_snapshot_needs_other_machine(
    plotter: stepdeck.Machine, tmp_path: Path
) -> None:
    settings = plotter.settings()
    path = settings.save(tmp_path / "plotter.toml")
    path.write_text(path.read_text().replace('"grbl-plotter"', '"other-plotter"'))
    with pytest.raises(stepdeck.WrongMachine):
        settings.load(path)
    assert settings.load(path, other_machine=True) == []


def test_the_stage_has_its_parameters_instead(qapp: object) -> None:
    stage = stepdeck.connect("xy-stage", emulator=True, simulated=True)
    try:
        with pytest.raises(stepdeck.Unsupported, match="read_parameters"):
            stage.settings()
    finally:
        stage.close()


def test_the_asyncio_form_reads_and_writes_settings(qapp: object) -> None:
    async def scenario() -> tuple[float, dict[str, float]]:
        machine = await stepdeck.aio.connect("usb3", emulator=True, simulated=True)
        try:
            before = (await machine.read_settings())["X.thread"]
            return before, await machine.write_settings({"X.thread": 6})
        finally:
            machine.close()

    before, written = asyncio.run(scenario())
    assert before == 4.0 and written == {"X.thread": 6.0}


def test_a_snapshot_of_another_firmware_warns_and_still_restores(
    plotter: stepdeck.Machine, tmp_path: Path
) -> None:
    settings = plotter.settings()
    path = settings.save(tmp_path / "plotter.toml")
    text = path.read_text(encoding="utf-8")
    assert 'firmware = "1.1h.20190825"' in text
    path.write_text(text.replace("1.1h.20190825", "1.1f.20170801"), encoding="utf-8")
    settings.write({"$24": 30.5})
    with pytest.warns(UserWarning, match=r"firmware 1\.1f\.20170801, the device runs 1\.1h"):
        assert [d.key for d in settings.load(path)] == ["$24"]
    assert settings["$24"] == 25.0
