"""The entry point: command-line links, and switching machine from the Link page."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt, QTimer
from PySide6.QtWidgets import QApplication, QComboBox, QDialog, QDialogButtonBox, QInputDialog
from pytestqt.qtbot import QtBot

from app.__main__ import (
    Launcher,
    ask_profile,
    build_parser,
    connect_as_asked,
    profile_dialog,
    report_unexpected,
    start,
)
from app.machine import LinkState
from app.profiles import available_profiles, load_profile
from app.settings import StationSettings
from tests.helpers.hostile_corpus import winder_operations


@pytest.fixture
def store(tmp_path: Path) -> QSettings:
    return QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)


def test_switching_machine_rebuilds_station_and_window(qtbot: QtBot, store: QSettings) -> None:
    launcher = Launcher(store, period_ms=None)
    try:
        first = launcher.open(load_profile("xy-stage"))
        first.connect_emulator()
        assert launcher.window is not None
        qtbot.addWidget(launcher.window)
        launcher.window.connection_panel.profileRequested.emit("usb3")  # as the combo does
        assert launcher.station is not first
        assert first.link is None  # the old machine was stopped and its link closed
        assert launcher.station is not None and launcher.station.profile.name == "usb3"
        assert launcher.window.windowTitle() == "StepDeck — Three-axis USB unit"
        station = launcher.station
        qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5000)
        assert StationSettings(store).profile == "usb3"
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_an_unknown_machine_is_refused_and_the_old_one_kept(
    qtbot: QtBot, store: QSettings, monkeypatch: pytest.MonkeyPatch
) -> None:
    launcher = Launcher(store, period_ms=None)
    warnings: list[str] = []
    monkeypatch.setattr(
        "app.__main__.QMessageBox.warning", lambda _parent, _title, text: warnings.append(text)
    )
    try:
        station = launcher.open(load_profile("xy-stage"))
        assert launcher.window is not None
        qtbot.addWidget(launcher.window)
        launcher.switch("no-such-machine")
        assert launcher.station is station
        assert warnings and "no-such-machine" in warnings[0]
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_command_line_port_is_connected_and_remembered(
    store: QSettings, monkeypatch: pytest.MonkeyPatch
) -> None:
    settings = StationSettings(store)
    calls: list[tuple[str, int | None]] = []

    class FakeStation:
        profile = load_profile("xy-stage")

        def connect_serial(self, port: str, baud: int | None = None) -> None:
            calls.append((port, baud))

    args = build_parser().parse_args(["--port", "/dev/ttyUSB7", "--baud", "19200"])
    connect_as_asked(FakeStation(), args, settings)  # type: ignore[arg-type]
    assert calls == [("/dev/ttyUSB7", 19200)]
    machine = settings.machine("xy-stage")
    assert (machine.transport, machine.device, machine.baud) == ("serial", "/dev/ttyUSB7", 19200)


def test_an_unexpected_error_stops_the_machine_and_says_so(
    qtbot: QtBot, store: QSettings, capsys: pytest.CaptureFixture[str]
) -> None:
    launcher = Launcher(store, period_ms=None)
    try:
        station = launcher.open(load_profile("xy-stage"))
        assert launcher.window is not None
        qtbot.addWidget(launcher.window)
        station.connect_emulator()
        qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED)
        assert station.session is not None
        station.session.set_jog([1, 0])
        messages: list[str] = []
        station.model.message.connect(messages.append)
        try:
            raise RuntimeError("boom")
        except RuntimeError as exc:
            report_unexpected(launcher)(RuntimeError, exc, exc.__traceback__)
        assert station.session.jog_vector == (0, 0)
        assert messages[-1] == "Internal error (RuntimeError: boom); machine stopped"
        assert "Traceback" in capsys.readouterr().err
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


# --- stepdeck --list-ports -------------------------------------------------------------


def test_list_ports_prints_every_port_and_exits(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    import app.__main__ as entry
    from protocol.transport.serial_link import PortInfo

    ports = [
        PortInfo("/dev/ttyACM0", "RP2040 plotter", "USB VID:PID=2E8A:000A"),
        PortInfo("/dev/ttyUSB10", "FT232R USB UART", "USB VID:PID=0403:6001"),
    ]
    monkeypatch.setattr(entry, "serial_ports", lambda: ports)
    assert entry.main(["--list-ports"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines == [
        "/dev/ttyACM0   RP2040 plotter  [USB VID:PID=2E8A:000A]",
        "/dev/ttyUSB10  FT232R USB UART  [USB VID:PID=0403:6001]",
    ]
    monkeypatch.setattr(entry, "serial_ports", list)
    assert entry.main(["-l"]) == 1
    assert capsys.readouterr().out == "no serial ports found\n"


def test_list_ports_needs_no_display() -> None:
    """The real command, in a fresh process without a display: it must not start Qt."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "QT_QPA_PLATFORM")}
    done = subprocess.run(
        [sys.executable, "-m", "app", "--list-ports"],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
        cwd=Path(__file__).resolve().parents[2],
    )
    assert done.returncode in (0, 1), done.stderr
    assert done.stdout.strip(), "prints the ports or says there are none"
    assert "Traceback" not in done.stderr


# --- --port without --profile: asked, never guessed ---------------------------------------


def test_a_port_without_a_profile_is_refused_headless_with_the_reason(
    store: QSettings, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The README's --port example once reused the stage profile on a G-code board."""
    settings = StationSettings(store)
    settings.profile = "xy-stage"  # remembered from an earlier run: not a reason to guess
    opened: list[str] = []
    monkeypatch.setattr(Launcher, "open", lambda _self, profile: opened.append(profile.name))
    args = build_parser().parse_args(["--port", "/dev/ttyUSB7"])
    assert start(args, settings) == 2  # the suite runs on the offscreen platform
    assert opened == []
    err = capsys.readouterr().err
    assert "--port /dev/ttyUSB7 needs --profile NAME" in err
    assert "xy-stage" in err and "grbl-plotter" in err  # the names to choose from
    assert "does not guess" in err


def test_the_profile_question_offers_the_remembered_machine_but_waits_for_a_click(
    qtbot: QtBot,
) -> None:
    dialog = profile_dialog("/dev/ttyUSB7", "grbl-plotter")
    qtbot.addWidget(dialog)
    dialog.show()
    combo = dialog.findChild(QComboBox)
    assert combo is not None
    assert [combo.itemText(i) for i in range(combo.count())] == available_profiles()
    assert combo.currentText() == "grbl-plotter"
    assert "/dev/ttyUSB7" in dialog.labelText()
    assert dialog.isVisible() and dialog.result() == 0  # nothing chosen until confirmed
    combo.setCurrentIndex(combo.findText("pcb-drill"))
    buttons = dialog.findChild(QDialogButtonBox)
    assert buttons is not None
    connect = buttons.button(QDialogButtonBox.StandardButton.Ok)
    assert connect.text() == "Connect"
    qtbot.mouseClick(connect, Qt.MouseButton.LeftButton)
    assert dialog.result() == QDialog.DialogCode.Accepted
    assert dialog.textValue() == "pcb-drill"


def test_a_cancelled_question_opens_nothing(
    qtbot: QtBot, store: QSettings, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("app.__main__.HEADLESS_PLATFORMS", frozenset())

    def cancel() -> None:
        dialog = QApplication.activeModalWidget()
        assert isinstance(dialog, QInputDialog)
        dialog.reject()

    QTimer.singleShot(0, cancel)
    err = io.StringIO()
    assert ask_profile("/dev/ttyUSB7", StationSettings(store), err) is None
    assert "no machine chosen for /dev/ttyUSB7" in err.getvalue()


def test_the_machine_chosen_for_a_port_is_the_one_opened_and_remembered(
    qtbot: QtBot, store: QSettings, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("app.__main__.HEADLESS_PLATFORMS", frozenset())
    settings = StationSettings(store)
    settings.profile = "xy-stage"

    def choose() -> None:
        dialog = QApplication.activeModalWidget()
        assert isinstance(dialog, QInputDialog)
        assert dialog.textValue() == "xy-stage"  # preselected: the last used
        dialog.setTextValue("grbl-plotter")
        dialog.accept()

    calls: list[tuple[str, str, int | None]] = []
    monkeypatch.setattr(
        "app.station.Station.connect_serial",
        lambda station, port, baud=None: calls.append((station.profile.name, port, baud)),
    )
    QTimer.singleShot(0, choose)
    launcher = start(build_parser().parse_args(["--port", "/dev/ttyUSB7"]), settings)
    assert isinstance(launcher, Launcher)
    try:
        assert launcher.window is not None
        qtbot.addWidget(launcher.window)
        assert calls == [("grbl-plotter", "/dev/ttyUSB7", None)]
        assert settings.profile == "grbl-plotter"
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_a_baud_no_port_can_take_is_refused_on_the_command_line(
    capsys: pytest.CaptureFixture[str],
) -> None:
    with pytest.raises(SystemExit):
        build_parser().parse_args(["--port", "/dev/ttyUSB7", "--baud", str(2**70)])
    assert "outside 50…4000000" in capsys.readouterr().err


def test_a_profile_loaded_from_a_file_opens_and_leaves_the_remembered_one(
    qtbot: QtBot, store: QSettings, tmp_path: Path
) -> None:
    shipped = load_profile("xy-stage").source
    assert shipped is not None
    custom = tmp_path / "my-stage.toml"
    custom.write_text(
        shipped.read_text(encoding="utf-8").replace('name = "xy-stage"', 'name = "my-stage"'),
        encoding="utf-8",
    )
    settings = StationSettings(store)
    settings.profile = "usb3"
    launcher = Launcher(settings, period_ms=None)
    try:
        station = launcher.open(load_profile(custom))
        assert launcher.window is not None
        qtbot.addWidget(launcher.window)
        assert station.profile.name == "my-stage"
        assert settings.profile == "usb3"  # "my-stage" could not be found by name next time
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_the_plotters_sender_arguments_port_and_file_are_taken() -> None:
    """FIDELITY S1-15: the CoreXY plotter's sender takes the serial port and the file;
    ``stepdeck --port DEVICE --profile corexy-plotter FILE`` names both (the job then waits
    in the jobs dock for Start: a machine never moves without the operator)."""
    args = build_parser().parse_args(
        ["--port", "/dev/ttyACM0", "--profile", "corexy-plotter", "unicorn.gcode"]
    )
    assert args.port == "/dev/ttyACM0" and args.profile == "corexy-plotter"
    assert args.job == Path("unicorn.gcode")


def test_a_job_named_on_the_command_line_is_read_into_the_jobs_dock(
    qtbot: QtBot, store: QSettings, tmp_path: Path
) -> None:
    folder = tmp_path / "cat"
    folder.mkdir()
    (folder / "param.txt").write_text("tvar = 0\npocet_hrebiku = 6\npolomer_matrice = 10\n")
    (folder / "poradi.txt").write_text("3\n0\n3\n1\n")
    args = build_parser().parse_args([str(folder / "param.txt")])  # either file of the pair
    launcher = Launcher(store, period_ms=None)
    try:
        launcher.open(load_profile("string-art"), args.job)
        window = launcher.window
        assert window is not None
        qtbot.addWidget(window)
        runner = window.job_runner  # type: ignore[attr-defined]
        qtbot.waitUntil(lambda: runner.program is not None, timeout=10_000)
        assert runner.program.name == "cat"
        # Drill 6 nails (5 operations each with the 250 ms dwell), wind 3 entries: the
        # firmware's sequence (tests/helpers/hostile_corpus.py counts it).
        assert len(runner.program) == winder_operations(6, 3)
    finally:
        launcher.shutdown()
        if launcher.window is not None:
            launcher.window.close()


def test_check_is_a_subcommand_that_opens_no_window(tmp_path: Path) -> None:
    from app.__main__ import main

    job = tmp_path / "ok.gcode"
    job.write_text("G0 X1 Y1 F1000\nG1 X10 Y10\n")
    assert main(["check", str(job), "--profile", "grbl-plotter"]) == 0
    job.write_text("G0 X1 Y1\nG1 X10 Y10\n")
    assert main(["check", str(job), "--profile", "grbl-plotter"]) == 2
    assert main(["check", str(job)]) == 1  # no profile: a usage error


def test_the_desktop_entry_opens_the_job_types_the_loaders_read() -> None:
    """resources/stepdeck.desktop and stepdeck-mime.xml name only files StepDeck reads."""
    import configparser
    import xml.etree.ElementTree as ET

    from app.jobs.loaders import JOB_TYPES

    resources = Path(__file__).resolve().parents[2] / "resources"
    desktop = configparser.ConfigParser(interpolation=None)
    desktop.optionxform = str  # type: ignore[assignment,method-assign]
    desktop.read(resources / "stepdeck.desktop")
    entry = desktop["Desktop Entry"]
    assert entry["Exec"] == "stepdeck %f"
    assert build_parser().parse_args(["some.gcode"]).job == Path("some.gcode")
    ns = "{http://www.freedesktop.org/standards/shared-mime-info}"
    mime_tag, glob_tag = ns + "mime-type", ns + "glob"
    tree = ET.parse(resources / "stepdeck-mime.xml")
    defined = {m.get("type"): m for m in tree.getroot().iter(mime_tag)}
    listed = [t for t in entry["MimeType"].split(";") if t]
    assert set(defined) <= set(listed)
    extensions = {e for t in JOB_TYPES for e in t.extensions}
    for mime in defined.values():
        for glob in mime.iter(glob_tag):
            pattern = glob.get("pattern", "")
            assert pattern in ("param.txt", "poradi.txt") or pattern[1:] in extensions, pattern


def test_a_string_art_job_opens_on_the_winder_unless_a_machine_is_named(tmp_path: Path) -> None:
    from app.__main__ import profile_for_job

    poradi = tmp_path / "poradi.txt"
    poradi.write_text("2\n0\n3\n")
    plotter = load_profile("grbl-plotter")
    assert profile_for_job(poradi, plotter).name == "string-art"
    winder = load_profile("string-art")
    assert profile_for_job(poradi, winder) is winder
    drawing = tmp_path / "drawing.gcode"
    drawing.write_text("G0 X1 Y1\n")
    assert profile_for_job(drawing, plotter) is plotter  # any machine may take G-code
    assert profile_for_job(tmp_path / "missing.txt", plotter) is plotter  # the dock says why
