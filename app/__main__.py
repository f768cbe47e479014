"""``stepdeck`` / ``python -m app``: the station's entry point.

Launched bare it opens on the emulated XY stage (in-process emulator, real
time), so it is usable at once with nothing attached.
"""

from __future__ import annotations

import argparse
import sys
import traceback
from collections.abc import Callable, Sequence
from types import TracebackType
from typing import TextIO

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication, QMainWindow, QMessageBox

from app.discovery import serial_ports
from app.profiles import (
    DEFAULT_PROFILE,
    MachineProfile,
    ProfileError,
    available_profiles,
    load_profile,
)
from app.settings import StationSettings, default_settings
from app.station import Station


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stepdeck", description="Control station for small stepper-motor machines."
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
    link.add_argument("--port", metavar="DEVICE", help="connect over this serial port")
    link.add_argument(
        "--ble",
        nargs="?",
        const="",
        metavar="ADDRESS",
        help="connect over Bluetooth LE (to ADDRESS, or the strongest stage found)",
    )
    parser.add_argument("--baud", type=int, help="serial baud rate (default: the profile's)")
    parser.add_argument(
        "-l",
        "--list-ports",
        action="store_true",
        help="print the serial ports present (device, description, hardware id) and exit",
    )
    return parser


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
    if args.port:
        settings.transport, settings.device = "serial", args.port
        if args.baud:
            settings.baud = args.baud
        station.connect_serial(args.port, args.baud)
    elif args.ble is not None:
        settings.transport = "ble"
        if args.ble:
            settings.device = args.ble
        station.connect_ble(args.ble or None)
    else:
        station.connect_emulator()


class Launcher:
    """Builds the station and its window, and rebuilds both when the operator switches machine."""

    def __init__(self, store: QSettings, period_ms: int | None) -> None:
        self.store = store
        self.settings = StationSettings(store)
        self.period_ms = period_ms
        self.station: Station | None = None
        self.window: QMainWindow | None = None

    def open(self, profile: MachineProfile) -> Station:
        from widgets.main_window import MainWindow

        self.settings.profile = profile.name
        station = Station(profile)
        if self.period_ms:
            station.set_period_ms(self.period_ms)
        window = MainWindow(station, self.store)
        window.profileRequested.connect(self.switch)
        window.show()
        self.station, self.window = station, window
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
        station.model.message.emit(f"Internal error ({kind.__name__}: {error}); machine stopped")

    return hook


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == ["string-art"]:  # a subcommand: no window
        from app.cli.string_art import main as string_art

        return string_art(argv[1:])
    args = build_parser().parse_args(argv)
    if args.list_ports:
        return print_ports(sys.stdout)
    app = QApplication.instance() or QApplication(sys.argv[:1])
    assert isinstance(app, QApplication)
    app.setApplicationName("StepDeck")
    app.setOrganizationName("StepDeck")
    store = default_settings()
    settings = StationSettings(store)
    try:
        profile = load_profile(args.profile or settings.profile)
    except ProfileError as exc:
        if args.profile:
            print(f"stepdeck: {exc}", file=sys.stderr)
            return 2
        profile = load_profile(DEFAULT_PROFILE)  # a stale setting must not stop the launch
    if args.period:
        settings.period_ms = max(20, min(1000, args.period))
    launcher = Launcher(store, settings.period_ms)
    sys.excepthook = report_unexpected(launcher)
    station = launcher.open(profile)
    try:
        connect_as_asked(station, args, settings)
    except Exception as exc:  # whatever the link does, the window stays usable
        QMessageBox.critical(launcher.window, "StepDeck", f"Could not connect: {exc}")
    code = app.exec()
    launcher.shutdown()
    return code


if __name__ == "__main__":
    sys.exit(main())
