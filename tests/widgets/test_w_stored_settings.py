"""The Settings page: GRBL's $$ and the usb3 unit's EEPROM edited with real clicks and keys."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractButton, QApplication, QFileDialog, QMessageBox
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from app.stored_access import specs_for
from tests.helpers.harness import StationHarness
from widgets.panels.stored_settings import STATE, VALUE, StoredSettingsPanel


def build(qtbot: QtBot, profile: str) -> Iterator[tuple[StationHarness, StoredSettingsPanel]]:
    h = StationHarness(load_profile(profile))
    specs = specs_for(h.station.dialect.session_type, h.station.profile)
    assert specs is not None
    panel = StoredSettingsPanel(h.station, specs)
    qtbot.addWidget(panel)
    panel.resize(900, 700)
    panel.show()
    h.connect()
    h.run(0.5)
    try:
        yield h, panel
    finally:
        h.close()


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[tuple[StationHarness, StoredSettingsPanel]]:
    yield from build(qtbot, "grbl-plotter")


def click(qtbot: QtBot, button: QAbstractButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def settle(h: StationHarness, panel: StoredSettingsPanel) -> None:
    access = panel.access
    assert access is not None
    h.run_until(lambda: access.busy is None, timeout=5.0)
    h.run_until(lambda: access.why_not_now() is None, timeout=5.0)


def type_value(qtbot: QtBot, panel: StoredSettingsPanel, key: str, text: str) -> None:
    """Double-click the value cell, type over it, press Enter: as the operator does."""
    row = panel.row_of(key)
    item = panel.table.item(row, VALUE)
    assert item is not None
    panel.table.scrollToItem(item)
    centre = panel.table.visualItemRect(item).center()
    qtbot.mouseClick(panel.table.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    qtbot.mouseDClick(panel.table.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    editor = QApplication.focusWidget()
    assert editor is not None and editor is not panel.table
    qtbot.keyClick(editor, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    # The delegate commits the editor's text through a queued call.
    qtbot.waitUntil(lambda: panel.table.state() is not panel.table.State.EditingState)


def shown(panel: StoredSettingsPanel, key: str, column: int = VALUE) -> str:
    item = panel.table.item(panel.row_of(key), column)
    assert item is not None
    return item.text()


def test_read_fills_every_row_with_what_the_board_holds(
    qtbot: QtBot, grbl: tuple[StationHarness, StoredSettingsPanel]
) -> None:
    h, panel = grbl
    click(qtbot, panel.read_button)
    settle(h, panel)
    assert panel.table.rowCount() == 34
    assert shown(panel, "$110") == "6000" and shown(panel, "$0") == "10"
    tip = panel.table.item(panel.row_of("$0"), VALUE).toolTip()  # type: ignore[union-attr]
    assert "3 µs" in tip and "Allowed: 3…255 µs" in tip


def test_an_edit_is_written_and_read_back(
    qtbot: QtBot, grbl: tuple[StationHarness, StoredSettingsPanel]
) -> None:
    h, panel = grbl
    click(qtbot, panel.read_button)
    settle(h, panel)
    type_value(qtbot, panel, "$110", "4500.5")
    assert panel.edited == {"$110"}
    click(qtbot, panel.apply_button)
    settle(h, panel)
    assert h.gcode_emulator._settings_table[110] == pytest.approx(4500.5)
    assert shown(panel, "$110", STATE) == "✓ read back"
    assert "Written and read back: $110" in panel.summary.text()


def test_a_value_out_of_range_is_framed_red_and_never_sent(
    qtbot: QtBot, grbl: tuple[StationHarness, StoredSettingsPanel]
) -> None:
    h, panel = grbl
    click(qtbot, panel.read_button)
    settle(h, panel)
    type_value(qtbot, panel, "$0", "2")
    assert shown(panel, "$0", STATE) == "✗ not allowed"
    since = len(h.written)
    click(qtbot, panel.apply_button)
    h.run(0.3)
    assert b"$0=" not in b"".join(h.written[since:])
    assert "Not written: $0 (Step pulse time): must be within 3…255 µs" in panel.summary.text()
    assert h.gcode_emulator._settings_table[0] == 10


def test_a_snapshot_is_saved_and_restores_only_what_differs(
    qtbot: QtBot,
    grbl: tuple[StationHarness, StoredSettingsPanel],
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    h, panel = grbl
    path = tmp_path / "board.toml"
    answer = (str(path), "")
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: answer)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: answer)
    click(qtbot, panel.read_button)
    settle(h, panel)
    click(qtbot, panel.save_button)
    assert '"$110" = 6000.0  # X maximum rate [mm/min]' in path.read_text(encoding="utf-8")
    type_value(qtbot, panel, "$111", "3000")
    click(qtbot, panel.apply_button)
    settle(h, panel)
    click(qtbot, panel.load_button)
    box = panel.confirm_box
    assert box is not None
    assert "$111 Y maximum rate: 3000 → 6000 mm/min" in box.text()
    assert "$110" not in box.text()
    since = len(h.written)
    accept = [b for b in box.buttons() if box.buttonRole(b) is QMessageBox.ButtonRole.AcceptRole]
    click(qtbot, accept[0])
    settle(h, panel)
    sent = b"".join(h.written[since:])
    assert b"$111=6000\n" in sent and b"$110=" not in sent
    assert shown(panel, "$111") == "6000"


def test_nothing_is_written_while_a_job_runs(
    qtbot: QtBot, grbl: tuple[StationHarness, StoredSettingsPanel]
) -> None:
    h, panel = grbl
    click(qtbot, panel.read_button)
    settle(h, panel)
    h.station.model.set_jog_lock("a job is running")  # what the job runner sets
    type_value(qtbot, panel, "$1", "100")
    since = len(h.written)
    click(qtbot, panel.apply_button)
    h.run(0.3)
    assert "Not written: a job is running" in panel.summary.text()
    assert b"$1=" not in b"".join(h.written[since:])


def test_the_usb3_units_thread_is_chosen_and_written(qtbot: QtBot) -> None:
    for h, panel in build(qtbot, "usb3"):
        click(qtbot, panel.read_button)
        settle(h, panel)
        combo = panel.combos["X.thread"]
        assert combo.currentText().startswith("M6")
        panel.table.scrollTo(panel.table.model().index(panel.row_of("X.thread"), VALUE))
        combo.setFocus()
        qtbot.keyClick(combo, Qt.Key.Key_Down)  # M6 → M8, as the arrow key chooses
        assert panel.edited == {"X.thread"}
        click(qtbot, panel.apply_button)
        settle(h, panel)
        assert int(h.usb3_emulator.threads[0]) == 5
        assert shown(panel, "X.thread", STATE) == "✓ read back"


def test_a_value_the_board_refuses_is_marked_with_its_error(
    qtbot: QtBot, grbl: tuple[StationHarness, StoredSettingsPanel]
) -> None:
    h, panel = grbl
    click(qtbot, panel.read_button)
    settle(h, panel)
    assert panel.access is not None
    panel.access.values["$22"] = 1.0  # the station believes homing is on; the board does not
    h.gcode_emulator._settings_table[22] = 0.0
    type_value(qtbot, panel, "$20", "1")
    click(qtbot, panel.apply_button)
    settle(h, panel)
    assert shown(panel, "$20", STATE) == "✗ refused"
    assert "error 10" in panel.summary.text()


@pytest.mark.parametrize("profile", ["grbl-plotter", "usb3"])
def test_a_language_switch_edits_nothing(qtbot: QtBot, i18n_cache: Path, profile: str) -> None:
    """The rows' new names and tooltips are no operator's edit: nothing is marked, and the
    values read are shown (an edited row would keep its blank, and Apply would send it)."""
    from app import i18n

    for h, panel in build(qtbot, profile):
        i18n.install("cs", i18n_cache)
        try:
            QApplication.processEvents()
            assert panel.edited == set()
            assert all(shown(panel, spec.key, STATE) == "" for spec in panel.specs)
            click(qtbot, panel.apply_button)
            assert panel.summary.text() == QApplication.translate(
                "StoredSettingsPanel", "Nothing changed"
            )
            click(qtbot, panel.read_button)
            settle(h, panel)
            i18n.install("sk", i18n_cache)
            QApplication.processEvents()
            assert panel.edited == set()
            key = panel.specs[0].key
            combo = panel.combos.get(key)
            assert (combo.currentText() if combo is not None else shown(panel, key)) != ""
        finally:
            i18n.install("en", i18n_cache)


def name_shown_whole(panel: StoredSettingsPanel, row: int) -> bool:
    """The row's name, wrapped at its column's width, fits the row (no "…")."""
    from PySide6.QtCore import QRect

    from widgets.panels.stored_settings import NAME, NAME_PADDING

    table = panel.table
    width = table.columnWidth(NAME) - NAME_PADDING
    text = shown(panel, panel.specs[row].key, NAME)
    needed = table.fontMetrics().boundingRect(
        QRect(0, 0, width, 10_000), Qt.TextFlag.TextWordWrap, text
    )
    return needed.width() <= width and needed.height() <= table.rowHeight(row)


@pytest.mark.parametrize("language", ["en", "cs", "sk"])
def test_every_name_is_shown_whole_in_a_narrow_page(
    qtbot: QtBot, i18n_cache: Path, language: str
) -> None:
    """Beside the jobs dock the page is about 470 px wide: a long name (Czech, Slovak)
    wraps onto more lines of its row instead of ending in "…"."""
    from app import i18n
    from widgets.panels.stored_settings import NAME

    i18n.install(language, i18n_cache)
    panels = build(qtbot, "grbl-plotter")
    try:
        _h, panel = next(panels)
        panel.resize(470, 700)
        rows = range(panel.table.rowCount())
        qtbot.waitUntil(lambda: all(name_shown_whole(panel, row) for row in rows))
        assert panel.table.columnWidth(NAME) >= 90  # the value and state columns left it room
    finally:
        panels.close()
        i18n.install("en", i18n_cache)


def test_a_snapshot_of_another_firmware_warns_and_still_writes(
    qtbot: QtBot,
    grbl: tuple[StationHarness, StoredSettingsPanel],
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    h, panel = grbl
    path = tmp_path / "old-board.toml"
    answer = (str(path), "")
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: answer)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: answer)
    click(qtbot, panel.read_button)
    settle(h, panel)
    click(qtbot, panel.save_button)
    text = path.read_text(encoding="utf-8").replace("1.1h.20190825", "1.1f.20170801")
    path.write_text(text.replace('"$111" = 6000.0', '"$111" = 5000.0'), encoding="utf-8")
    click(qtbot, panel.load_button)
    box = panel.confirm_box
    assert box is not None and box.icon() is QMessageBox.Icon.Warning
    assert "saved on firmware 1.1f.20170801; the device runs 1.1h.20190825" in box.text()
    assert "$111 Y maximum rate: 6000 → 5000 mm/min" in box.text()
    accept = [b for b in box.buttons() if box.buttonRole(b) is QMessageBox.ButtonRole.AcceptRole]
    click(qtbot, accept[0])  # a warning, not a refusal
    settle(h, panel)
    assert h.gcode_emulator._settings_table[111] == 5000.0
