"""Settings through one validated layer: whatever the file holds, the station starts.

Each remembered value is read against its type and range; a bad one gives the
default and a warning naming the key and the file, a file Qt cannot read
gives defaults and a warning naming the file, and the window shows them.
"""

from __future__ import annotations

import itertools
import math
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from PySide6.QtCore import QByteArray, QSettings
from pytestqt.qtbot import QtBot

from app.__main__ import Launcher, build_parser, start
from app.machine import LinkState
from app.settings import (
    ALL_SPECS,
    BAUD,
    JOB_OPTIONS,
    PAGE,
    PERIOD_MS,
    PROFILE,
    UNREADABLE_SUFFIX,
    Spec,
    StationSettings,
)

_DIR = Path(tempfile.mkdtemp(prefix="stepdeck-settings-"))
_names = itertools.count()


def _fresh_file() -> Path:
    """A new path per example: Qt caches a settings file per path within the process."""
    return _DIR / f"s{next(_names)}.ini"


def _ini(path: Path, text: bytes) -> QSettings:
    path.write_bytes(text)
    return QSettings(str(path), QSettings.Format.IniFormat)


def _section_and_name(spec: Spec[object]) -> tuple[str, str]:
    section, name = spec.key.split("/")
    return section, name


def _is_valid(spec: Spec[object], value: object) -> bool:
    if value is None or value == spec.default:
        return True
    return spec.convert(value) == value


def _check_read(spec: Spec[object], store: QSettings) -> None:
    station_settings = StationSettings(store)
    value = station_settings.read(spec)
    assert _is_valid(spec, value)
    warnings = station_settings.take_warnings()
    assert len(warnings) <= 1
    for warning in warnings:
        assert spec.key in warning and store.fileName() in warning
        assert value == spec.default
    if isinstance(value, int) and not isinstance(value, bool):
        assert -(2**31) < value < 2**31  # fits every Qt int it reaches


_python_values = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(2**62), max_value=2**62),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=40),
    st.binary(max_size=40),
    st.lists(st.one_of(st.integers(-1000, 1000), st.text(max_size=5)), max_size=4),
    st.binary(max_size=40).map(QByteArray),
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(spec=st.sampled_from(ALL_SPECS), value=_python_values)
def test_any_stored_value_reads_as_a_valid_one_or_the_default_with_a_warning(
    spec: Spec[object], value: object
) -> None:
    path = _fresh_file()
    writer = QSettings(str(path), QSettings.Format.IniFormat)
    writer.setValue(spec.key, value)
    writer.sync()
    del writer
    _check_read(spec, QSettings(str(path), QSettings.Format.IniFormat))


_line_text = st.one_of(
    st.text(
        alphabet=st.characters(blacklist_categories=["Cs"], blacklist_characters="\r\n"),
        max_size=60,
    ),
    st.sampled_from(
        [
            "1180591620717411303424",
            "-5",
            "2147483648",
            "@ByteArray(\\0\\xff)",
            "@Variant(\\0\\0\\0\\x7f\\0\\0\\0\\x12)",
            "@Invalid()",
            "true",
            "nan",
            "1e-3",
            "1, 2",
            "xy-stage",
            "serial",
        ]
    ),
)


@pytest.mark.qt_log_ignore("QVariant::load")  # Qt's own note on a garbled @Variant
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(spec=st.sampled_from(ALL_SPECS), text=_line_text)
def test_any_text_in_the_file_reads_as_a_valid_value_or_the_default_with_a_warning(
    spec: Spec[object], text: str
) -> None:
    section, name = _section_and_name(spec)
    store = _ini(_fresh_file(), f"[{section}]\n{name}={text}\n".encode())
    _check_read(spec, store)


@pytest.mark.parametrize(
    ("spec", "text"),
    [
        (BAUD, "1180591620717411303424"),  # once an OverflowError at every launch
        (PERIOD_MS, "-5"),  # once a 1 ms timer, ~180 frames/s
        (PERIOD_MS, "2147483648"),  # once an empty "Could not connect:" dialog
        (PROFILE, "no-such-machine"),
        (PAGE, "true"),
        (JOB_OPTIONS["excellon_step_inch"], "0.5"),
    ],
)
def test_the_values_that_once_broke_the_start_give_the_default_and_say_so(
    spec: Spec[object], text: str, tmp_path: Path
) -> None:
    section, name = _section_and_name(spec)
    path = tmp_path / "stepdeck.ini"
    station_settings = StationSettings(_ini(path, f"[{section}]\n{name}={text}\n".encode()))
    assert station_settings.read(spec) == spec.default
    (warning,) = station_settings.take_warnings()
    assert spec.key in warning and str(path) in warning and text[:20] in warning
    assert station_settings.take_warnings() == []  # shown once
    assert station_settings.read(spec) == spec.default
    assert station_settings.take_warnings() == []  # and not again for the same key


def test_good_values_come_back_as_written(tmp_path: Path) -> None:
    path = tmp_path / "stepdeck.ini"
    first = StationSettings(QSettings(str(path), QSettings.Format.IniFormat))
    drill = first.machine("pcb-drill")
    first.profile, drill.transport, drill.device = "pcb-drill", "serial", "/dev/ttyUSB0"
    drill.baud, first.period_ms = 9600, 250
    first.set_job_options({"draw": True, "excellon_step_inch": 1e-3}, "pcb-drill")
    first.sync()
    # A new process reads text from the file, not the values cached in this one.
    copy = tmp_path / "copy.ini"
    copy.write_bytes(path.read_bytes())
    again = StationSettings(QSettings(str(copy), QSettings.Format.IniFormat))
    drill = again.machine("pcb-drill")
    assert (again.profile, drill.transport, drill.device) == ("pcb-drill", "serial", "/dev/ttyUSB0")
    assert (drill.baud, again.period_ms) == (9600, 250)
    assert again.job_options("pcb-drill") == {"draw": True, "excellon_step_inch": 1e-3}
    assert again.take_warnings() == []


def test_a_value_out_of_range_is_never_written(tmp_path: Path) -> None:
    store = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    station_settings = StationSettings(store)
    with pytest.raises(ValueError, match="link/baud"):
        station_settings.machine("xy-stage").baud = 2**40
    with pytest.raises(ValueError, match="station/period_ms"):
        station_settings.period_ms = -5
    assert not any(key.endswith("link/baud") for key in store.allKeys())
    assert not store.contains("station/period_ms")


@pytest.mark.parametrize(
    "content",
    [b"\x00\x01\x02garbage[[[\n=\n", b"[main_window\npage=2", b"\xff\xfe\xfa" * 300],
)
def test_a_corrupt_file_gives_defaults_and_a_warning_naming_it(
    content: bytes, tmp_path: Path
) -> None:
    path = tmp_path / "stepdeck.ini"
    station_settings = StationSettings(_ini(path, content))
    assert station_settings.profile == PROFILE.default
    assert station_settings.machine(PROFILE.default).baud is None
    assert station_settings.period_ms is None
    (warning,) = station_settings.take_warnings()
    assert f"Settings file {path} is malformed: defaults are used" in warning
    kept = path.with_name(path.name + UNREADABLE_SUFFIX)
    assert kept.read_bytes() == content  # Qt rewrites the file on the next save
    assert str(kept) in warning


def test_a_settings_file_that_cannot_be_read_is_named(tmp_path: Path) -> None:
    path = tmp_path / "stepdeck.ini"
    path.mkdir()  # not readable as a file, even for root
    station_settings = StationSettings(QSettings(str(path), QSettings.Format.IniFormat))
    assert station_settings.machine(PROFILE.default).transport == "emulator"
    (warning,) = station_settings.take_warnings()
    assert f"Settings file {path} is not readable" in warning


# --- the station starts, and says so ---------------------------------------------------


def _started(tmp_path: Path, content: bytes, qtbot: QtBot) -> Launcher:
    path = tmp_path / "stepdeck.ini"
    launcher = start(build_parser().parse_args([]), StationSettings(_ini(path, content)))
    assert isinstance(launcher, Launcher)
    assert launcher.window is not None
    qtbot.addWidget(launcher.window)
    return launcher


def test_the_station_starts_on_a_corrupt_file_and_shows_the_warning(
    qtbot: QtBot, tmp_path: Path
) -> None:
    launcher = _started(tmp_path, b"\x00\x01\x02garbage[[[\n=\n", qtbot)
    try:
        window = launcher.window
        station = launcher.station
        assert window is not None and station is not None
        box = window.settings_warning
        assert box is not None
        qtbot.waitUntil(box.isVisible)
        assert str(tmp_path / "stepdeck.ini") in box.text()
        assert str(tmp_path / "stepdeck.ini") in window.message_label.text()
        assert station.profile.name == PROFILE.default
        qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5000)
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_the_station_starts_on_out_of_range_values_and_names_each(
    qtbot: QtBot, tmp_path: Path
) -> None:
    content = (
        b"[link]\nbaud=1180591620717411303424\ntransport=serial\ndevice=/dev/ttyUSB3\n"
        b"[station]\nperiod_ms=-5\nprofile=xy-stage\n"
        b"[main_window]\npage=99\n"
    )
    launcher = _started(tmp_path, content, qtbot)
    try:
        window, station = launcher.window, launcher.station
        assert window is not None and station is not None
        box = window.settings_warning
        assert box is not None
        qtbot.waitUntil(box.isVisible)
        for key in ("link/baud", "station/period_ms", "main_window/page"):
            assert key in box.text()
        assert "3 settings could not be used" in window.message_label.text()
        assert station.period_ms == station.profile.period_ms  # not a 1 ms timer
        panel = window.connection_panel
        assert panel.baud_combo.currentData() == station.profile.link.baud
        assert panel.selected_port() == "/dev/ttyUSB3"  # the good values are kept
        # ...but the page shows the link in use: the bare launch opened the emulator.
        qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5000)
        assert panel.transport == "emulator"
        assert window.menu_panel.current == 0
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_a_clean_start_shows_no_warning(qtbot: QtBot, tmp_path: Path) -> None:
    launcher = _started(tmp_path, b"[station]\nprofile=xy-stage\n", qtbot)
    try:
        assert launcher.window is not None
        assert launcher.window.settings_warning is None
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_excellon_steps_match_what_the_dock_offers(qtbot: QtBot) -> None:
    """The stored choices and the dock's are one list: a step saved is a step restored."""
    from tests.helpers.harness import StationHarness
    from widgets.main_window import MainWindow

    harness = StationHarness()
    window = MainWindow(harness.station)
    qtbot.addWidget(window)
    combo = window.jobs_dock.step_combo
    offered = [float(combo.itemData(i)) for i in range(combo.count())]
    spec = JOB_OPTIONS["excellon_step_inch"]
    assert all(math.isclose(spec.convert(step), step) for step in offered)
    assert set(window.jobs_dock.option_values()) == set(JOB_OPTIONS)
    harness.close()
