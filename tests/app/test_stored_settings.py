"""Stored settings through the station: GRBL's $$ and $N= on the emulated board, the usb3
unit's EEPROM values, each write checked whole before the wire and read back after."""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from app.machines.gcode.grbl_settings import BY_KEY, GRBL_SETTINGS
from app.machines.settings_access import SettingsAccess
from app.machines.stored_settings import Kind
from app.profiles import load_profile
from app.scripting.errors import StepdeckError, WrongMachine
from app.scripting.settings_snapshot import (
    check_machine,
    diff,
    firmware_change,
    load_snapshot,
    save_snapshot,
)
from app.stored_access import settings_access
from tests.helpers.harness import StationHarness

SETTING_LINE = re.compile(rb"\$(\d+)=([^\r\n]*)\n")


@pytest.fixture
def grbl(qapp: object) -> Iterator[StationHarness]:
    h = StationHarness(load_profile("grbl-plotter"))
    h.connect()
    h.run_until(lambda: h.gcode_session.machine_state == "Idle", timeout=5.0)
    yield h
    h.close()


def access_of(h: StationHarness) -> SettingsAccess:
    access = settings_access(h.station.session)
    assert access is not None
    return access


def finish(h: StationHarness, access: SettingsAccess) -> None:
    h.run_until(lambda: access.busy is None, timeout=5.0)
    h.run_until(lambda: access.why_not_now() is None, timeout=5.0)


def writes_sent(h: StationHarness, since: int) -> list[tuple[str, str]]:
    data = b"".join(h.written[since:])
    return [(f"${m[1].decode()}", m[2].decode()) for m in SETTING_LINE.finditer(data)]


def test_a_read_lists_every_setting_grbl_has(grbl: StationHarness) -> None:
    access = access_of(grbl)
    assert access.read() is None
    finish(grbl, access)
    assert access.last is not None and access.last.ok
    assert set(access.values) == set(BY_KEY)
    assert access.values["$110"] == 6000.0  # the profile's 100 mm/s
    assert grbl.gcode_emulator.position() == {"X": 0.0, "Y": 0.0, "Z": 0.0}


def test_a_write_is_read_back_and_the_board_keeps_it(grbl: StationHarness) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    since = len(grbl.written)
    assert access.write({"$110": 4500.25, "$1": 50}) is None
    finish(grbl, access)
    assert access.last is not None and access.last.ok, access.last
    assert access.last.values == {"$110": 4500.25, "$1": 50.0}
    assert writes_sent(grbl, since) == [("$1", "50"), ("$110", "4500.25")]
    assert b"$$\n" in b"".join(grbl.written[since:])
    assert access.values["$110"] == 4500.25


def test_one_bad_value_refuses_the_whole_write_and_sends_nothing(grbl: StationHarness) -> None:
    access = access_of(grbl)
    since = len(grbl.written)
    refusal = access.write({"$110": 3000, "$0": 2, "$13": 1, "$999": 1})
    assert refusal is not None
    assert "$0 (Step pulse time): must be within 3…255 µs" in refusal
    assert "millimetres" in refusal and "$999: no such setting" in refusal
    assert writes_sent(grbl, since) == []


def test_settings_that_conflict_are_refused_with_the_reason(grbl: StationHarness) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    assert "needs homing" in (access.write({"$22": 0, "$20": 1}) or "")
    assert "below $30" in (access.write({"$31": 1000}) or "")
    assert "mechanical travel, 300 mm" in (access.write({"$130": 301}) or "")
    assert "steps/s" in (access.write({"$100": 1000, "$110": 6000}) or "")


def test_nothing_is_written_while_the_machine_moves(grbl: StationHarness) -> None:
    access = access_of(grbl)
    session = grbl.gcode_session
    assert session.send_line("G1 X100 F3000")
    grbl.run_until(lambda: session.machine_state == "Run", timeout=5.0)
    since = len(grbl.written)
    refusal = access.write({"$1": 100})
    assert refusal == "the machine is moving"
    assert access.read() is not None
    assert writes_sent(grbl, since) == [] and b"$$" not in b"".join(grbl.written[since:])


def test_a_write_the_board_refuses_says_so(grbl: StationHarness) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    access.values["$22"] = 1.0  # the station believes homing is on; the board does not
    grbl.gcode_emulator._settings_table[22] = 0.0
    assert access.write({"$20": 1}) is None
    finish(grbl, access)
    assert access.last is not None and not access.last.ok
    assert "error 10" in access.last.refusals[0]


# A value outside a setting's range never reaches the wire; one inside goes as a number
# GRBL reads back as the same value.
VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**9), max_value=10**9),
    st.integers(min_value=-2, max_value=300),
    st.decimals(min_value=-1, max_value=300, places=3).map(float),
    st.decimals(min_value=-1000, max_value=200_000, places=3).map(float),
)


@settings(max_examples=150, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(key=st.sampled_from([s.key for s in GRBL_SETTINGS]), value=VALUES)
def test_only_a_value_within_range_reaches_the_wire(
    grbl: StationHarness, key: str, value: float
) -> None:
    access = access_of(grbl)
    finish(grbl, access)
    spec = BY_KEY[key]
    since = len(grbl.written)
    refusal = access.write({key: value})
    sent = writes_sent(grbl, since)
    if refusal is not None:
        event("refused")
        assert sent == []
        return
    assert spec.check(value) is None
    finish(grbl, access)
    event("sent" if sent else "already held")
    assert access.last is not None and access.last.ok, access.last  # GRBL kept it as sent
    if sent:
        ((sent_key, text),) = sent
        assert sent_key == key and re.fullmatch(r"\d+(\.\d{1,3})?", text), text
        assert spec.low <= float(text) <= spec.high
        assert spec.kind is Kind.DECIMAL or "." not in text


def test_a_snapshot_round_trips_with_a_diff(grbl: StationHarness, tmp_path: Path) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    path = save_snapshot(tmp_path / "grbl.toml", grbl.station.profile, access)
    access.write({"$110": 3000, "$24": 30.5})
    finish(grbl, access)
    snapshot = load_snapshot(path, access)
    changes = diff(snapshot, access)
    assert [(d.key, d.device, d.wanted) for d in changes] == [
        ("$24", 30.5, 25.0),
        ("$110", 3000.0, 6000.0),
    ]
    access.write({d.key: d.wanted for d in changes})
    finish(grbl, access)
    assert access.last is not None and access.last.ok
    assert diff(snapshot, access) == []
    with pytest.raises(WrongMachine):
        check_machine(snapshot, load_profile("corexy-plotter"), other_machine=False)


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("format = 1\nkind = 'usb3-eeprom'\n[machine]\n[settings]\n", "'usb3-eeprom' settings"),
        ("format = 1\nkind = 'grbl'\n[machine]\n[settings]\n'$77' = 1\n", "$77 is no setting"),
        ("format = 1\nkind = 'grbl'\n[machine]\n[settings]\n'$1' = 'x'\n", "is not a number"),
        ("format = 2\n", "not a StepDeck settings snapshot"),
        ("[[[", "not a readable snapshot"),
    ],
)
def test_a_file_that_is_no_snapshot_is_refused(
    grbl: StationHarness, tmp_path: Path, text: str, reason: str
) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(StepdeckError, match=re.escape(reason)):
        load_snapshot(path, access_of(grbl))


def test_a_snapshot_value_out_of_range_is_refused_on_restore(
    grbl: StationHarness, tmp_path: Path
) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    path = save_snapshot(tmp_path / "grbl.toml", grbl.station.profile, access)
    path.write_text(path.read_text().replace('"$0" = 10', '"$0" = 1'), encoding="utf-8")
    changes = diff(load_snapshot(path, access), access)
    since = len(grbl.written)
    assert "must be within 3…255" in (access.write({d.key: d.wanted for d in changes}) or "")
    assert writes_sent(grbl, since) == []


# --- the usb3 unit ------------------------------------------------------------------------


@pytest.fixture
def usb3(qapp: object) -> Iterator[StationHarness]:
    h = StationHarness(load_profile("usb3"))
    h.connect()
    yield h
    h.close()


def test_the_usb3_units_eeprom_values_are_written_and_read_back(usb3: StationHarness) -> None:
    access = access_of(usb3)
    assert access.read() is None
    finish(usb3, access)
    assert access.values["X.thread"] == 4.0 and access.values["Z.step_size"] == 3.0
    since = len(usb3.written)
    assert access.write({"X.thread": 6, "Y.step_size": 5}) is None
    finish(usb3, access)
    assert access.last is not None and access.last.ok, access.last
    sent = b"".join(usb3.written[since:])
    assert b"M353;" in sent and b"T644;" in sent
    assert usb3.usb3_emulator.step_sizes[1] == 5
    refusal = access.write({"X.thread": 7, "Y.step_size": 1.5})
    assert refusal is not None and "none of the choices" not in refusal
    assert "0…6" in refusal and "whole number" in refusal


def test_a_dollar_dollar_typed_in_the_console_updates_the_values(grbl: StationHarness) -> None:
    access = access_of(grbl)
    changed: list[bool] = []
    access.changed.connect(lambda: changed.append(True))
    assert grbl.gcode_session.send_line("$$")
    grbl.run_until(lambda: access.values.get("$132") is not None, timeout=5.0)
    assert set(access.values) == set(BY_KEY) and changed


def test_a_board_reset_before_the_answer_ends_the_write_with_the_reason(
    grbl: StationHarness,
) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    assert access.write({"$1": 30}) is None
    grbl.gcode_session.soft_reset()  # before the board answered
    grbl.run_until(lambda: access.busy is None, timeout=5.0)
    assert access.last is not None and not access.last.ok
    assert "reset" in access.last.refusals[0]
    finish(grbl, access)
    assert access.read() is None  # nothing left over: the next read works
    finish(grbl, access)
    assert access.last is not None and access.last.ok


def test_a_lost_link_ends_a_read_with_the_reason(grbl: StationHarness) -> None:
    access = access_of(grbl)
    assert access.read() is None
    grbl.station.close_link()
    grbl.run_until(lambda: access.busy is None, timeout=5.0)
    assert access.last is not None and "link" in access.last.refusals[0]


# --- the firmware version -----------------------------------------------------------------


def test_a_snapshot_records_the_firmware_the_board_said_it_runs(
    grbl: StationHarness, tmp_path: Path
) -> None:
    access = access_of(grbl)
    since = len(grbl.written)
    assert access.read() is None
    finish(grbl, access)
    assert b"$I\n" in b"".join(grbl.written[since:])  # asked with the read
    assert access.firmware == "1.1h.20190825"
    path = save_snapshot(tmp_path / "grbl.toml", grbl.station.profile, access)
    assert 'firmware = "1.1h.20190825"' in path.read_text(encoding="utf-8")
    snapshot = load_snapshot(path, access)
    assert snapshot.firmware == "1.1h.20190825"
    assert firmware_change(snapshot, access) is None


def test_a_snapshot_of_another_firmware_is_restored_with_both_versions_named(
    grbl: StationHarness, tmp_path: Path
) -> None:
    access = access_of(grbl)
    access.read()
    finish(grbl, access)
    path = save_snapshot(tmp_path / "grbl.toml", grbl.station.profile, access)
    text = path.read_text(encoding="utf-8").replace("1.1h.20190825", "1.1f.20170801")
    path.write_text(text.replace('"$110" = 6000.0', '"$110" = 5000.0'), encoding="utf-8")
    snapshot = load_snapshot(path, access)
    assert firmware_change(snapshot, access) == ("1.1f.20170801", "1.1h.20190825")
    changes = diff(snapshot, access)  # not refused: the operator decides
    assert [d.key for d in changes] == ["$110"]
    assert access.write({d.key: d.wanted for d in changes}) is None
    finish(grbl, access)
    assert access.last is not None and access.last.ok


def test_a_snapshot_without_a_version_and_a_usb3_unit_claim_none(
    usb3: StationHarness, tmp_path: Path
) -> None:
    access = access_of(usb3)
    access.read()
    finish(usb3, access)
    assert access.firmware is None  # its wire has no way to say it
    path = save_snapshot(tmp_path / "usb3.toml", usb3.station.profile, access)
    assert "firmware" not in path.read_text(encoding="utf-8")
    assert load_snapshot(path, access).firmware == ""
