"""``stepdeck`` / ``python -m app``: the station's entry point.

Launched bare it opens on the emulated XY stage (in-process emulator, real
time), so it is usable at once with nothing attached.  ``stepdeck JOB`` opens
the window with the job loaded in the jobs dock (a file manager opens job
files this way, resources/stepdeck.desktop); ``stepdeck check …`` and the
other subcommands in :data:`SUBCOMMANDS` run without a window.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import traceback
from collections.abc import Callable, Sequence
from pathlib import Path
from types import TracebackType
from typing import TextIO

from PySide6.QtCore import QCoreApplication, QSettings
from PySide6.QtGui import QGuiApplication, QIcon
from PySide6.QtWidgets import QApplication, QDialog, QInputDialog, QMainWindow, QMessageBox

from app import i18n
from app.discovery import serial_ports
from app.main_thread_gc import MainThreadCollector
from app.profiles import (
    DEFAULT_PROFILE,
    MachineProfile,
    ProfileError,
    available_profiles,
    load_profile,
)
from app.resources import ICON
from app.settings import BAUD_RANGE, StationSettings, default_settings
from app.station import Station

#: ``stepdeck NAME …`` runs module's ``main(argv) -> int`` with the rest of the command line.
SUBCOMMANDS = {
    "check": "app.cli.check",
    "run": "app.cli.run",
    "string-art": "app.cli.string_art",
    "install-desktop": "app.cli.install_desktop",
}


#: Qt platforms with no screen to ask on: there, a missing choice is refused, not guessed.
HEADLESS_PLATFORMS = frozenset({"offscreen", "minimal"})


def _baud(text: str) -> int:
    """A baud rate a serial port can be asked for (a huge one once stopped every launch)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    low, high = BAUD_RANGE
    if not low <= value <= high:
        raise argparse.ArgumentTypeError(f"{value} is outside {low}…{high}")
    return value


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stepdeck",
        description="Control station for small stepper-motor machines.",
        epilog="stepdeck check JOB… --profile P: check job files without a window "
        "(stepdeck check --help).  stepdeck install-desktop: add StepDeck to the desktop's "
        "application menu for this user.",
    )
    parser.add_argument(
        "job",
        nargs="?",
        type=Path,
        metavar="JOB",
        help="a job file to open in the jobs dock (a string-art pair by either file)",
    )
    parser.add_argument(
        "--profile",
        help=f"machine profile ({', '.join(available_profiles())}); default: the last used",
    )
    parser.add_argument(
        "--period", type=int, metavar="MS", help="command frame period, 20…1000 ms (default 100)"
    )
    link = parser.add_mutually_exclusive_group()
    link.add_argument(
        "--emulator", action="store_true", help="connect to the built-in emulator (the default)"
    )
    link.add_argument(
        "--port",
        metavar="DEVICE",
        help="connect over this serial port (name the machine with --profile, or you are asked)",
    )
    link.add_argument(
        "--ble",
        nargs="?",
        const="",
        metavar="ADDRESS",
        help="connect over Bluetooth LE (to ADDRESS, or the strongest stage found)",
    )
    parser.add_argument("--baud", type=_baud, help="serial baud rate (default: the profile's)")
    parser.add_argument(
        "-l",
        "--list-ports",
        action="store_true",
        help="print the serial ports present (device, description, hardware id) and exit",
    )
    return parser


def profile_for_job(job: Path, profile: MachineProfile) -> MachineProfile:
    """The machine to open ``job`` on when none was named: the last one, unless the job is
    string art and it is no winder (a file manager opening ``poradi.txt`` means the winder)."""
    from app.jobs.formats.string_art.program import AXES as WINDER_AXES
    from app.jobs.loaders import STRING_ART, type_for
    from app.jobs.program import JobFileError

    try:
        kind = type_for(job)
    except (JobFileError, KeyError):
        return profile  # the dock says what is wrong with the file
    names = {axis.name for axis in profile.axes}
    if kind is STRING_ART and not set(WINDER_AXES) <= names:
        try:
            return load_profile("string-art")
        except ProfileError:
            return profile
    return profile


def print_ports(out: TextIO) -> int:
    """The serial ports, one per line, as the plotter's old sender script's ``-l`` did."""
    ports = serial_ports()
    if not ports:
        print("no serial ports found", file=out)
        return 1
    width = max(len(p.device) for p in ports)
    for port in ports:
        print(f"{port.device:<{width}}  {port.description}  [{port.hwid}]", file=out)
    return 0


def connect_as_asked(station: Station, args: argparse.Namespace, settings: StationSettings) -> None:
    """Open the link the command line names; bare, the built-in emulator."""
    machine = settings.machine(station.profile.name)
    if args.port:
        machine.transport, machine.device = "serial", args.port
        if args.baud:
            machine.baud = args.baud
        station.connect_serial(args.port, args.baud)
    elif args.ble is not None:
        machine.transport = "ble"
        if args.ble:
            machine.device = args.ble
        station.connect_ble(args.ble or None)
    else:
        station.connect_emulator()


class Launcher:
    """Builds the station and its window, and rebuilds both when the operator switches machine."""

    def __init__(self, store: QSettings | StationSettings, period_ms: int | None) -> None:
        self.settings = store if isinstance(store, StationSettings) else StationSettings(store)
        self.period_ms = period_ms
        self.station: Station | None = None
        self.window: QMainWindow | None = None

    def open(self, profile: MachineProfile, job: Path | None = None) -> Station:
        """The station and its window for ``profile``, with ``job`` being read into the dock."""
        from widgets.main_window import MainWindow

        if profile.name in available_profiles():
            # Only a shipped profile can be found by its name next time; one loaded from a
            # path (``--profile my.toml``) leaves the remembered machine as it was.
            self.settings.profile = profile.name
        station = Station(profile)
        if self.period_ms:
            station.set_period_ms(self.period_ms)
        window = MainWindow(station, self.settings)
        window.profileRequested.connect(self.switch)
        window.show()
        self.station, self.window = station, window
        if job is not None:
            window.jobs_dock.open_path(job, background=True)
        return station

    def switch(self, name: str) -> None:
        try:
            profile = load_profile(name)
        except ProfileError as exc:
            QMessageBox.warning(self.window, "StepDeck", str(exc))
            return
        if self.window is not None:
            self.window.close()  # stops the machine and closes its link
        station = self.open(profile)
        station.connect_emulator()

    def shutdown(self) -> None:
        if self.station is not None:
            self.station.shutdown()
        self.settings.sync()


def report_unexpected(launcher: Launcher) -> Callable[..., None]:
    """An error no code path expected: keep the station running, stop the machine, say so.

    The full traceback still goes to stderr for the bug report; the operator
    gets one line in the status bar instead of a window that silently stopped
    reacting.
    """

    def hook(kind: type[BaseException], error: BaseException, tb: TracebackType | None) -> None:
        traceback.print_exception(kind, error, tb, file=sys.stderr)
        station = launcher.station
        if station is None:
            return
        if station.session is not None:
            station.session.stop_all()
        station.model.message.emit(
            QCoreApplication.translate(
                "Station", "Internal error ({0}: {1}); machine stopped"
            ).format(kind.__name__, error)
        )

    return hook


def profile_dialog(port: str, remembered: str) -> QInputDialog:
    """Which machine is on ``port``: the remembered one offered first, but never assumed.

    The README's own ``--port`` example once reused the last profile and sent
    G-code to an XY stage; so a port named without ``--profile`` is a question.
    """
    names = available_profiles()
    dialog = QInputDialog()
    dialog.setObjectName("profile_choice")
    dialog.setWindowTitle("StepDeck — which machine?")
    dialog.setLabelText(
        f"Which machine is on {port}?\n"
        "Commands in the wrong machine's language can move it unexpectedly."
    )
    dialog.setComboBoxItems(names)
    dialog.setComboBoxEditable(False)
    if remembered in names:
        dialog.setTextValue(remembered)
    dialog.setOkButtonText("Connect")
    return dialog


def ask_profile(port: str, settings: StationSettings, err: TextIO) -> str | None:
    """The profile the operator confirms for ``port``; None (and why, on ``err``) if none."""
    known = ", ".join(available_profiles())
    if QGuiApplication.platformName() in HEADLESS_PLATFORMS:
        print(
            f"stepdeck: --port {port} needs --profile NAME ({known}): "
            "the station does not guess which machine is on a port",
            file=err,
        )
        return None
    dialog = profile_dialog(port, settings.profile)
    if dialog.exec() != QDialog.DialogCode.Accepted:
        print(f"stepdeck: no machine chosen for {port}; nothing was opened", file=err)
        return None
    return dialog.textValue()


def start(
    args: argparse.Namespace, settings: StationSettings, err: TextIO | None = None
) -> Launcher | int:
    """Build the station and its window and open the link asked for; an exit code if refused."""
    err = err or sys.stderr
    name = args.profile
    if args.port and not name:
        name = ask_profile(args.port, settings, err)
        if name is None:
            return 2
    try:
        profile = load_profile(name or settings.profile)
    except ProfileError as exc:
        if name:
            print(f"stepdeck: {exc}", file=err)
            return 2
        profile = load_profile(DEFAULT_PROFILE)  # a stale setting must not stop the launch
    if args.job is not None and not name:
        profile = profile_for_job(args.job, profile)
    if args.period:
        settings.period_ms = max(20, min(1000, args.period))
    launcher = Launcher(settings, settings.period_ms)
    sys.excepthook = report_unexpected(launcher)
    station = launcher.open(profile, args.job)
    try:
        connect_as_asked(station, args, settings)
    except Exception as exc:  # whatever the link does, the window stays usable
        reason = str(exc) or type(exc).__name__  # never an empty "Could not connect:"
        QMessageBox.critical(launcher.window, "StepDeck", f"Could not connect: {reason}")
    return launcher


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] in SUBCOMMANDS:
        command = importlib.import_module(SUBCOMMANDS[argv[0]])
        return int(command.main(argv[1:]))
    args = build_parser().parse_args(argv)
    if args.list_ports:
        return print_ports(sys.stdout)
    app = QApplication.instance() or QApplication(sys.argv[:1])
    assert isinstance(app, QApplication)
    app.setApplicationName("StepDeck")
    app.setOrganizationName("StepDeck")
    app.setWindowIcon(QIcon(str(ICON)))
    app.setDesktopFileName("stepdeck")  # Wayland: the icon and name of stepdeck.desktop
    collector = MainThreadCollector(app)  # cycles freed on the GUI thread, not a transport's
    collector.start()
    settings = StationSettings(default_settings())
    i18n.install(settings.language)  # before any widget is built
    launcher = start(args, settings)
    if isinstance(launcher, int):
        return launcher
    code = app.exec()
    launcher.shutdown()
    return code


if __name__ == "__main__":
    sys.exit(main())
