"""Parameter snapshots on the Dynamics page: saved, compared, written only where they differ."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractButton, QFileDialog, QMessageBox
from pytestqt.qtbot import QtBot

from protocol.stage.codec import CommandId, EchoType
from tests.helpers.harness import StationHarness
from tests.widgets.test_w_dynamics_panel import apply, field, written_commands
from widgets.panels.dynamics import DynamicsPanel

X, Y = 0, 1
WRITES = range(CommandId.WRITE_FAST_SPEED, CommandId.WRITE_TRAVEL + 1)


@pytest.fixture
def panel(qtbot: QtBot, harness: StationHarness) -> DynamicsPanel:
    panel = DynamicsPanel(harness.station)
    qtbot.addWidget(panel)
    panel.show()
    harness.connect()
    harness.run(2.5)
    return panel


def click(qtbot: QtBot, button: QAbstractButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def choose_file(monkeypatch: pytest.MonkeyPatch, path: Path) -> None:
    """The file dialog answers ``path`` (the dialog itself is Qt's)."""
    answer = (str(path), "Parameter snapshots (*.toml)")
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: answer)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: answer)


def confirm_button(panel: DynamicsPanel) -> QAbstractButton:
    box = panel.confirm_box
    assert box is not None
    accept = [b for b in box.buttons() if box.buttonRole(b) is QMessageBox.ButtonRole.AcceptRole]
    return accept[0]


def set_acceleration(qtbot: QtBot, panel: DynamicsPanel, harness: StationHarness, v: str) -> None:
    box = field(panel, Y, EchoType.ACCELERATION)
    box.clear()
    qtbot.keyClicks(box, v)
    apply(qtbot, panel)
    harness.run(0.5)


def test_a_snapshot_loads_only_what_differs_and_undo_puts_it_back(
    qtbot: QtBot,
    panel: DynamicsPanel,
    harness: StationHarness,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    snapshot = tmp_path / "stage.toml"
    choose_file(monkeypatch, snapshot)
    click(qtbot, panel.save_button)
    text = snapshot.read_text(encoding="utf-8")
    assert 'profile = "xy-stage"' in text and "acceleration = 20.0" in text
    set_acceleration(qtbot, panel, harness, "35")
    assert harness.emulator.parameter(Y, EchoType.ACCELERATION) == 35_000
    click(qtbot, panel.load_button)
    assert panel.confirm_box is not None
    assert "Y Acceleration: 35 → 20 mm/s²" in panel.confirm_box.text()
    assert "Fast speed" not in panel.confirm_box.text()
    since = len(harness.written)
    click(qtbot, confirm_button(panel))
    harness.run(0.5)
    writes = [c for c in written_commands(harness, since) if c in WRITES]
    assert writes == [CommandId.WRITE_ACCELERATION]
    assert harness.emulator.parameter(Y, EchoType.ACCELERATION) == 20_000
    assert panel.undo_button.isEnabled()
    click(qtbot, panel.undo_button)
    harness.run(0.5)
    assert harness.emulator.parameter(Y, EchoType.ACCELERATION) == 35_000
    assert not panel.undo_button.isEnabled()


def test_another_machines_snapshot_is_written_only_when_confirmed(
    qtbot: QtBot,
    panel: DynamicsPanel,
    harness: StationHarness,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    snapshot = tmp_path / "other.toml"
    choose_file(monkeypatch, snapshot)
    click(qtbot, panel.save_button)
    text = snapshot.read_text(encoding="utf-8").replace('"xy-stage"', '"bench-stage"')
    snapshot.write_text(text.replace("irun = 16", "irun = 12", 1), encoding="utf-8")
    click(qtbot, panel.load_button)
    box = panel.confirm_box
    assert box is not None
    assert "another machine" in box.text() and "X Run current (IRUN): 16 → 12" in box.text()
    since = len(harness.written)
    cancel = box.button(QMessageBox.StandardButton.Cancel)
    click(qtbot, cancel)
    harness.run(0.5)
    assert not [c for c in written_commands(harness, since) if c in WRITES]
    assert panel.summary.text() == "Snapshot not loaded"
    click(qtbot, panel.load_button)
    click(qtbot, confirm_button(panel))
    harness.run(0.5)
    assert harness.emulator.parameter(X, EchoType.IRUN) == 12


def test_a_refused_value_from_a_snapshot_is_shown_with_what_the_device_keeps(
    qtbot: QtBot,
    panel: DynamicsPanel,
    harness: StationHarness,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    snapshot = tmp_path / "bad.toml"
    choose_file(monkeypatch, snapshot)
    click(qtbot, panel.save_button)
    text = snapshot.read_text(encoding="utf-8")
    snapshot.write_text(text.replace("ihold = 8", "ihold = 99", 1), encoding="utf-8")
    click(qtbot, panel.load_button)
    click(qtbot, confirm_button(panel))
    harness.run(0.5)
    assert panel.states[(X, int(EchoType.IHOLD))].text() == "✗ refused, kept 8"
    snapshot.write_text("this is [ not toml", encoding="utf-8")
    click(qtbot, panel.load_button)
    assert panel.confirm_box is None
    assert panel.summary.text().startswith("Not loaded:")
