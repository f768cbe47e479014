"""``stepdeck`` / ``python -m app``: the station's entry point.

Launched bare it opens on the emulated XY stage (in-process emulator, real
time), so it is usable at once with nothing attached.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from PySide6.QtWidgets import QApplication, QMessageBox

from app.profiles import ProfileError, available_profiles, load_profile
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
    parser.add_argument(
        "--emulator", action="store_true", help="connect to the built-in emulator (default)"
    )
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    app = QApplication.instance() or QApplication(sys.argv[:1])
    assert isinstance(app, QApplication)
    app.setApplicationName("StepDeck")
    app.setOrganizationName("StepDeck")
    settings = StationSettings(default_settings())
    try:
        profile = load_profile(args.profile or settings.profile)
    except ProfileError as exc:
        if args.profile:
            print(f"stepdeck: {exc}", file=sys.stderr)
            return 2
        profile = load_profile("xy-stage")  # a stale setting must not stop the launch
    settings.profile = profile.name
    station = Station(profile)
    if args.period:
        settings.period_ms = max(20, min(1000, args.period))
    if settings.period_ms:
        station.set_period_ms(settings.period_ms)
    from widgets.main_window import MainWindow

    window = MainWindow(station, settings.store)
    window.show()
    try:
        station.connect_emulator()
    except Exception as exc:  # a broken emulator must still leave a usable window
        QMessageBox.critical(window, "StepDeck", f"Could not start the emulator: {exc}")
    code = app.exec()
    station.shutdown()
    settings.sync()
    return code


if __name__ == "__main__":
    sys.exit(main())
